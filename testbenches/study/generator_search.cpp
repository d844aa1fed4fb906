#include "generator_search.h"

#include <algorithm>
#include <bitset>
#include <cstdlib>

#include "../src/ua60553_formats.h"

namespace shading::study {

unsigned candidate::nnz() const {
    return static_cast<unsigned>(std::bitset<64>(k31).count() +
                                 std::bitset<64>(static_cast<uint64_t>(std::llabs(k32))).count());
}

static std::string bits7(uint64_t v) {
    std::string s;
    for (int b = 6; b >= 0; --b) s += ((v >> b) & 1u) ? '1' : '0';
    return s;
}
std::string candidate::k31_string() const { return bits7(k31); }
std::string candidate::k32_string() const { return bits7(static_cast<uint64_t>(std::llabs(k32))); }

uint64_t candidate_a(const candidate& c, unsigned n) {
    if (c.n_lt2_zero && n < 2) return 0;
    return wrap_bits(static_cast<int64_t>(n * c.k31) + c.k32, ua60553::a_fmt.width);
}

std::vector<candidate> search_generators(const grid& g, double keep_below) {
    std::vector<candidate> all;
    // A candidate is dropped as soon as one code's error exceeds keep_below (early abort); small n,
    // where the linear law is hardest to fit, come first.
    const double best = keep_below;
    for (uint64_t k31 = 96; k31 <= 106; ++k31) {  // [0.75, 0.83] in Q0.7
        if (std::bitset<8>(k31).count() > 4) continue;
        for (int64_t k32 = -127; k32 <= 127; ++k32) {
            if (std::bitset<8>(static_cast<uint64_t>(std::llabs(k32))).count() > 3) continue;
            for (bool special : {false, true}) {
                candidate c{k31, k32, special};
                double worst = 0;
                for (unsigned n = 1; n <= 1000 && worst <= best; ++n) {
                    const uint64_t a = candidate_a(c, n);
                    worst = std::max(worst, g.max_rel_err_056(n, [a](uint64_t code) {
                        return datapath_brdf(a, ua60553::a_fmt.frac, code);
                    }, best));
                }
                if (worst > keep_below) continue;
                c.worst_1000 = worst;
                for (unsigned n = 1; n <= 512; ++n) {
                    const uint64_t a = candidate_a(c, n);
                    c.worst_512 = std::max(c.worst_512, g.max_rel_err_056(n, [a](uint64_t code) {
                        return datapath_brdf(a, ua60553::a_fmt.frac, code);
                    }));
                }
                all.push_back(c);
            }
        }
    }
    std::sort(all.begin(), all.end(), [](const candidate& x, const candidate& y) {
        if (x.worst_1000 != y.worst_1000) return x.worst_1000 < y.worst_1000;
        if (x.nnz() != y.nnz()) return x.nnz() < y.nnz();
        if (x.n_lt2_zero != y.n_lt2_zero) return !x.n_lt2_zero;
        return x.worst_512 < y.worst_512;
    });
    return all;
}

}  // namespace shading::study
