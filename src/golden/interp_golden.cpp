#include "golden/interp_golden.h"

namespace shading::interp {

std::vector<uint64_t> golden_horner_steps(const cubic_coefs& k, uint64_t t_code, bool degree2) {
    uint64_t rg[6];
    const std::size_t n = golden_horner_into(k, t_code, degree2, rg);
    return std::vector<uint64_t>(rg, rg + n);
}

double fd_error_bound(unsigned k, unsigned m, int frac) {
    if (frac >= coef_fmt.frac + 3 * static_cast<int>(m)) return 0.0;
    const double kk = k;
    const double c2 = kk * (kk - 1) / 2, c3 = kk * (kk - 1) * (kk - 2) / 6;
    return (3 * kk + 3 * c2 + 2 * c3) / static_cast<double>(1ull << frac);
}

}  // namespace shading::interp
