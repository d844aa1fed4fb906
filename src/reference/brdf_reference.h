// Real-valued references for the specular term: the exact BRDF, the quadratic
// model with the exact a(n) (the quadratic-BRDF paper formula 7), the patent's linear a (UA 60553 formula 10),
// and the prior approximations of the quadratic-BRDF paper (Schlick, (cos k*gamma)^(n/k), Lyon).
#pragma once

namespace shading::ref {

double cos_pow(double c, double n);                 // cos^n gamma
double a_exact(double n);                           // (t^(n-1) - 1) / (t - 1), t = sqrt((n-1)/n)
double a_patent_formula(double n);                  // 0.786 n + 0.5 as printed in the patent
double quadratic(double c, double a);               // q(c) = c + a (c^2 - c)
double schlick(double c, double n);                 // c / (n - n c + c)
double cos_k_gamma(double c, double n, double k);   // cos(k * acos c)^(n/k), 0 beyond k*gamma = pi/2
// Lyon (Apple Technical Report #43, 1993) as the quadratic-BRDF paper restates it: cos^n from the chord
// D = N - H, N.H = 1 - D.D/2 (for unit vectors D.D = 2 - 2 cos), and the power as
// max(0, 1 - (n/gamma) D.D/2)^gamma, gamma = 2^k reached by k squarings (the report's f_k(x) =
// (1 - x/2^k)^(2^k) at x = (n/2) D.D). gamma = 0: lyon_gamma(n). Equals cos^n when gamma = n.
double lyon_power(double cos_nh, double n, unsigned gamma);
// gamma chosen from n: the largest power of two not above n (1 for n < 2), so n/gamma lies in [1, 2),
// the lobe ends at cos = 1 - gamma/n >= 0 and floor(log2 n) squarings, as the squared-quadratic law's k.
unsigned lyon_gamma(double n);

// The UA 60553 datapath in real numbers for the same input codes: BRDF clamped to [0, 1]
// (saturate mode) times k_s*I, no rounding anywhere.
double real_datapath_out(double a, double c, double ksi);

// The squared-quadratic law (ours; formats/squared_formats.h) in real numbers: n = 2^k (1 + f) with
// f in [0, 1), a = f + f (1 - f) / 2^(k + 2), the quadratic at n' = 1 + f clamped to [0, 1] and
// squared k times. n < 1 is read as n = 1 (k = 0, a = 0), as the device does.
unsigned squared_k(unsigned n);
double squared_f(unsigned n);
double squared_a(unsigned n);
double squared_law(double c, unsigned n);
// The same law with any a and k (the fit's studies): clamp(q(c, a), 0, 1)^(2^k).
double squared_law_with(double c, double a, unsigned k);

}  // namespace shading::ref
