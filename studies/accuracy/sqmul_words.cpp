#include "sqmul_words.h"

#include <algorithm>
#include <bitset>
#include <cmath>

#include "formats/specular_formats.h"
#include "formats/squared_formats.h"
#include "arith/sqmul_arith.h"
#include "reference/brdf_reference.h"

namespace shading::study {

namespace {
constexpr auto sat = overflow_mode::saturate;

sqmul_nets nets(const sqmul_design& d, unsigned n, uint64_t cos_code, const std::array<uint64_t, 3>& ksi) {
    return d.walk == sqmul_walk::left_to_right ? golden_sqmul(n, cos_code, ksi, sat, d.p_frac)
                                               : golden_sqmul_r2l(n, cos_code, ksi, sat, d.p_frac);
}
}  // namespace

const std::vector<unsigned>& sqmul_study_fracs() {
    static const std::vector<unsigned> fracs{15, 16, 17, 18, 19, 20};
    return fracs;
}

std::vector<sqmul_design> sqmul_designs() {
    std::vector<sqmul_design> v;
    for (const auto w : {sqmul_walk::left_to_right, sqmul_walk::right_to_left})
        for (unsigned f : sqmul_study_fracs()) {
            const bool l2r = w == sqmul_walk::left_to_right;
            v.push_back({std::string(l2r ? "l2r" : "r2l") + "_p" + std::to_string(f),
                         std::string(l2r ? "left to right, one multiplier" : "right to left, two multipliers") +
                             ", Q1." + std::to_string(f),
                         w, f});
        }
    return v;
}

uint64_t sqmul_design_word(const sqmul_design& d, unsigned n, uint64_t cos_code) {
    return nets(d, n, cos_code, {0, 0, 0}).p;
}

double sqmul_design_value(const sqmul_design& d, unsigned n, uint64_t cos_code) {
    return std::ldexp(static_cast<double>(sqmul_design_word(d, n, cos_code)), -static_cast<int>(d.p_frac));
}

std::array<uint64_t, 3> sqmul_design_out(const sqmul_design& d, unsigned n, uint64_t cos_code,
                                         const std::array<uint64_t, 3>& ksi) {
    return nets(d, n, cos_code, ksi).out;
}

unsigned sqmul_clocks(sqmul_walk w, unsigned n) {
    const sqmul_design d{"", "", w, sqmul::p_frac};
    return squared::sync_stages + 1 + nets(d, n, 0, {0, 0, 0}).steps + 1;
}

unsigned sqmul_clocks_formula(sqmul_walk w, unsigned n) {
    unsigned log2n = 0;
    while ((n >> (log2n + 1)) != 0) ++log2n;
    return w == sqmul_walk::left_to_right ? log2n + static_cast<unsigned>(std::bitset<32>(n).count()) + 3 : log2n + 5;
}

rel_error worst_rel_error(const std::function<double(unsigned n, uint64_t code)>& f, double threshold,
                          unsigned n_max) {
    rel_error r;
    for (unsigned n = 1; n <= n_max; ++n) {
        double worst_n = 0;
        for (uint64_t c = spec::cos_one;; --c) {
            const double p = ref::cos_pow(to_real(c, spec::cos_fmt), n);
            if (p < threshold) break;
            const double e = std::fabs(f(n, c) - p) / p;
            if (e > r.worst) r.worst = e, r.at_n = n, r.at_code = c;
            worst_n = std::max(worst_n, e);
            if (c == 0) break;
        }
        r.n_above_1pct += worst_n > 0.01;
    }
    return r;
}

}  // namespace shading::study
