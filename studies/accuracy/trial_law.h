// The trial law: the first form proposed for squaring, set beside ours in the accuracy study as a
// real-valued comparison: the quadratic at n' = n / 2^k in [2, 4), k = floor(log2 n) - 1 (k = 0
// and n' = n for n < 4), clamped to [0, 1] and squared k times, with
//   inflection: a = a_exact(n'), the quadratic-BRDF paper's a at n' (reference/brdf_reference.h);
//   fitted:     a per n minimising the law's NMSE over a surface's cos distribution, searched in the
//               bracket it was proposed with, [max(a_i / 2, 0), 1.5 a_i + 0.01] (a_i the inflection a).
// Unlike our device's n' in [1, 2), n' >= 2 puts a > 1 and the quadratic's zero inside (0, 1).
#pragma once

#include "head_surface.h"

namespace shading::study {

unsigned trial_k(unsigned n);
double trial_n_prime(unsigned n);
double trial_a_inflection(unsigned n);
double trial_law(double c, double a, unsigned n);
// The fit: a 21-point grid over the bracket, then Newton's method on the cost's analytic slopes
// between the best grid point's neighbours, to 1e-9 of the bracket. Deterministic.
double trial_a_fitted(const cos_distribution& d, unsigned n);

}  // namespace shading::study
