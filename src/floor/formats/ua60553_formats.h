// UA 60553's ROM-free coefficient generator: a = n * K31 + K32 (patent formula 10),
// MUL6 with the constant at node 31 and ADD15 with the constant at node 32.
#pragma once

#include "formats/fixed_point.h"

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

namespace shading::ua60553 {

// A ROM-free generator beyond formula 10, found by the study's search (studies/accuracy,
// modules/tuned/README.md, "A better ROM-free a(n)"): the same MUL6 and ADD15 on the same buses, but node 32 may
// carry a negative constant (its two's complement on a Q1.7 signed bus, sign-extended by ADD15),
// and n < 2 forces a = 0 (an OR gate over n's bits 9..1 drives the key block on the a bus).
// Why: a(n) = 2(1 - e^(-1/2)) n - 1/2 + O(1/n) = 0.78694 n - 0.5 (modules/tuned/README.md), so the patent's slope is
// right but its +0.5 has the wrong sign; and a(1) = 0 cannot lie on a line through a(2) = 1 with
// slope 0.79.
struct tuned_generator {
    const char* name;
    const char* k31_bits;  // node 31, Q0.7, MSB (weight 1/2) first
    const char* k32_bits;  // |K32|, Q0.7, MSB first
    bool k32_negative;     // node 32 = -|K32|
};

inline constexpr qfmt k32s_fmt{8, true, 7};  // node 32 of the tuned device: Q1.7 signed
// The special case's OR gate reads n's wires tuned_or_lo..9: 1 when n >= 2^tuned_or_lo = 2.
inline constexpr unsigned tuned_or_lo = 1;

// The search's winner (build/bin/generator_search, out/generator_search.csv): the patent's own
// node-31 constant 0.1100101b = 0.7890625 with node 32 = -0.101b = -0.625, and n < 2 -> a = 0.
// Worst relative error above cos^n = 0.56 over n in [1, 1000]: 3.09 % bit-accurate (the ROM
// prototype: 3.16 %; the patent's constants: 56.7 %, at n = 1).
inline constexpr tuned_generator minimax{"minimax", "1100101", "1010000", true};

// The same search ranked n by n against the ROM prototype UA 22802 (aiming to be as accurate as
// the ROM for every n): the candidate whose largest excess over the ROM's error, max over n of
// (error(n) - error_ROM(n)), is smallest. Node 32 = -0.1001001b = -0.5703125 (a(2) = 1.0078 close
// to the exact 1): worse than the ROM only for n = 2..30, by at most 0.26 points; worst case
// 3.09 %, beside minimax's 3.086 %. Same cost as minimax.
inline constexpr tuned_generator rom_matched{"rom_matched", "1100101", "1001001", true};

}  // namespace shading::ua60553
