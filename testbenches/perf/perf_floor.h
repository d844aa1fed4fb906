// perf_models' floor rows (perf_floor.cpp), added to perf_cases.h's list.
#pragma once

namespace shading::perf {

// The harnesses with nothing inside (the floors under the speed figures).
void register_floor_cases();

}  // namespace shading::perf
