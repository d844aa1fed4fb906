#include "reference/brdf_reference.h"

#include <algorithm>
#include <cmath>

#include "arith/ua22802_arith.h"

namespace shading::ref {

double cos_pow(double c, double n) { return std::pow(c, n); }

// The formula defines UA 22802's ROM content, so its one definition is in the floor with the ROM's
// format (arith/ua22802_arith.h); a reference may use the floor.
double a_exact(double n) { return ua22802::a_formula(n); }

double a_patent_formula(double n) { return 0.786 * n + 0.5; }

double quadratic(double c, double a) { return c + a * (c * c - c); }

double schlick(double c, double n) { return c / (n - n * c + c); }

double cos_k_gamma(double c, double n, double k) {
    const double kg = k * std::acos(std::clamp(c, -1.0, 1.0));
    if (kg >= M_PI / 2) return 0.0;
    return std::pow(std::cos(kg), n / k);
}

unsigned lyon_gamma(double n) {
    unsigned g = 1;
    while (g <= n / 2.0 && g < (1u << 30)) g *= 2;
    return g;
}

double lyon_power(double cos_nh, double n, unsigned gamma) {
    if (gamma == 0) gamma = lyon_gamma(n);
    const double dd = 2.0 - 2.0 * cos_nh;  // D.D for unit N and H
    const double base = std::max(0.0, 1.0 - (n / gamma) * dd / 2.0);
    return std::pow(base, static_cast<double>(gamma));
}

double real_datapath_out(double a, double c, double ksi) {
    return std::clamp(quadratic(c, a), 0.0, 1.0) * ksi;
}

unsigned squared_k(unsigned n) {
    unsigned k = 0;
    while (n >> (k + 1)) ++k;  // floor(log2 n), 0 for n <= 1
    return k;
}

double squared_f(unsigned n) {
    if (n == 0) return 0.0;
    return static_cast<double>(n) / static_cast<double>(1u << squared_k(n)) - 1.0;
}

double squared_a(unsigned n) {
    const double f = squared_f(n);
    return f + f * (1.0 - f) / static_cast<double>(1u << (squared_k(n) + 2));
}

double squared_law_with(double c, double a, unsigned k) {
    double s = std::clamp(quadratic(c, a), 0.0, 1.0);
    for (unsigned i = 0; i < k; ++i) s *= s;
    return s;
}

double squared_law(double c, unsigned n) { return squared_law_with(c, squared_a(n), squared_k(n)); }

}  // namespace shading::ref
