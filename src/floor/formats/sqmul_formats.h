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
inline constexpr unsigned n_min = squared::n_min;
inline constexpr unsigned n_max = squared::n_max;
// LZC and BSH1 as the squared-quadratic device's: z leading zeros of n, n << z, its 9 low wires f
// are n's bits below its leading one, walked most significant first; 9 - z squares (none for n = 0).
inline constexpr unsigned z_width = squared::z_width;
inline constexpr unsigned z_full = squared::z_full;
inline constexpr qfmt mant_fmt = squared::mant_fmt;
inline constexpr qfmt f_fmt = squared::f_fmt;
inline constexpr qfmt p_fmt = squared::q_fmt;  // Q1.18
inline constexpr unsigned p_frac = squared::q_frac;
inline constexpr uint64_t p_one = squared::q_one;
inline constexpr unsigned cos_align = squared::cos_align;  // Q1.15 onto Q1.18
// n = 1023 = 0b1111111111: 9 squares and 9 multiplications.
inline constexpr unsigned max_steps = 2 * (n_fmt.width - 1);
// RG_P's 16 high wires (Q1.15, 3 low wires open: floor) to UA 60553's colour multipliers.
inline constexpr unsigned p_to_brdf_drop = squared::sq_to_brdf_drop;
// Strobe 17 crosses into clk's domain through the squared-quadratic device's synchroniser, so done
// rises squares + multiplies + 2 + sync_stages rising edges after the strobe fell (sqmul_count.h).
inline constexpr unsigned sync_stages = squared::sync_stages;

// MX_P's select code, the input RG_P takes at a falling edge of clk: its own word, cos (the load)
// or MUL_P's product; MX_B's, MUL_P's second operand: RG_P (a square) or cos (a multiplication).
// The controller (modules/sqmul/sqmul_count.h) drives them, the block model wires the
// multiplexers' inputs in this order and the RTL generator writes them into the Verilog.
enum p_select : unsigned { p_hold = 0, p_load = 1, p_product = 2 };
inline constexpr unsigned p_inputs = 3;
enum b_select : unsigned { b_p = 0, b_cos = 1 };
inline constexpr unsigned b_inputs = 2;

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
