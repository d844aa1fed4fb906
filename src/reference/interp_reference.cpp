#include "reference/interp_reference.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shading::ref {

real_poly cubic_coefs(const std::array<double, 4>& in, interp::sample_set set) {
    const double i1 = in[0], i2 = in[1], i3 = in[2], i4 = in[3];
    real_poly p;
    if (set == interp::sample_set::case1) {
        p.a = -8.0 * (3 * i1 - 8 * i2 + 6 * i3 - i4) / 3.0;
        p.b = 2.0 * (7 * i1 - 16 * i2 + 10 * i3 - i4);
        p.c = -(21 * i1 - 32 * i2 + 12 * i3 - i4) / 3.0;
    } else {
        p.a = -8.0 * (i1 - 6 * i2 + 8 * i3 - 3 * i4) / 3.0;
        p.b = 2.0 * (3 * i1 - 14 * i2 + 16 * i3 - 5 * i4);
        p.c = -(13 * i1 - 36 * i2 + 32 * i3 - 9 * i4) / 3.0;
    }
    p.d = i1;
    return p;
}

real_poly quad_coefs(const std::array<double, 3>& in) {
    real_poly p;
    p.b = 2 * in[0] - 4 * in[1] + 2 * in[2];
    p.c = -3 * in[0] + 4 * in[1] - in[2];
    p.d = in[0];
    return p;
}

double eval(const real_poly& p, double t) { return ((p.a * t + p.b) * t + p.c) * t + p.d; }

std::array<double, 4> sample_ts(interp::sample_set set) {
    if (set == interp::sample_set::case1) return {0.0, 0.25, 0.5, 1.0};
    return {0.0, 0.5, 0.75, 1.0};
}

std::vector<double> fit_polynomial(const std::vector<double>& ts, const std::vector<double>& vals) {
    const std::size_t n = ts.size();
    // Cubic and quadratic fits only (a small bound also keeps n + 1 below any overflow).
    if (vals.size() != n || n == 0 || n > 8) throw std::invalid_argument("fit_polynomial: 1..8 points");
    std::vector<std::vector<double>> m(n, std::vector<double>(n + 1));
    for (std::size_t r = 0; r < n; ++r) {
        double p = 1.0;
        for (std::size_t c = 0; c < n; ++c, p *= ts[r]) m[r][c] = p;
        m[r][n] = vals[r];
    }
    for (std::size_t col = 0; col < n; ++col) {
        std::size_t piv = col;
        for (std::size_t r = col + 1; r < n; ++r)
            if (std::abs(m[r][col]) > std::abs(m[piv][col])) piv = r;
        std::swap(m[col], m[piv]);
        for (std::size_t r = 0; r < n; ++r) {
            if (r == col) continue;
            const double f = m[r][col] / m[col][col];
            for (std::size_t c = col; c <= n; ++c) m[r][c] -= f * m[col][c];
        }
    }
    std::vector<double> x(n);
    for (std::size_t r = 0; r < n; ++r) x[r] = m[r][n] / m[r][r];
    return x;
}

double line_intensity(double x) {
    const double h_dx = 0.6 * std::exp(-x * x / 0.18) * (-2.0 * x / 0.18);  // dh/dx
    const double h_dy = -0.15;                                              // the line's tilt
    double n[3] = {-h_dx, -h_dy, 1.0};
    const double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& v : n) v /= nn;
    const double l[3] = {-0.40, 0.35, 0.8470537};   // unit vector to the light
    const double h[3] = {-0.2081159, 0.1821014, 0.9610030};  // (L + V)/|L + V|, V = +z
    const double hn = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    const double nl = std::max(0.0, n[0] * l[0] + n[1] * l[1] + n[2] * l[2]);
    const double nh = std::max(0.0, (n[0] * h[0] + n[1] * h[1] + n[2] * h[2]) / hn);
    const double i = 255.0 * (0.06 + 0.62 * nl + 0.30 * std::pow(nh, 24.0));
    return std::clamp(i, 0.0, 255.0);
}

uint64_t to_sample_code(double intensity) {
    const double code = std::round(intensity * static_cast<double>(1u << interp::sample_fmt.frac));
    return static_cast<uint64_t>(std::clamp(code, 0.0, static_cast<double>(interp::sample_fmt.mask())));
}

}  // namespace shading::ref
