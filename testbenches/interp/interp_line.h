// The scenario the interpolation benches stream: one raster line of `width` pixels cut into
// intervals of N = 2^m pixels (the last one shorter), exact intensities at every pixel from
// ref::line_intensity, and for every interval the sample codes each unit needs. Plus the
// variants (coefficient unit x division mode) whose coefficients the Horner and forward-difference
// benches evaluate.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "golden/interp_golden.h"
#include "reference/interp_reference.h"

namespace shading::tb {

struct line_interval {
    unsigned first_pixel = 0, len = 0;
    std::array<uint64_t, 4> c1{}, c2{};  // sample codes at t = 0,1/4,1/2,1 and t = 0,1/2,3/4,1
    std::array<uint64_t, 3> q{};         // sample codes at t = 0,1/2,1
};

struct line_scenario {
    unsigned width = 0, m = 0;
    double x0 = -1.2, dx = 0.0;
    std::vector<double> exact;  // exact intensity per pixel
    std::vector<line_interval> intervals;

    unsigned n() const { return 1u << m; }
    double x(double pixel) const { return x0 + pixel * dx; }
};

// The last interval keeps its nominal length N for the samples (its t = 1 point lies past the
// line's end, where the shading function is still defined) and outputs only its remaining pixels.
inline line_scenario make_line(unsigned width, unsigned m) {
    line_scenario s;
    s.width = width;
    s.m = m;
    s.dx = 2.4 / width;
    const unsigned n = 1u << m;
    for (unsigned p = 0; p < width; ++p) s.exact.push_back(ref::line_intensity(s.x(p)));
    auto code_at = [&](unsigned p) { return ref::to_sample_code(ref::line_intensity(s.x(p))); };
    for (unsigned first = 0; first < width; first += n) {
        line_interval iv;
        iv.first_pixel = first;
        iv.len = std::min(n, width - first);
        iv.c1 = {code_at(first), code_at(first + n / 4), code_at(first + n / 2), code_at(first + n)};
        iv.c2 = {code_at(first), code_at(first + n / 2), code_at(first + 3 * n / 4), code_at(first + n)};
        iv.q = {code_at(first), code_at(first + n / 2), code_at(first + n)};
        s.intervals.push_back(iv);
    }
    return s;
}

enum class variant { cubic1_shift_add, cubic1_exact, cubic2_shift_add, cubic2_exact, quad };
inline constexpr std::array<variant, 5> all_variants{variant::cubic1_shift_add, variant::cubic1_exact,
                                                     variant::cubic2_shift_add, variant::cubic2_exact,
                                                     variant::quad};

inline std::string variant_name(variant v) {
    switch (v) {
        case variant::cubic1_shift_add: return "cubic1_shiftadd";
        case variant::cubic1_exact: return "cubic1_exactdiv";
        case variant::cubic2_shift_add: return "cubic2_shiftadd";
        case variant::cubic2_exact: return "cubic2_exactdiv";
        case variant::quad: return "quadratic";
    }
    return "?";
}

inline bool is_quad(variant v) { return v == variant::quad; }

// Coefficients of a variant for an interval, from the golden coefficient models (which the
// coefficient-unit bench proves bit-exact to the SystemC units).
inline interp::cubic_coefs variant_coefs(variant v, const line_interval& iv) {
    using interp::div3_mode;
    using interp::sample_set;
    switch (v) {
        case variant::cubic1_shift_add: return interp::golden_cubic_coefs(iv.c1, sample_set::case1, div3_mode::shift_add);
        case variant::cubic1_exact: return interp::golden_cubic_coefs(iv.c1, sample_set::case1, div3_mode::exact);
        case variant::cubic2_shift_add: return interp::golden_cubic_coefs(iv.c2, sample_set::case2, div3_mode::shift_add);
        case variant::cubic2_exact: return interp::golden_cubic_coefs(iv.c2, sample_set::case2, div3_mode::exact);
        case variant::quad: return interp::golden_quad_coefs(iv.q);
    }
    return {};
}

// A quadratic a t^2 + b t + c as the cubic the forward-difference evaluator takes: A = 0.
inline interp::cubic_coefs as_cubic(const interp::cubic_coefs& q) {
    interp::cubic_coefs k;
    k.b = q.a;
    k.c = q.b;
    k.d = q.c;
    return k;
}

}  // namespace shading::tb
