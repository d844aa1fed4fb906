// Bit-accurate golden model of UA 22802 (the ROM prototype), plain C++: the ROM word computed
// directly from the formula, then the shared datapath model (specular_golden.h).
#pragma once

#include <array>
#include <cstdint>

#include "golden/specular_golden.h"

namespace shading {

// ROM word for address n (ua22802_formats.h): floor(a(n) * 2^6 + 1/2) on the Q10.6 bus.
uint64_t golden_a_rom(uint64_t n_bits);

// The whole UA 22802 device.
datapath_nets golden_ua22802(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi,
                             overflow_mode mode);

}  // namespace shading
