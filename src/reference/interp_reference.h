// Real-valued references for the interpolation paper's interpolation: the coefficient formulas in
// real numbers, a general polynomial fit through sample points (to re-derive those formulas),
// and the "exact intensity" along a raster line that the benches interpolate.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "formats/interp_formats.h"

namespace shading::ref {

struct real_poly {
    double a = 0, b = 0, c = 0, d = 0;  // a t^3 + b t^2 + c t + d (a = 0 for a quadratic)
};

//'s formulas, real arithmetic (division by 3 exact).
real_poly cubic_coefs(const std::array<double, 4>& i, interp::sample_set set);
// Quadratic through t = 0, 1/2, 1: a t^2 + b t + c returned as b t^2 + c t + d (a = 0).
real_poly quad_coefs(const std::array<double, 3>& i);
double eval(const real_poly& p, double t);

// Sample positions of a set, t values.
std::array<double, 4> sample_ts(interp::sample_set set);

// The polynomial of degree ts.size()-1 through (ts[i], vals[i]), by Gaussian elimination on the
// Vandermonde system; coefficients lowest power first. Independent of the formulas above.
std::vector<double> fit_polynomial(const std::vector<double>& ts, const std::vector<double>& vals);

// Exact intensity (0..255) along one raster line of a lit face-like surface: a height field
// h(x) = 0.6 exp(-x^2 / 0.18) (a cheek) seen from +z, Lambert diffuse plus a Blinn specular
// highlight (n = 24), light from upper left. Smooth for every x, so any interval can be sampled,
// also past the end of the line (the last, shorter interval; see the README).
double line_intensity(double x);

// Intensity -> sample_fmt code (Q8.8, round to nearest, clamped to the bus).
uint64_t to_sample_code(double intensity);

}  // namespace shading::ref
