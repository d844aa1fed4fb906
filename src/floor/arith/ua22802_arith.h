// The bit-exact function of UA 22802 (the ROM prototype), plain C++: the ROM word computed directly
// from the quadratic-BRDF paper's a(n), then the shared datapath (specular_arith.h). The golden
// model of the device, and what the pipeline's fast model reaches through device_specular (the
// floor, docs/layers.md).
#pragma once

#include <array>
#include <cstdint>

#include "arith/specular_arith.h"

namespace shading {

namespace ua22802 {
// The real a(n) the ROM holds rounded: the quadratic-BRDF paper's formula 7,
// (t^(n-1) - 1) / (t - 1) with t = sqrt((n-1)/n), 0 for n <= 1. It defines the ROM's content, so it
// sits here with the ROM's format; ref::a_exact (reference/brdf_reference.h) is this function.
double a_formula(double n);
}  // namespace ua22802

// ROM word for address n (ua22802_formats.h): floor(a(n) * 2^6 + 1/2) on the Q10.6 bus.
uint64_t golden_a_rom(uint64_t n_bits);

// The whole UA 22802 device.
datapath_nets golden_ua22802(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi,
                             overflow_mode mode);

}  // namespace shading
