// The bit-exact function of the squared-quadratic specular device (ours; formats in
// formats/squared_formats.h), plain C++ written from the format table, not from the blocks: the
// golden model the device is checked against, and what its fast model, the TLM wrapper and the
// pipeline's fast model call (the floor, docs/layers.md).
#pragma once

#include <array>
#include <cstdint>

#include "formats/fixed_point.h"

namespace shading {

// The generator of a from n (LZC, BSH1, INV_F, MUL_E, BSH2, ADD_A), every net as raw bus bits.
struct squared_a_nets {
    uint64_t z;      // leading zeros of n, 0..10
    uint64_t mant;   // n << z, Q1.9
    uint64_t f;      // its 9 low wires, Q0.9
    uint64_t e;      // f x ~f, Q0.18
    uint64_t esh;    // e << z, 27 wires (Q0.29)
    uint64_t bend;   // esh >> 17, Q0.12
    uint64_t a;      // (f << 3) + bend, Q0.12
    unsigned k;      // squarings: 9 - z for n >= 1, 0 for n = 0
};
squared_a_nets golden_squared_a(uint64_t n_bits);

// Every net of the device for one cos code: the Fig. 1 datapath at n', the k squares, the colours.
struct squared_nets {
    squared_a_nets gen;
    uint64_t cos2;   // MUL7, Q2.30
    uint64_t diff;   // ADD9, Q2.30 two's complement
    uint64_t prod;   // MUL10, Q2.18 two's complement
    uint64_t q;      // ADD11, Q1.18: the quadratic at n'
    std::array<uint64_t, 10> sq;  // RG_SQ after the load (sq[0] = q) and after each square
    uint64_t brdf;   // RG_SQ after the k-th square, Q1.18
    std::array<uint64_t, 3> out;  // MUL12..14 (R, G, B), Q9.8
};

squared_nets golden_squared(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi,
                            overflow_mode mode);

}  // namespace shading
