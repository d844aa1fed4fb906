// The block-level pipeline tops the programs share, shading_pipeline<AGen, EVAL> for every device and
// evaluator: compiled once, in shading_pipeline_sim (pipeline_sim_horner.cpp, pipeline_sim_fd.cpp),
// which a program that includes this header links; another AGen still instantiates in the unit that
// names it. CPU s of a unit at -Og, before/after: test_pipeline_fast 23.7/15.7, render_pipeline_rtl
// 18.4/13.1, test_rtl_pipeline 19.5/16.9 (one run each, back to back, on the shared machine).
#pragma once

#include "pipeline/shading_pipeline.h"
#include "sqmul/sqmul_device.h"
#include "squared/squared_device.h"
#include "tuned/a_gen_tuned.h"
#include "ua22802/a_gen_rom.h"
#include "ua60553/a_gen_linear.h"

namespace shading {

extern template class shading_pipeline<a_gen_linear, pipeline::evaluator::horner>;
extern template class shading_pipeline<a_gen_tuned, pipeline::evaluator::horner>;
extern template class shading_pipeline<a_gen_rom, pipeline::evaluator::horner>;
extern template class shading_pipeline<squared_device, pipeline::evaluator::horner>;
extern template class shading_pipeline<sqmul_device, pipeline::evaluator::horner>;
extern template class shading_pipeline<a_gen_linear, pipeline::evaluator::fd>;
extern template class shading_pipeline<a_gen_tuned, pipeline::evaluator::fd>;
extern template class shading_pipeline<a_gen_rom, pipeline::evaluator::fd>;
extern template class shading_pipeline<squared_device, pipeline::evaluator::fd>;
extern template class shading_pipeline<sqmul_device, pipeline::evaluator::fd>;

}  // namespace shading
