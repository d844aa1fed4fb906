// Accuracy study of the quadratic BRDF (the quadratic-BRDF paper), of the devices built on it and of
// our squared-quadratic law. For every n in [1, --n-max] and every method: the largest relative
// error against cos^n where cos^n >= 0.56 (the paper's measure) and where cos^n >= 0.1 (the tail
// below it, where a highlight's rim lies), the NMSE over the 32769 Q1.15 codes of cos in [0, 1]
// (study_metrics.h) and the NMSE over the distribution of cos = N.H on the rendered head
// (head_surface.h). Writes, into --out:
//   accuracy.csv            one row per n, three columns per method (+ the a of each generator)
//   accuracy_summary.csv    one row per method: worst cases, whether the paper's 4 % holds
//   fig2_curve.csv          cos^n and the approximations along cos for --fig2-n (the paper's Fig. 2)
//   rom_fraction_sweep.csv  the measurement that fixed the ROM word's fraction bits
//   hw_cost.csv             ROM bits, multiplier cells and adder bits per design
// and appends one summary row per method to $SHADING_SUMMARY.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "testbenches/options/tool_options.h"
#include "reference/brdf_reference.h"
#include "formats/specular_formats.h"
#include "formats/squared_formats.h"
#include "arith/specular_arith.h"
#include "arith/squared_arith.h"
#include "formats/ua22802_formats.h"
#include "arith/ua22802_arith.h"
#include "formats/ua60553_formats.h"
#include "arith/ua60553_tuned_arith.h"
#include "head_surface.h"
#include "study_devices.h"
#include "study_metrics.h"
#include "trial_law.h"

using namespace shading;
using namespace shading::study;

namespace {

struct method {
    std::string id, label;
    std::function<double(unsigned n, uint64_t code)> f;
};

// `trial_a`: the fitted a of the trial law per n (trial_law.h).
std::vector<method> methods(const std::vector<double>& trial_a) {
    auto c_of = [](uint64_t code) { return to_real(code, spec::cos_fmt); };
    std::vector<method> ms{
        {"quad_exact", "quadratic, exact a(n), real-valued (clamped to [0,1])",
         [c_of](unsigned n, uint64_t code) {
             return std::clamp(ref::quadratic(c_of(code), ref::a_exact(n)), 0.0, 1.0);
         }},
    };
    for (const study_device& d : study_devices()) ms.push_back({d.id, d.label, d.brdf});
    const std::vector<method> laws{
        {"squared_law", "squared-quadratic law (ours), real-valued",
         [c_of](unsigned n, uint64_t code) { return ref::squared_law(c_of(code), n); }},
        {"trial_inflection", "trial law, n' in [2,4), a at the inflection (real)",
         [c_of](unsigned n, uint64_t code) { return trial_law(c_of(code), trial_a_inflection(n), n); }},
        {"trial_fitted", "trial law, n' in [2,4), a fitted on the head (real)",
         [c_of, &trial_a](unsigned n, uint64_t code) { return trial_law(c_of(code), trial_a[n], n); }},
        {"schlick", "Schlick c/(n - n c + c)",
         [c_of](unsigned n, uint64_t code) { return ref::schlick(c_of(code), n); }},
        // Lyon's chord form (reference lyon_power): gamma from n, and a small fixed gamma = 4.
        {"lyon", "Lyon max(0, 1 - (n/g) D.D/2)^g, g = 2^floor(log2 n)",
         [c_of](unsigned n, uint64_t code) { return ref::lyon_power(c_of(code), n, 0); }},
        {"lyon_g4", "Lyon max(0, 1 - (n/4) D.D/2)^4",
         [c_of](unsigned n, uint64_t code) { return ref::lyon_power(c_of(code), n, 4); }},
        {"cosk", "(cos k gamma)^(n/k) as printed",
         [c_of](unsigned n, uint64_t code) { return ref::cos_k_gamma(c_of(code), n, cosk_k_for(n)); }},
        {"cosk_k2", "(cos k gamma)^(n/k^2) re-derived",
         [c_of](unsigned n, uint64_t code) {
             const double k = cosk_k_for(n);
             return ref::cos_k_gamma(c_of(code), n / k, k);  // exponent (n/k)/k
         }},
    };
    ms.insert(ms.end(), laws.begin(), laws.end());
    return ms;
}

// Hardware cost (modules/tuned/README.md, "Hardware cost"): multiplier cells = WA x WB of each array multiplier (a multiplier
// by a hardwired constant keeps only the rows of its non-zero constant bits: WN x nnz); adder bits
// = output width of each adder; gates = inputs of the special case's OR gate + AND gates of the key
// block. Registers and the colour path are common to all and listed for completeness. Every width is
// read from the format tables (src/floor/formats) the device tops take their template widths from.
struct cost {
    std::string design;
    unsigned rom_bits, gen_mult_cells, gen_adder_bits, gen_gates, mul10_cells, shared_mult_cells,
        shared_adder_bits;
    unsigned total_mult() const { return gen_mult_cells + mul10_cells + shared_mult_cells; }
    unsigned total_adder() const { return gen_adder_bits + shared_adder_bits; }
};

unsigned nnz(const char* bits) {
    unsigned k = 0;
    for (; *bits; ++bits) k += *bits == '1';
    return k;
}

std::vector<cost> costs() {
    using spec::brdf_fmt, spec::cos_fmt, spec::d_fmt, spec::ksi_fmt;
    const unsigned shared_mult = cos_fmt.width * cos_fmt.width + 3 * (brdf_fmt.width * ksi_fmt.width);  // MUL7, MUL12..14
    const unsigned shared_add = d_fmt.width + brdf_fmt.width;                                         // ADD9, ADD11
    const unsigned wn = ua60553::n_fmt.width, wa60553 = ua60553::a_fmt.width;
    const unsigned mul10_60553 = wa60553 * d_fmt.width;                  // MUL10: a x (cos^2 - cos)
    const unsigned tuned_gates = (wn - ua60553::tuned_or_lo) + wa60553;  // OR over n[9:1], key block
    return {
        {"ua22802_rom", ua22802::rom_bits, 0, 0, 0, ua22802::a_fmt.width * d_fmt.width, shared_mult, shared_add},
        {"ua60553_patent", 0, wn * nnz(ua60553::patent.k31_bits), wa60553, 0, mul10_60553, shared_mult,
         shared_add},
        {"ua60553_minimax", 0, wn * nnz(ua60553::minimax.k31_bits), wa60553, tuned_gates, mul10_60553,
         shared_mult, shared_add},
        {"ua60553_rom_matched", 0, wn * nnz(ua60553::rom_matched.k31_bits), wa60553, tuned_gates, mul10_60553,
         shared_mult, shared_add},
    };
}

}  // namespace

int main(int argc, char* argv[]) {
    shading::tb::accuracy_study_options o;
    if (auto rc = shading::tb::parse_accuracy_study(argc, argv, o)) return *rc;  // fig2_n already at most n_max
    const std::string &out_dir = o.out, &data_dir = o.data_dir;
    const unsigned fig2_n = o.fig2_n, size = o.size, n_max = o.n_max;
    // Every file goes into --out: made if missing, and a folder that cannot be written stops the
    // study before its minute of work instead of leaving no file behind a "wrote" line.
    std::error_code made;
    std::filesystem::create_directories(out_dir, made);
    if (made || !std::ofstream(out_dir + "/accuracy_summary.csv")) {
        std::fprintf(stderr, "accuracy_study: cannot write into --out %s\n", out_dir.c_str());
        return 1;
    }

    // The distribution of N.H on the head, and the trial law's a fitted on it for every n.
    // Timing: CPU seconds of this process (the machine is shared) and wall-clock seconds.
    std::clock_t cpu = std::clock();
    auto t0 = std::chrono::steady_clock::now();
    const auto lap = [&cpu, &t0](const char* what) {
        const std::clock_t c = std::clock();
        const auto t = std::chrono::steady_clock::now();
        std::printf("%s in %.1f s CPU (%.1f s wall)\n", what, static_cast<double>(c - cpu) / CLOCKS_PER_SEC,
                    std::chrono::duration<double>(t - t0).count());
        cpu = c, t0 = t;
    };
    cos_distribution dist;
    try {
        const head_surface head(data_dir, size);
        dist = nh_distribution(head.raster());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "accuracy_study: %s\n", e.what());
        return 1;
    }
    std::vector<double> trial_a(1001, 0.0);
    for (unsigned n = 1; n <= n_max; ++n) trial_a[n] = trial_a_fitted(dist, n);
    std::printf("head %ux%u: %zu (pixel, light) samples with N.L > 0, %zu distinct N.H codes\n", size, size,
                dist.samples, dist.codes.size());
    lap("the head's distribution and the trial law's a fitted for every n");

    const grid g;
    const auto ms = methods(trial_a);
    const std::size_t M = ms.size();
    std::vector<std::vector<double>> maxrel(M, std::vector<double>(1001)), nm(M, std::vector<double>(1001)),
        hnm(M, std::vector<double>(1001)), maxrel010(M, std::vector<double>(1001));

    // Each method once per code and n; the three measures read the same values.
    std::vector<double> exact(spec::cos_one + 1), vals(spec::cos_one + 1);
    for (unsigned n = 1; n <= n_max; ++n) {
        for (uint64_t c = 0; c <= spec::cos_one; ++c) exact[c] = ref::cos_pow(to_real(c, spec::cos_fmt), n);
        double den = 0, hden = 0;
        for (uint64_t c = 0; c <= spec::cos_one; ++c) den += exact[c] * exact[c];
        for (std::size_t i = 0; i < dist.codes.size(); ++i) hden += dist.weight[i] * exact[dist.codes[i]] * exact[dist.codes[i]];
        for (std::size_t m = 0; m < M; ++m) {
            const auto& f = ms[m].f;
            double num = 0, hnum = 0;
            for (uint64_t c = 0; c <= spec::cos_one; ++c) {
                vals[c] = f(n, c);
                const double e = vals[c] - exact[c];
                num += e * e;
            }
            for (std::size_t i = 0; i < dist.codes.size(); ++i) {
                const double e = vals[dist.codes[i]] - exact[dist.codes[i]];
                hnum += dist.weight[i] * e * e;
            }
            maxrel[m][n] = g.max_rel_err_056(n, [&vals](uint64_t code) { return vals[code]; });
            // The tail the paper's 0.56 leaves out: down to cos^n = 0.1, where a highlight's rim is.
            double worst010 = 0;
            for (uint64_t c = 0; c <= spec::cos_one; ++c)
                if (exact[c] >= 0.1) worst010 = std::max(worst010, std::abs(vals[c] - exact[c]) / exact[c]);
            maxrel010[m][n] = worst010;
            nm[m][n] = num / den;
            hnm[m][n] = hnum / hden;
        }
    }
    lap("every method measured for every n");

    std::ofstream csv(out_dir + "/accuracy.csv");
    csv << "n,cosk_k,a_exact,a_rom,a_patent,a_minimax,a_rom_matched,k_squared,a_squared,k_trial,a_trial_inflection,"
           "a_trial_fitted";
    for (const auto& m : ms) csv << ",maxrel056_" << m.id << ",nmse_" << m.id << ",hnmse_" << m.id;
    for (const auto& m : ms) csv << ",maxrel010_" << m.id;
    csv << '\n';
    csv.precision(9);
    for (unsigned n = 1; n <= n_max; ++n) {
        const auto sq = golden_squared_a(n);
        csv << n << ',' << cosk_k_for(n) << ',' << ref::a_exact(n) << ','
            << to_real(golden_a_rom(n), ua22802::a_fmt) << ','
            << to_real(golden_a_linear(n, ua60553::patent), ua60553::a_fmt) << ','
            << to_real(golden_a_tuned(n, ua60553::minimax), ua60553::a_fmt) << ','
            << to_real(golden_a_tuned(n, ua60553::rom_matched), ua60553::a_fmt) << ',' << sq.k << ','
            << to_real(sq.a, squared::a_fmt) << ',' << trial_k(n) << ',' << trial_a_inflection(n) << ',' << trial_a[n];
        for (std::size_t m = 0; m < M; ++m) csv << ',' << maxrel[m][n] << ',' << nm[m][n] << ',' << hnm[m][n];
        for (std::size_t m = 0; m < M; ++m) csv << ',' << maxrel010[m][n];
        csv << '\n';
    }

    // Per method: worst over n in [1, 512] and [1, 1000], the n where it occurs, the paper's claim.
    std::ofstream sum(out_dir + "/accuracy_summary.csv");
    sum << "method,label,worst_maxrel056_1_512,at_n,worst_maxrel056_1_1000,at_n,paper_4pct_holds_1_512,"
           "worst_nmse_1_1000,at_n,n_above_4pct,n_above_1pct,worst_head_nmse_1_1000,at_n,worst_maxrel010_1_1000,at_n\n";
    const char* summary_path = std::getenv("SHADING_SUMMARY");
    std::ofstream tsv;
    if (summary_path != nullptr && *summary_path != '\0') tsv.open(summary_path, std::ios::app);
    std::printf("%-16s %11s %5s %11s %5s %5s %5s %10s %5s %10s %5s\n", "method", "worst<=512", "at n", "worst<=1000",
                "at n", "<=4%", ">1%", "worst NMSE", "at n", "head NMSE", "at n");
    std::size_t points = 0;
    for (unsigned n = 1; n <= n_max; ++n) points += g.codes(n).size();
    for (std::size_t m = 0; m < M; ++m) {
        auto arg = [&](const std::vector<double>& v, unsigned hi) {
            hi = std::min(hi, n_max);
            return static_cast<unsigned>(std::max_element(v.begin() + 1, v.begin() + hi + 1) - v.begin());
        };
        const unsigned n512 = arg(maxrel[m], 512), n1000 = arg(maxrel[m], 1000), nn = arg(nm[m], 1000),
                       nh = arg(hnm[m], 1000), n010 = arg(maxrel010[m], 1000);
        const bool holds = maxrel[m][n512] <= 0.04;
        unsigned above4 = 0, above1 = 0;
        for (unsigned n = 1; n <= n_max; ++n) above4 += maxrel[m][n] > 0.04, above1 += maxrel[m][n] > 0.01;
        sum << ms[m].id << ",\"" << ms[m].label << "\"," << maxrel[m][n512] << ',' << n512 << ','
            << maxrel[m][n1000] << ',' << n1000 << ',' << (holds ? "yes" : "no") << ',' << nm[m][nn] << ','
            << nn << ',' << above4 << ',' << above1 << ',' << hnm[m][nh] << ',' << nh << ','
            << maxrel010[m][n010] << ',' << n010 << '\n';
        std::printf("%-16s %11.5f %5u %11.5f %5u %5s %5u %10.3e %5u %10.3e %5u\n", ms[m].id.c_str(), maxrel[m][n512],
                    n512, maxrel[m][n1000], n1000, holds ? "yes" : "no", above1, nm[m][nn], nn, hnm[m][nh], nh);
        if (tsv.is_open())
            tsv << "accuracy\t" << ms[m].id << '\t' << points << "\t-\t" << std::fixed
                << std::setprecision(2) << 100.0 * maxrel[m][n1000] << std::defaultfloat
                << "%\t-\tworst max rel err above 0.56, n in [1," << n_max << "] (at n=" << n1000
                << "); paper's 4% for n<=512: " << (holds ? "holds" : "fails") << "; worst NMSE "
                << nm[m][nn] << ", on the head " << hnm[m][nh] << '\n';
    }
    // The tuned generators against the ROM, n by n.
    const auto index_of = [&ms](const char* id) {
        return static_cast<std::size_t>(std::find_if(ms.begin(), ms.end(), [id](const method& m) { return m.id == id; }) -
                                        ms.begin());
    };
    const std::size_t rom = index_of("rom");
    for (const char* id : {"minimax", "rom_matched"}) {
        const std::size_t t = index_of(id);
        unsigned worse = 0, last_worse = 0;
        double excess = 0;
        for (unsigned n = 1; n <= n_max; ++n) {
            const double d = maxrel[t][n] - maxrel[rom][n];
            if (d > 0) ++worse, last_worse = n;
            excess = std::max(excess, d);
        }
        std::printf("%s vs rom, n by n: worse at %u of %u n (the largest such n: %u), by at most %.5f (absolute)\n",
                    id, worse, n_max, last_worse, excess);
    }

    // The quadratic-BRDF paper's Fig. 2: the curves along cos for one n.
    std::ofstream fig2(out_dir + "/fig2_curve.csv");
    fig2 << "n,cos,exact";
    for (const auto& m : ms) fig2 << ',' << m.id;
    fig2 << '\n';
    fig2.precision(9);
    for (uint64_t c = 0; c <= spec::cos_one; c += 8) {
        fig2 << fig2_n << ',' << to_real(c, spec::cos_fmt) << ',' << ref::cos_pow(to_real(c, spec::cos_fmt), fig2_n);
        for (const auto& m : ms) fig2 << ',' << m.f(fig2_n, c);
        fig2 << '\n';
    }

    // The ROM word's fraction bits: how much rounding a to F fraction bits adds to each n's error.
    std::ofstream sweep(out_dir + "/rom_fraction_sweep.csv");
    sweep << "frac_bits,word_bits,rom_bits,worst_maxrel056_1_1000,max_excess_over_model_rel_n3_1000,"
             "max_excess_over_model_abs\n";
    for (int F = 2; F <= 10; ++F) {
        double worst = 0, excess_rel = 0, excess_abs = 0;
        for (unsigned n = 1; n <= n_max; ++n) {
            const uint64_t a = static_cast<uint64_t>(std::floor(std::ldexp(ref::a_exact(n), F) + 0.5));
            const double e = g.max_rel_err_056(n, [&](uint64_t code) { return datapath_brdf(a, F, code); });
            worst = std::max(worst, e);
            excess_abs = std::max(excess_abs, e - maxrel[0][n]);
            if (n >= 3) excess_rel = std::max(excess_rel, (e - maxrel[0][n]) / maxrel[0][n]);
        }
        const unsigned word = static_cast<unsigned>(ua22802::a_fmt.int_bits() + F);
        sweep << F << ',' << word << ',' << ua22802::rom_words * word << ',' << worst << ',' << excess_rel << ',' << excess_abs
              << '\n';
    }

    std::ofstream hw(out_dir + "/hw_cost.csv");
    hw << "design,rom_bits,generator_multiplier_cells,generator_adder_bits,special_case_gates,mul10_cells,"
          "shared_multiplier_cells,shared_adder_bits,total_multiplier_cells,total_adder_bits\n";
    for (const auto& c : costs())
        hw << c.design << ',' << c.rom_bits << ',' << c.gen_mult_cells << ',' << c.gen_adder_bits << ','
           << c.gen_gates << ',' << c.mul10_cells << ',' << c.shared_mult_cells << ',' << c.shared_adder_bits
           << ',' << c.total_mult() << ',' << c.total_adder() << '\n';

    std::cout << "accuracy_study: wrote " << out_dir << "/{accuracy,accuracy_summary,fig2_curve,"
              << "rom_fraction_sweep,hw_cost}.csv\n";
    return (csv && sum && fig2 && sweep && hw) ? 0 : 1;
}
