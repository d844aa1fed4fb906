#include "study_metrics.h"

#include <cmath>

#include "reference/brdf_reference.h"
#include "arith/specular_arith.h"
#include "formats/specular_formats.h"

namespace shading::study {

grid::grid() : codes_(1024), exact_(1024) {
    for (unsigned n = 0; n < 1024; ++n)
        for (uint64_t c = spec::cos_one;; --c) {
            const double p = ref::cos_pow(to_real(c, spec::cos_fmt), n);
            if (p < 0.56) break;
            codes_[n].push_back(c);
            exact_[n].push_back(p);
            if (c == 0) break;
        }
}

double grid::max_rel_err_056(unsigned n, const approx_fn& f, double abort_above) const {
    double worst = 0;
    const auto& cs = codes_[n];
    const auto& ps = exact_[n];
    for (std::size_t i = 0; i < cs.size(); ++i) {
        worst = std::max(worst, std::fabs(f(cs[i]) - ps[i]) / ps[i]);
        if (worst > abort_above) break;
    }
    return worst;
}

double grid::nmse(unsigned n, const approx_fn& f) const {
    double num = 0, den = 0;
    for (uint64_t c = 0; c <= spec::cos_one; ++c) {
        const double p = ref::cos_pow(to_real(c, spec::cos_fmt), n);
        const double e = f(c) - p;
        num += e * e;
        den += p * p;
    }
    return num / den;
}

double datapath_brdf(uint64_t a_bits, int a_frac, uint64_t cos_code) {
    return to_real(golden_datapath(a_bits, a_frac, cos_code, {0, 0, 0}, overflow_mode::saturate).brdf,
                   spec::brdf_fmt);
}

double cosk_k_for(unsigned n) {
    unsigned k = 1;
    while (4u * k * k <= n) k *= 2;
    return k;
}

}  // namespace shading::study
