// Forward-difference testbench program: evaluates one raster line with the coefficients of
// every variant (quadratics as cubics with A = 0), one pixel per clock, checks every pixel
// against the golden model and against the Horner unit's golden result at the same t (documented
// bound 0..2 LSB of Q16.16), measures the error against the exact intensity; writes a CSV.
// Fails on a mismatch, a pixel outside the bound, or an unexpected report. Options common to every
// bench: common/common_options.h.
//
//   interp_fd_tb                        VCD traces/interp_fd.vcd, view traces/interp_fd.gtkw
//   interp_fd_tb --m 6 --csv out/interp_fd.csv
//   interp_fd_tb --random 1000000 --seed 7 --m 6   random intervals of 1..2^m pixels
#include <cmath>
#include <fstream>
#include <iostream>

#include "testbenches/common/bench_runner.h"
#include "testbenches/options/bench_options.h"
#include "testbenches/interp/interp_fd_bench.h"
#include "testbenches/interp/interp_line.h"

using namespace shading;
using namespace shading::tb;

namespace {

using options = interp_fd_options;

template <unsigned M>
int run_m(bench_runner& run, const options& o) {
    if (run.random()) {
        fd_bench<M> bench("tb", random_fd_intervals<M>(run.random_count(), run.seed()));
        bench.checker.keep_samples(false);
        bench.checker.inject_mismatch(run.inject(), run.inject_count());
        run.simulate(bench, sc_core::sc_max_time());
        std::cout << "interp_fd (m = " << M << "): FD - Horner in [" << bench.checker.min_vs_horner() << ", "
                  << bench.checker.max_vs_horner() << "] LSB (bound [0, 2]), clocks per pixel "
                  << bench.checker.cycles_per_pixel() << '\n';
        run.report_random("random_m" + std::to_string(M), bench.checker.checked(), bench.checker.mismatches());
        return run.finish(bench.checker.checked(), bench.checker.mismatches(),
                          bench.checker.within_horner_bound() ? 0 : 1);
    }
    const auto line = make_line(o.width, M);
    std::vector<fd_interval> ivs;
    std::vector<variant> iv_variant;
    for (auto v : all_variants)
        for (const auto& iv : line.intervals) {
            const auto k = variant_coefs(v, iv);
            ivs.push_back({is_quad(v) ? as_cubic(k) : k, iv.len});
            iv_variant.push_back(v);
        }
    fd_bench<M> bench("tb", ivs);
    bench.checker.inject_mismatch(run.inject(), run.inject_count());
    run.simulate(bench);

    std::ofstream csv;
    if (!o.csv_path.empty()) {
        csv.open(o.csv_path);
        csv << "unit,variant,pixel,t,exact,value,error\n";
    }
    const auto& s = bench.checker.samples();
    const bool in_bound = bench.checker.within_horner_bound();
    std::cout << "interp_fd: " << s.size() << " pixels, intervals of " << line.n() << "; FD - Horner in ["
              << bench.checker.min_vs_horner() << ", " << bench.checker.max_vs_horner()
              << "] LSB of Q16.16 (documented bound [0, 2])\n";
    std::size_t i = 0;
    for (auto v : all_variants) {
        std::size_t n = 0, bad = 0;
        double max_err = 0.0;
        sc_core::sc_time first, last;
        for (; i < s.size() && iv_variant[s[i].interval] == v; ++i, ++n) {
            const unsigned pixel = line.intervals[s[i].interval % line.intervals.size()].first_pixel + s[i].k;
            const double value = to_real(s[i].out, interp::coef_fmt);
            const double exact = line.exact[pixel];
            max_err = std::max(max_err, std::abs(value - exact));
            if (!s[i].matched) ++bad;
            if (n == 0) first = s[i].accepted;
            last = s[i].valid;
            if (csv.is_open())
                csv << "fd," << variant_name(v) << ',' << pixel << ',' << static_cast<double>(s[i].k) / line.n() << ','
                    << exact << ',' << value << ',' << value - exact << '\n';
        }
        const double cpp = n ? (last - first) / interp_period() / static_cast<double>(n) : 0.0;
        std::cout << "  " << variant_name(v) << ": " << n << " pixels, mismatches " << bad
                  << ", max |I - exact| = " << max_err << ", clocks per pixel " << cpp << '\n';
        run.summary({run.bench(), variant_name(v) + "_m" + std::to_string(M), n, bad, fmt_levels(max_err),
                     fmt_number(cpp),
                     in_bound ? "max |I_hw - exact|; FD-Horner within [0,2] LSB" : "FD-Horner OUT OF BOUND"});
    }
    return run.finish(s.size(), bench.checker.mismatches(), in_bound ? 0 : 1);
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    options o;
    if (auto rc = parse_interp_fd(argc, argv, o)) return *rc;
    bench_runner run("interp_fd", o.bench);
    if (auto rc = run.start(argc, argv)) return *rc;
    switch (o.m) {
        case 2: return run_m<2>(run, o);
        case 3: return run_m<3>(run, o);
        case 4: return run_m<4>(run, o);
        case 5: return run_m<5>(run, o);
        default: return run_m<6>(run, o);
    }
}
