#include "generator_search.h"

#include <algorithm>
#include <bitset>
#include <cstdlib>

#include "arith/ua22802_arith.h"
#include "formats/ua22802_formats.h"
#include "formats/ua60553_formats.h"

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

std::size_t rank_against_rom(const grid& g, std::vector<candidate>& all) {
    std::vector<double> rom(1001);
    for (unsigned n = 1; n <= 1000; ++n) {
        const uint64_t w = golden_a_rom(n);
        rom[n] = g.max_rel_err_056(n, [w](uint64_t code) { return datapath_brdf(w, ua22802::a_fmt.frac, code); });
    }
    for (auto& c : all) {
        c.excess_over_rom = -1.0;
        c.n_worse_than_rom = 0;
        for (unsigned n = 1; n <= 1000; ++n) {
            const uint64_t a = candidate_a(c, n);
            const double e = g.max_rel_err_056(n, [a](uint64_t code) {
                return datapath_brdf(a, ua60553::a_fmt.frac, code);
            });
            c.excess_over_rom = std::max(c.excess_over_rom, e - rom[n]);
            c.n_worse_than_rom += e > rom[n] ? 1u : 0u;
        }
    }
    std::size_t best = 0;
    for (std::size_t i = 1; i < all.size(); ++i) {
        const auto& x = all[i];
        const auto& b = all[best];
        if (x.excess_over_rom != b.excess_over_rom ? x.excess_over_rom < b.excess_over_rom
            : x.worst_1000 != b.worst_1000     ? x.worst_1000 < b.worst_1000
                                               : x.nnz() < b.nnz())
            best = i;
    }
    return best;
}

}  // namespace shading::study
