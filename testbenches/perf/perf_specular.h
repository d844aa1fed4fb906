// perf_models' rows for the specular devices (perf_specular.cpp), added to perf_cases.h's list.
#pragma once

#include <string>

namespace shading::perf {

// The specular devices (block level, fast, the Verilator twin).
void register_specular_cases();
// The UA 60553 TLM wrapper in one timing mode (loosely timed, or pin-accurate when `pin`).
void add_specular_tlm(const std::string& name, bool pin);

}  // namespace shading::perf
