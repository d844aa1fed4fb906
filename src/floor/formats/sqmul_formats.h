// Number formats of the square-and-multiply baseline (ours, for comparison): the design any
// engineer would try first for cos^n, one multiplier iterated over the bits of n, left to right:
//     P <- cos;  for each bit of n below its leading one:  P <- P^2;  if the bit is 1: P <- P * cos
// (floor(log2 n) squares and popcount(n) - 1 multiplications, one per clock). P is the
// squared-quadratic device's Q1.18 word, so the two are compared at the same precision and cost
// per multiplier; the colour multipliers are UA 60553's, on P's 16 high wires.
#pragma once

#include "formats/squared_formats.h"

namespace shading::sqmul {

inline constexpr qfmt n_fmt = squared::n_fmt;
inline constexpr qfmt p_fmt = squared::q_fmt;  // Q1.18
inline constexpr unsigned p_frac = squared::q_frac;
inline constexpr uint64_t p_one = squared::q_one;
inline constexpr unsigned cos_align = squared::cos_align;  // Q1.15 onto Q1.18
// n = 1023 = 0b1111111111: 9 squares and 9 multiplications.
inline constexpr unsigned max_steps = 2 * (n_fmt.width - 1);

}  // namespace shading::sqmul
