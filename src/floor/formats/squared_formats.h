// Number formats of the squared-quadratic specular device (ours, not in UA 60553): the patent's
// Fig. 1 datapath evaluates the quadratic law at a small exponent n' = n / 2^k in [1, 2), and a
// squaring stage squares its result k times, so the output approximates
//     cos^n = (cos^n')^(2^k),   n = 2^k * (1 + f),   n' = 1 + f,   f in [0, 1).
// At n' in [1, 2) the quadratic q(c) = c + a (c^2 - c) is the linear interpolation of c^x between
// x = 1 and x = 2 when a = f; its zero lies at c <= 0, so the tail of cos^n is kept. The generator
// of a bends that line slightly (the fit: studies/accuracy/README.md, "The fit"):
//     a = f + f (1 - f) / 2^(k + 2),
// built from the normalised n alone: a leading-zero counter, two barrel shifts, a 9 x 9 multiplier
// and an adder (no ROM, no constant multiplier). One table, read by the golden model, the SystemC
// blocks' template widths, the RTL generator and the README.
#pragma once

#include "formats/fixed_point.h"
#include "formats/specular_formats.h"
#include "formats/ua60553_formats.h"

namespace shading::squared {

// in16 / RG1: n, the same 10-bit unsigned integer as UA 60553's (valid 1..1000).
inline constexpr qfmt n_fmt = ua60553::n_fmt;
inline constexpr unsigned n_min = ua60553::n_min;
inline constexpr unsigned n_max = ua60553::n_max;

// LZC: the leading zeros z of n, 0..10 (10 for n = 0). The number of squarings is k = 9 - z for
// z <= 9 (n >= 1), none for n = 0.
inline constexpr unsigned z_width = 4;
inline constexpr unsigned z_full = n_fmt.width - 1;  // 9: z of n = 1, no squaring

// BSH1: n << z, the normalised exponent 1.f as Q1.9 (bit 9 is 1 for n >= 1); its 9 low wires are
// f, Q0.9. n' = 1 + f exactly: no bit of n is lost.
inline constexpr qfmt mant_fmt{10, false, 9};
inline constexpr qfmt f_fmt{9, false, 9};

// INV_F: ~f, Q0.9 = 1 - f - 2^-9 (no adder for the missing LSB: the bend is fitted as built).
// MUL_E: f x ~f, Q0.18, exact (9 x 9 -> 18).
inline constexpr qfmt e_fmt{18, false, 18};

// BSH2: e << z on 27 wires, read as Q0.29: e * 2^z / 2^11 = e / 2^(k + 2). Its 17 low wires are
// left open (floor) onto the 12-bit bend bus, Q0.12.
inline constexpr unsigned esh_width = e_fmt.width + z_full;     // 27
inline constexpr int esh_frac = e_fmt.frac + z_full + 2;        // 29
inline constexpr qfmt bend_fmt{12, false, 12};

// ADD_A: a = f + bend, Q0.12 (f aligned by three wires). a < 1 for every n (f + f(1-f)/8 < 1).
inline constexpr qfmt a_fmt{12, false, 12};

// The datapath of Fig. 1 at n': MUL7 = cos^2 (Q2.30), INV8, ADD9 = cos^2 - cos (Q2.30 signed),
// exactly as in UA 60553 (specular_formats.h). MUL10 = a x (cos^2 - cos): Q0.12 x Q2.30s = Q2.42s,
// 24 low wires dropped (floor) -> Q2.18 signed, 20 bits (|a (cos^2 - cos)| < 2).
inline constexpr unsigned q_frac = 18;
inline constexpr qfmt mul10_fmt{20, true, static_cast<int>(q_frac)};
inline constexpr unsigned mul10_drop = a_fmt.frac + spec::d_fmt.frac - q_frac;  // 24

// cos aligned onto the q bus: Q1.15 << 3 -> Q1.18 (wiring).
inline constexpr unsigned cos_align = q_frac - spec::cos_fmt.frac;  // 3

// ADD11 = MUL10 + cos, the quadratic at n': Q1.18 unsigned, 19 bits. For cos <= 1.0 the sum lies
// in [0, 1.0] in both modes: a < 1 on a 12-bit grid makes a (cos - cos^2) < 8 cos in units of the
// q bus, and 8 cos is an integer there, so the floor of MUL10 never takes the sum below 0 (the
// golden tests check every n and code). Only cos > 1.0 (a range violation) can leave [0, 1]:
// saturate mode clamps to 1.0, wrap mode keeps the 19 low wires.
inline constexpr qfmt q_fmt{19, false, static_cast<int>(q_frac)};
inline constexpr uint64_t q_one = 1ull << q_frac;
inline constexpr uint64_t q_sat_lo = 0;
inline constexpr uint64_t q_sat_hi = q_one;

// The squaring stage: MX_SQ -> RG_SQ (Q1.18) -> MUL_SQ = RG_SQ^2, Q2.36, 18 low wires dropped
// (floor) and the 19 wires above kept (Q1.18; in saturate mode the value is <= 1 and 1.0^2 = 1.0
// fits; in wrap mode the high wires are dropped). Why 18 fraction bits: the relative error of the
// k-th square grows like 2^k LSB; at 16 bits the worst case above cos^n = 0.56 exceeds 1 % at
// n = 882 (k = 9), at 18 it stays below the law's own 0.39 % (studies/accuracy/README.md, the
// fraction sweep).
inline constexpr qfmt sq_fmt = q_fmt;
inline constexpr unsigned max_squarings = z_full;  // 9, for n = 512..1023

// MX_SQ's select code, the input RG_SQ takes at a falling edge: its own value, the quadratic ADD11
// (the load) or MUL_SQ's square. The squaring controller (modules/squared/sq_count.h) drives it, the
// block model wires MX_SQ's inputs in this order and the RTL generator writes it into the Verilog.
enum sq_select : unsigned { sq_hold = 0, sq_load = 1, sq_square = 2 };

// Strobe 17 crosses into clk's domain through a synchroniser of this many flip-flops (blocks/
// synchroniser.h): the request it raises reaches the controller at the second rising edge after
// the strobe and is taken at the third, so done rises k + 2 + sync_stages rising edges after the
// strobe fell (modules/squared/sq_count.h).
inline constexpr unsigned sync_stages = 2;

// The colour multipliers read the squaring register's 16 high wires (Q1.15, 3 low wires open:
// floor) and are UA 60553's MUL12..14: Q1.15 x 8.0 -> Q9.8.
inline constexpr unsigned sq_to_brdf_drop = q_frac - spec::brdf_fmt.frac;  // 3

}  // namespace shading::squared
