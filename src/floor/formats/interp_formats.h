// Number formats of the interpolation paper's interpolation hardware: the coefficient
// units, the iterative Horner unit and the forward-difference evaluator. One table, used by the
// golden models (src/floor/arith/interp_arith.*, src/golden/interp_golden.*), the modules'
// template widths and the README.
// Notation: Qi.f = i integer bits (sign included when signed), f fraction bits.
#pragma once

#include <cstdint>

#include "formats/fixed_point.h"

namespace shading::interp {

//: case 1 samples at t = 0, 1/4, 1/2, 1 (the paper's preferred case); case 2 at
// t = 0, 1/2, 3/4, 1.
enum class sample_set { case1, case2 };
// x/3 as the interpolation paper's shift-and-add x*(1/2 - 1/8 - 1/32 - 1/128) = x * 43/128 (Fig. 2), or exact
// (floor onto Q.16) so the two can be compared.
enum class div3_mode { shift_add, exact };
// Where the /3 of A and C is applied. whole_sum: on the whole weighted sum, A = (-24I1 + 64I2 -
// 48I3 + 8I4)/3 (this model's default). partial_sum: as the interpolation paper prints it, on the part whose
// weights are not multiples of 3 only, the rest added as integers: case 1 A = 8(8I2 + I4)/3 -
// 8(I1 + 2I3), C = (32I2 + I4)/3 - 7I1 - 4I3; case 2 A = 8(2I2 + I4) - 8(I1 + 8I3)/3,
// C = 3(4I2 + I4) - (13I1 + 32I3)/3 (the paper prints these with I3 and I4 swapped: its subscripts
// fit the t = 1 sample named I3; here samples are numbered by increasing t).
enum class div3_grouping { whole_sum, partial_sum };

// I1..I4: exact intensities at the sample points, unsigned Q8.8: the 8-bit colour range 0..255
// with 8 fraction bits, so a shading unit's rounding is not the interpolation's error floor.
inline constexpr qfmt sample_fmt{16, false, 8};

// Output of a coefficient unit's shift-and-add network (before any division by 3): a signed sum
// of shifted samples, Q16.8. Every weight is an integer, so the sum is exact. The largest
// magnitude of any network is 8*(3+6)*Imax = 72*Imax (case 1, 8*(-3I1+8I2-6I3+I4) with I2 = I4 = 0)
// < 72*256 = 18432 < 2^15: 16 integer bits incl. sign never wrap.
inline constexpr qfmt sum_fmt{24, true, 8};
// The partial-sum grouping's networks (the divided part and the integer part) are sums of the same
// kind, each at most 72*Imax (case 1 A's 64I2 + 8I4, case 2 A's 8I1 + 64I3): sum_fmt holds them.

// A, B, C, D (and a, b, c): signed Q16.16, one format for every coefficient so the Horner unit and
// the forward-difference set-up read them all alike.
// Bounds (|I| < 256): case 1 |A| <= 24 Imax, |B| <= 34 Imax, |C| <= 11 Imax; case 2 |A| <= 24 Imax,
// |B| <= 38 Imax, |C| <= 15 Imax; quadratic |a| <= 4 Imax, |b| <= 4 Imax: all < 9728 < 2^15.
// 16 fraction bits hold x/3 by the paper's shift-and-add exactly: a Q.8 operand times
// 1/2 - 1/8 - 1/32 - 1/128 has at most 8 + 7 = 15 fraction bits.
inline constexpr qfmt coef_fmt{32, true, 16};
inline constexpr unsigned div3_shift = coef_fmt.frac - sum_fmt.frac;  // 8: Q.8 -> Q.16

// t: unsigned Q1.8, t = k / 2^m exactly for m <= 8; 1.0 = 256. Codes above 256 (t > 1) are
// extrapolation: reported (shading/input) and evaluated as given, with the wraps below.
inline constexpr qfmt t_fmt{9, false, 8};
inline constexpr uint64_t t_one = 1ull << t_fmt.frac;

// Horner MUL = MX1 * t: Q16.16 signed x Q1.8 unsigned -> Q17.24 exact, 8 low wires dropped
// (floor) and the top wire dropped -> Q16.16. With t <= 1, |MX1 * t| <= |MX1|: never wraps.
inline constexpr unsigned horner_mul_drop = t_fmt.frac;
// Horner RG, MX1, MX2, BK and Sm: all coef_fmt. With in-range inputs every partial sum is
// bounded by |A| + |B| + |C| + |D| <= (24 + 38 + 15 + 1) * 256 < 2^15: Sm never wraps.
inline constexpr qfmt horner_fmt = coef_fmt;

// Control buses (the interpolation paper leaves the controllers open): each as wide as the codes it carries.
constexpr unsigned code_width(unsigned codes) {
    unsigned w = 1;
    while ((1u << w) < codes) ++w;
    return w;
}
inline constexpr unsigned horner_mx1_inputs = 2;  // MX1: A, RG
inline constexpr unsigned horner_mx2_inputs = 5;  // MX2: 0, MUL, B, C, D
inline constexpr unsigned horner_step_codes = 7;  // step: 0 idle, 1..6 the cubic's micro-steps
inline constexpr unsigned fd_mx_inputs = 3;       // forward differences' MX: hold, load, step
// len and pixel of an interval of 2^m pixels: 1..2^m needs m + 1 wires.
constexpr unsigned len_width(unsigned m) { return m + 1; }

// Interval length: N = 2^m pixels, t = k / N for pixel k = 0..N-1. Sample points t = 1/4, 1/2,
// 3/4 fall on pixel centres for m >= 2. The forward-difference evaluator supports m <= 6.
inline constexpr unsigned m_min = 2;
inline constexpr unsigned m_max = 6;

// Forward differences: P, D1, D2, D3 registers, signed Q22.34 on 56 wires. 34 = 16 + 3*m_max
// fraction bits make the set-up (A/N^3, B/N^2, C/N, shifts of Q16.16 codes) exact for every
// m <= m_max, so the recurrence accumulates no error at all. 22 integer bits: |D2| <= 6|A| + 2|B|
// <= 220 * 256 < 2^16, and P stays within |A|+|B|+|C|+|D| < 2^15 for k <= N (t <= 1).
inline constexpr qfmt fd_fmt{56, true, 34};

}  // namespace shading::interp
