// The squared-quadratic device's relative error in cos^n's tail: the accuracy study's measure
// (study_metrics.h) counts only the codes where cos^n >= 0.56 (the quadratic-BRDF paper, Fig. 3);
// this program also takes the codes down to a lower floor, where the highlight's ring lies. For
// each floor and each n: the largest |RG_SQ - cos^n| / cos^n over the Q1.15 codes of cos in
// [0, 1] with cos^n >= floor, RG_SQ (Q1.18, after the k-th square) from the golden model.
//   squared_tail [n ...]      (default: 2 3 5 10 20 100 1000, then the worst n in [1, 1000] and
//                             the largest n whose bend word is not 0)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "arith/squared_arith.h"
#include "formats/specular_formats.h"
#include "formats/squared_formats.h"
#include "reference/brdf_reference.h"

using namespace shading;

namespace {

struct worst {
    double rel = 0, cos = 0;
};

worst tail_error(unsigned n, double floor) {
    worst w;
    for (uint64_t code = 0; code <= spec::cos_one; ++code) {
        const double c = to_real(code, spec::cos_fmt);
        const double exact = ref::cos_pow(c, n);
        if (exact < floor) continue;
        const double q = to_real(golden_squared(n, code, {0, 0, 0}, overflow_mode::saturate).brdf, squared::sq_fmt);
        const double rel = std::abs(q - exact) / exact;
        if (rel > w.rel) w = {rel, c};
    }
    return w;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<unsigned> ns;
    for (int i = 1; i < argc; ++i) {
        const long n = std::strtol(argv[i], nullptr, 10);
        if (n < 1 || n > 1023) {
            std::fprintf(stderr, "usage: squared_tail [n ...] (each n in 1..1023)\n");
            return 2;
        }
        ns.push_back(static_cast<unsigned>(n));
    }
    if (ns.empty()) ns = {2, 3, 5, 10, 20, 100, 1000};
    const double floors[] = {0.56, 0.1};
    std::printf("worst relative error of RG_SQ (golden_squared) against cos^n over the Q1.15 codes with cos^n >= floor\n");
    std::printf("%6s %22s %22s\n", "n", "floor 0.56 (at cos)", "floor 0.1 (at cos)");
    for (unsigned n : ns) {
        std::printf("%6u", n);
        for (double f : floors) {
            const worst w = tail_error(n, f);
            std::printf("   %8.3f %% (%.4f)", 100 * w.rel, w.cos);
        }
        std::printf("\n");
    }
    if (argc > 1) return 0;
    // The bend as built: f x ~f (~f = 1 - f - 2^-9) shifted to Q0.29 and floored onto Q0.12.
    unsigned last_bend = 0;
    for (unsigned n = 1; n <= 1023; ++n)
        if (golden_squared_a(n).bend != 0) last_bend = n;
    std::printf("bend word (Q0.12) non-zero up to n = %u, 0 for every n above\n", last_bend);
    for (double f : floors) {
        worst all;
        unsigned at = 0;
        for (unsigned n = 1; n <= 1000; ++n) {
            const worst w = tail_error(n, f);
            if (w.rel > all.rel) all = w, at = n;
        }
        std::printf("floor %.2f, n in [1, 1000]: worst %.3f %% at n = %u (cos %.4f)\n", f, 100 * all.rel, at, all.cos);
    }
    return 0;
}
