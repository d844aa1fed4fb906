// The forward-difference pipelines' runs, for every device (pipeline_sim_run.h).
#include "pipeline_sim_run.h"

namespace shading::pipeline::sim_detail {

template sim_result run_device<evaluator::fd>(const plan&, const frame_constants&, const scene::device_config&,
                                                const plan_config&, const sim_options&);

}  // namespace shading::pipeline::sim_detail

namespace shading {

// The fd tops pipeline_tops.h declares, for every program that links this library.
template class shading_pipeline<a_gen_linear, pipeline::evaluator::fd>;
template class shading_pipeline<a_gen_tuned, pipeline::evaluator::fd>;
template class shading_pipeline<a_gen_rom, pipeline::evaluator::fd>;
template class shading_pipeline<squared_device, pipeline::evaluator::fd>;
template class shading_pipeline<sqmul_device, pipeline::evaluator::fd>;

}  // namespace shading
