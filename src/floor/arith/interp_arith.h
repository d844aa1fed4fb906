// The bit-exact functions of the interpolation paper's interpolation hardware (coefficient units,
// Horner unit, forward differences, the raster-line unit), plain C++ in direct integer arithmetic
// from the format table in interp_formats.h (independent of the SystemC blocks, which build the
// same values from shifters, adders and inverter banks). The golden models check the blocks against
// them; the fast models and the line wrapper's loosely-timed mode call them (the floor,
// docs/layers.md). golden/interp_golden.h adds what only the checks and studies use.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "formats/interp_formats.h"

namespace shading::interp {

// Coefficient codes (coef_fmt, signed Q16.16, as integers) of I(t) = A t^3 + B t^2 + C t + D.
struct cubic_coefs {
    int64_t a = 0, b = 0, c = 0, d = 0;
    bool operator==(const cubic_coefs& o) const { return a == o.a && b == o.b && c == o.c && d == o.d; }
};

// x (a sum_fmt code, Q.8) divided by 3 onto coef_fmt (Q.16).
int64_t golden_div3(int64_t x_q8, div3_mode mode);

// I1..I4 as sample_fmt codes (Q8.8 unsigned). `grouping`: /3 on the whole weighted sum (the
// default) or on the interpolation paper's partial sum (coef_unit_cubic_partial_sum.h).
cubic_coefs golden_cubic_coefs(const std::array<uint64_t, 4>& i, sample_set set, div3_mode mode,
                               div3_grouping grouping = div3_grouping::whole_sum);
// Quadratic through t = 0, 1/2, 1: a, b, c returned in the a, b, c fields (d = 0).
cubic_coefs golden_quad_coefs(const std::array<uint64_t, 3>& i);

// Iterative Horner unit (the interpolation paper, Fig. 4): the RG value after each micro-step, as coef_fmt bus
// bits. Cubic: 6 steps (RG <- B; A t + B; * t; + C; * t; + D). Degree 2 (a, b, c in the a, b, c
// fields): 4 steps (RG <- b; a t + b; * t; + c). Written to rg6[0 ..), returns how many; the last is
// I(t). (golden_horner_steps, golden/interp_golden.h, returns them as a vector.)
std::size_t golden_horner_into(const cubic_coefs& k, uint64_t t_code, bool degree2, uint64_t* rg6);
inline uint64_t golden_horner(const cubic_coefs& k, uint64_t t_code, bool degree2) {
    uint64_t rg[6];
    return rg[golden_horner_into(k, t_code, degree2, rg) - 1];
}

// Forward-difference evaluator for N = 2^m pixels, t = k/N: the set-up values on a bus with
// `frac` fraction bits (fd_fmt.frac in the hardware; fewer to study the error growth), then
// `len` outputs, each P truncated (floor) to coef_fmt bus bits.
std::vector<uint64_t> golden_fd(const cubic_coefs& k, unsigned m, unsigned len, int frac = fd_fmt.frac);
// The same outputs written to out[0 .. len) (coef_fmt is 32 bits wide), no allocation: for the
// loosely-timed line wrapper's per-interval hot path (modules/tlm/line_tlm.h).
void golden_fd_to(const cubic_coefs& k, unsigned m, unsigned len, uint32_t* out, int frac = fd_fmt.frac);

// The raster-line interpolator (modules/interp_line_unit.h): per interval, I1..I4 (sample_fmt
// codes) -> golden_cubic_coefs -> golden_fd over its len pixels (len 0 or > 2^m: a full interval of
// 2^m, as fd_ctrl evaluates it). Returns the pixels of all intervals in order, coef_fmt bus bits.
struct interval_samples {
    std::array<uint64_t, 4> i{};
    unsigned len = 0;
};
std::vector<uint64_t> golden_interp_line(const std::vector<interval_samples>& intervals, unsigned m,
                                         sample_set set, div3_mode mode,
                                         div3_grouping grouping = div3_grouping::whole_sum);

}  // namespace shading::interp
