// Search for the best ROM-free generator of `a` (generator_search.h). Writes every candidate
// whose worst error is below --keep as CSV (best first) and prints the winner; the winner is fixed
// in src/ua60553_formats.h as ua60553::minimax; the candidate closest to the ROM prototype n by n
// as ua60553::rom_matched (tests re-check both).
#include <cstdio>
#include <fstream>
#include <iostream>

#include "testbenches/options/tool_options.h"
#include "generator_search.h"

int main(int argc, char* argv[]) {
    shading::tb::generator_search_options o;
    if (auto rc = shading::tb::parse_generator_search(argc, argv, o)) return *rc;
    const std::string& csv = o.csv;
    const double keep = o.keep;

    using namespace shading::study;
    const grid g;
    auto all = search_generators(g, keep);
    const std::size_t matched = all.empty() ? 0 : rank_against_rom(g, all);
    std::ofstream out(csv);
    out << "rank,k31_bits,k31,k32_sign,k32_bits,k32,n_lt2_zero,nonzero_bits,worst_maxrel_1_1000,"
           "worst_maxrel_1_512,excess_over_rom,n_worse_than_rom\n";
    for (std::size_t i = 0; i < all.size(); ++i) {
        const auto& c = all[i];
        out << i + 1 << ',' << c.k31_string() << ',' << c.k31 / 128.0 << ',' << (c.k32 < 0 ? '-' : '+')
            << ',' << c.k32_string() << ',' << c.k32 / 128.0 << ',' << c.n_lt2_zero << ',' << c.nnz()
            << ',' << c.worst_1000 << ',' << c.worst_512 << ',' << c.excess_over_rom << ','
            << c.n_worse_than_rom << '\n';
    }
    if (all.empty()) {
        std::cerr << "generator_search: no candidate below " << keep << "\n";
        return 1;
    }
    const auto& w = all.front();
    std::printf("winner: K31 = 0.%s (%.7f), K32 = %c0.%s (%+.7f), n<2 -> a=0: %s, worst max rel err "
                "above 0.56: %.5f (n in [1,1000]), %.5f (n in [1,512]); %zu candidates kept\n",
                w.k31_string().c_str(), w.k31 / 128.0, w.k32 < 0 ? '-' : '+', w.k32_string().c_str(),
                w.k32 / 128.0, w.n_lt2_zero ? "yes" : "no", w.worst_1000, w.worst_512, all.size());
    const auto& m = all[matched];
    std::printf("closest to the ROM n by n: K31 = 0.%s (%.7f), K32 = %c0.%s (%+.7f), n<2 -> a=0: %s, "
                "worse than the ROM at %u of 1000 n by at most %.5f, worst %.5f (minimax: at %u n by %.5f)\n",
                m.k31_string().c_str(), m.k31 / 128.0, m.k32 < 0 ? '-' : '+', m.k32_string().c_str(),
                m.k32 / 128.0, m.n_lt2_zero ? "yes" : "no", m.n_worse_than_rom, m.excess_over_rom,
                m.worst_1000, w.n_worse_than_rom, w.excess_over_rom);
    for (const auto& c : all)
        if (!c.n_lt2_zero) {
            std::printf("best without the n<2 special case: K31 = 0.%s, K32 = %+.7f, worst %.5f\n",
                        c.k31_string().c_str(), c.k32 / 128.0, c.worst_1000);
            break;
        }
    return out ? 0 : 1;
}
