// The bit-exact function of the square-and-multiply device (ours; formats/sqmul_formats.h), plain
// C++ written from the format table, not from the blocks: cos^n exact up to the floors of its Q1.18
// products. The golden model the device is checked against, and what its fast model, the TLM
// wrapper and the pipeline's fast model call (the floor, docs/layers.md).
#pragma once

#include <array>
#include <cstdint>

#include "formats/fixed_point.h"

namespace shading {

struct sqmul_nets {
    unsigned squares = 0, multiplies = 0;  // clocks of each kind (n = 0 is read as n = 1: none)
    uint64_t p = 0;                        // P after the last step, Q1.18
    std::array<uint64_t, 3> out{};         // colour multipliers on P's 16 high wires, Q9.8
};

// Saturate mode clamps the loaded cos to 1.0 (a code above 0x8000 is out of range); wrap mode loads
// it as it is and every product keeps its 19 low wires above the floor.
sqmul_nets golden_sqmul(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi, overflow_mode mode);

}  // namespace shading
