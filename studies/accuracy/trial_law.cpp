#include "trial_law.h"

#include <algorithm>
#include <cmath>

#include "reference/brdf_reference.h"

namespace shading::study {

unsigned trial_k(unsigned n) {
    unsigned log2n = 0;
    while (n >> (log2n + 1)) ++log2n;
    return log2n >= 1 ? log2n - 1 : 0;
}

double trial_n_prime(unsigned n) { return std::ldexp(static_cast<double>(n), -static_cast<int>(trial_k(n))); }

double trial_a_inflection(unsigned n) { return ref::a_exact(trial_n_prime(n)); }

double trial_law(double c, double a, unsigned n) { return ref::squared_law_with(c, a, trial_k(n)); }

double trial_a_fitted(const cos_distribution& d, unsigned n) {
    const std::vector<double> exact = distribution_exact(d, n);
    std::vector<double> cs(d.codes.size()), ds(d.codes.size());
    for (std::size_t i = 0; i < cs.size(); ++i) {
        cs[i] = std::ldexp(static_cast<double>(d.codes[i]), -15);
        ds[i] = cs[i] * cs[i] - cs[i];  // q = c + a d, d <= 0
    }
    const unsigned k = trial_k(n);
    const double m = std::ldexp(1.0, static_cast<int>(k));  // L = clamp(q, 0, 1)^m
    auto cost = [&](double a) {  // the NMSE's numerator (its denominator does not depend on a)
        double num = 0.0;
        for (std::size_t i = 0; i < cs.size(); ++i) {
            const double e = ref::squared_law_with(cs[i], a, k) - exact[i];
            num += d.weight[i] * e * e;
        }
        return num;
    };
    // First and second derivative of the cost in a: L' = m q^(m-1) d, L'' = m (m-1) q^(m-2) d^2
    // where 0 < q < 1 (0 where the clamp holds q).
    auto slopes = [&](double a, double& d1, double& d2) {
        d1 = d2 = 0.0;
        for (std::size_t i = 0; i < cs.size(); ++i) {
            const double q = cs[i] + a * ds[i];
            if (!(q > 0.0 && q < 1.0)) continue;
            double qm2 = 1.0, t = q;  // q^(m-2) = q^2 q^4 ... q^(2^(k-1)) (k >= 1)
            for (unsigned j = 1; j < k; ++j) {
                t *= t;
                qm2 *= t;
            }
            const double qm1 = k == 0 ? 1.0 : qm2 * q;  // q^(m-1)
            const double L = qm1 * q, l1 = m * qm1 * ds[i], l2 = m * (m - 1.0) * qm2 * ds[i] * ds[i];
            const double e = L - exact[i];
            d1 += 2.0 * d.weight[i] * e * l1;
            d2 += 2.0 * d.weight[i] * (l1 * l1 + e * l2);
        }
    };
    const double ai = trial_a_inflection(n), lo = std::max(0.5 * ai, 0.0), hi = 1.5 * ai + 0.01;
    constexpr int points = 21;
    int best = 0;
    double best_cost = cost(lo);
    for (int i = 1; i < points; ++i) {
        const double c = cost(lo + (hi - lo) * i / (points - 1));
        if (c < best_cost) best_cost = c, best = i;
    }
    // Safeguarded Newton between the best grid point's neighbours: the slope's sign narrows the
    // bracket; a step that leaves it (or a point where the cost is not convex) bisects it instead.
    double x0 = lo + (hi - lo) * std::max(best - 1, 0) / (points - 1);
    double x1 = lo + (hi - lo) * std::min(best + 1, points - 1) / (points - 1);
    double a = lo + (hi - lo) * best / (points - 1);
    for (int it = 0; it < 60 && x1 - x0 > 1e-9 * (hi - lo); ++it) {
        double d1, d2;
        slopes(a, d1, d2);
        (d1 > 0 ? x1 : x0) = a;
        double next = d2 > 0 ? a - d1 / d2 : 0.5 * (x0 + x1);
        if (!(next > x0 && next < x1)) next = 0.5 * (x0 + x1);
        if (std::fabs(next - a) < 1e-12 * (hi - lo)) break;
        a = next;
    }
    return cost(a) <= best_cost ? a : lo + (hi - lo) * best / (points - 1);
}

}  // namespace shading::study
