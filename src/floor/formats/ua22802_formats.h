// UA 22802 (the prototype named in UA 60553): RG1 addresses a ROM that holds
// a(n) of the quadratic-BRDF paper formula 7; the ROM word drives MUL10 directly.
#pragma once

#include "formats/fixed_point.h"
#include "formats/ua60553_formats.h"

namespace shading::ua22802 {

// ROM address = RG1 = n, the same 10-bit unsigned integer as UA 60553's in16 (valid 1..1000).
inline constexpr qfmt addr_fmt = ua60553::n_fmt;
inline constexpr unsigned rom_words = 1u << addr_fmt.width;  // 1024: every address is programmed

// ROM word = a: Q10.6 unsigned, 16 bits. Integer part: a(1023) = 804.6 < 1024. Fraction bits
// chosen by measurement (out/rom_fraction_sweep.csv, README): with 6 fraction bits the rounding
// of a moves each n's worst relative error above cos^n = 0.56 by at most 5 % of the quadratic
// model's own error (n >= 3; n = 1, 2 are exact in any format), so the ROM device's error is the
// model's. 1024 x 16 bits = 16384 bits = 2 KiB, the "at least 2 KB" UA 60553 gives for the
// prototype's ROM.
inline constexpr qfmt a_fmt{16, false, 6};
inline constexpr unsigned rom_bits = rom_words * a_fmt.width;

// Content of word n: round to nearest (halves up) of a(n) * 2^6, i.e. floor(a * 64 + 1/2).
// Word 0 (n = 0, out of range): a = 0, as for n = 1, so the device outputs q = cos (cos^0 = 1 is
// not representable by the quadratic, whose q(0) = 0 always). Words 1001..1023 (n > 1000, out of
// range): the same formula continued; the range checker still reports such n.

}  // namespace shading::ua22802
