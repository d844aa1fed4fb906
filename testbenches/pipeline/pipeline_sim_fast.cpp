// The fast pin-level pipeline's runs, both evaluators (pipeline_sim_run.h; the block-level runs are in
// pipeline_sim_horner.cpp and pipeline_sim_fd.cpp).
#include "pipeline/shading_pipeline_fast.h"
#include "pipeline_sim_run.h"

namespace shading::pipeline::sim_detail {

template <evaluator EVAL>
sim_result run_fast(const plan& p, const frame_constants& k, const scene::device_config& dev, const plan_config& c,
                    const sim_options& o) {
    return run<a_gen_linear, EVAL, true>(p, k, dev, c, ua60553::patent, o);
}

template sim_result run_fast<evaluator::horner>(const plan&, const frame_constants&, const scene::device_config&,
                                                const plan_config&, const sim_options&);
template sim_result run_fast<evaluator::fd>(const plan&, const frame_constants&, const scene::device_config&,
                                            const plan_config&, const sim_options&);

}  // namespace shading::pipeline::sim_detail
