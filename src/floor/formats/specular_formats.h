// Number formats of the specular-colour datapath shared by UA 60553 and its prototype UA 22802.
// One table, used by the golden models, the modules' template widths and the
// README. Notation in comments: Qi.f = i integer bits (sign included when signed), f fraction bits.
#pragma once

#include "formats/fixed_point.h"

namespace shading::spec {

// in18 / RG2: cos(gamma), Q1.15 unsigned, so 1.0 = 0x8000 is exact. Codes above 0x8000 are
// out of range (reported; see the README).
inline constexpr qfmt cos_fmt{16, false, 15};
inline constexpr uint64_t cos_one = 1ull << 15;

// MUL7 = cos^2: Q2.30, exact (16 x 16 -> 32). Kept whole: a truncation here would be multiplied
// by a (up to ~800) in MUL10.
inline constexpr qfmt cos2_fmt{32, false, 30};

// INV8: ~(cos << 15) over 32 bits. The 15 low and 16 high wires of the aligned operand are tied
// to 0, so their inverters output 1.
inline constexpr qfmt inv8_fmt{32, false, 30};
inline constexpr unsigned inv8_align = cos2_fmt.frac - cos_fmt.frac;  // 15

// ADD9 = cos^2 + ~cos + 1 (carry node 28) = cos^2 - cos, two's complement Q2.30.
// For cos in [0, 2) the value lies in [-0.25, 2): it never wraps.
inline constexpr qfmt d_fmt{32, true, 30};

// MUL10 = a * (cos^2 - cos): a unsigned times d signed; the product is cut to 15 fraction bits by
// dropping the low wires (floor) and kept as Q12.15 signed (27 bits, |value| < 2048).
inline constexpr qfmt mul10_fmt{27, true, 15};

// ADD11 = MUL10 + cos (carry node 30 = 0): the BRDF q, as the unsigned Q1.15 bus that MUL12..14
// read. wrap mode: the low 16 wires of the two's-complement sum (patent-faithful);
// saturate mode: clamped to [0, 1.0].
inline constexpr qfmt brdf_fmt{16, false, 15};
inline constexpr uint64_t brdf_sat_lo = 0;
inline constexpr uint64_t brdf_sat_hi = cos_one;

// in19/in21/in23, RG3..RG5: k_s * I per channel, 8-bit unsigned integer 0..255.
inline constexpr qfmt ksi_fmt{8, false, 0};

// MUL12..14 -> out25..27: q * k_s*I = Q9.15 (24 bits), 7 low wires dropped (floor) -> Q9.8,
// 17 bits. The integer part is the 8-bit colour; bit 16 can only be set in wrap mode, where
// ADD11's negative sums are read as q >= 1.
inline constexpr qfmt out_fmt{17, false, 8};
inline constexpr unsigned out_drop = brdf_fmt.frac + ksi_fmt.frac - out_fmt.frac;  // 7

// Fraction bits MUL10 drops for an `a` bus of `a_frac` fraction bits.
constexpr unsigned mul10_drop(int a_frac) {
    return static_cast<unsigned>(a_frac + d_fmt.frac - mul10_fmt.frac);
}

}  // namespace shading::spec
