// Number formats of the square-and-multiply designs (ours, for comparison): the design any
// engineer would try first for cos^n, one multiplier iterated over the bits of n, left to right:
//     P <- cos;  for each bit of n below its leading one:  P <- P^2;  if the bit is 1: P <- P * cos
// (floor(log2 n) squares and popcount(n) - 1 multiplications, one per clock); and its right-to-left
// twin with two multipliers, both in one clock per bit of n, least significant first:
//     X <- cos, P <- 1.0;  for each bit of n:  if the bit is 1: P <- P * X;  X <- X^2
// P (and X) is the squared-quadratic device's Q1.18 word, so the designs are compared at the same
// precision and cost per multiplier; the colour multipliers are UA 60553's, on P's 16 high wires.
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

// The P word at `frac` fraction bits, Q1.frac, for the word-length study (studies/accuracy,
// sqmul_study) and its synthesis rows; the devices' word is p_word(p_frac). cos (Q1.15) is aligned
// onto it by frac - 15 wires (so frac >= 15), P's 16 high wires feed the colour multipliers.
struct p_word_fmt {
    qfmt fmt;
    unsigned frac;
    uint64_t one;
    unsigned cos_align;
};
inline constexpr unsigned p_frac_min = spec::cos_fmt.frac;  // 15: cos loaded as it is
inline constexpr unsigned p_frac_max = 24;                  // products of two words stay within 64 bits
constexpr p_word_fmt p_word(unsigned frac) {
    return {qfmt{frac + 1, false, static_cast<int>(frac)}, frac, 1ull << frac, frac - spec::cos_fmt.frac};
}
static_assert(p_word(p_frac).fmt.width == p_fmt.width && p_word(p_frac).one == p_one &&
              p_word(p_frac).cos_align == cos_align, "the devices' word is p_word(p_frac)");

}  // namespace shading::sqmul
