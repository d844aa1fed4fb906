// The Horner pipelines' runs, for every device (pipeline_sim_run.h).
#include "pipeline_sim_run.h"

namespace shading::pipeline::sim_detail {

template sim_result run_device<evaluator::horner>(const plan&, const frame_constants&, const scene::device_config&,
                                                const plan_config&, const sim_options&);

}  // namespace shading::pipeline::sim_detail
