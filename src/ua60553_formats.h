// UA 60553's ROM-free coefficient generator: a = n * K31 + K32 (patent formula 10),
// MUL6 with the constant at node 31 and ADD15 with the constant at node 32.
#pragma once

#include "fixed_point.h"

namespace shading::ua60553 {

// in16 / RG1: the specular exponent n, 10-bit unsigned integer, valid range 1..1000.
inline constexpr qfmt n_fmt{10, false, 0};
inline constexpr unsigned n_min = 1;
inline constexpr unsigned n_max = 1000;

// A ROM-free generator: two hardwired constants, written as bit strings with the most
// significant fraction bit (weight 1/2) first, both Q0.7.
struct linear_generator {
    const char* name;
    const char* k31_bits;  // node 31, second input of MUL6
    const char* k32_bits;  // node 32, second input of ADD15
};

// UA 60553, claims: bits 1, 2, 5, 7 of node 31 tied to 1, bits 3, 4, 6 to 0 -> 0.1100101b;
// bit 1 of node 32 tied to 1, the rest to 0 -> 0.1b (0.1000000b on the 7-bit bus).
inline constexpr linear_generator patent{"patent", "1100101", "1000000"};

inline constexpr qfmt k_fmt{7, false, 7};      // nodes 31 and 32: Q0.7
inline constexpr qfmt mul6_fmt{17, false, 7};  // n * K31: Q10.7, exact (10 x 7 -> 17)
inline constexpr qfmt a_fmt{18, false, 7};     // ADD15 = a: Q11.7, one bit wider than MUL6

}  // namespace shading::ua60553
