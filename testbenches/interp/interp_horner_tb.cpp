// Horner-unit testbench program: evaluates one raster line, interval by interval and pixel by
// pixel, with the coefficients of every variant (case 1 / case 2 cubic with shift-and-add or
// exact /3, quadratic), back to back through the iterative Horner unit of the interpolation paper, Fig. 4.
// Checks every micro-step against the golden model, measures clocks per pixel and the error
// against the exact intensity; writes a per-pixel CSV. Options common to every bench:
// common/common_options.h.
//
//   interp_horner_tb                    VCD traces/interp_horner.vcd, view traces/interp_horner.gtkw
//   interp_horner_tb --csv out/interp_horner.csv
//   interp_horner_tb --random 100000 --seed 7 [--gap 2]
//   interp_horner_tb --abstraction fast ...   the fast pin-level unit (interp/horner_unit_fast.h)
#include <cmath>
#include <fstream>
#include <iostream>

#include "testbenches/common/bench_runner.h"
#include "testbenches/options/bench_options.h"
#include "testbenches/interp/interp_horner_bench.h"
#include "testbenches/interp/interp_line.h"

using namespace shading;
using namespace shading::tb;

namespace {

template <class Bench>
int run_bench(bench_runner& run, const std::string& csv_path, unsigned width, unsigned m, unsigned gap);

}  // namespace

int sc_main(int argc, char* argv[]) {
    interp_horner_options o;
    if (auto rc = parse_interp_horner(argc, argv, o)) return *rc;
    bench_runner run("interp_horner", o.bench);
    if (auto rc = run.start(argc, argv)) return *rc;
    const std::string& csv_path = o.csv_path;
    const unsigned width = o.width, m = o.m, gap = o.gap;
    const std::string& level = o.abstraction;
    std::cout << "interp_horner: abstraction " << level << '\n';
    return level == "fast" ? run_bench<horner_bench_fast>(run, csv_path, width, m, gap)
                           : run_bench<horner_bench>(run, csv_path, width, m, gap);
}

namespace {

template <class Bench>
int run_bench(bench_runner& run, const std::string& csv_path, unsigned width, unsigned m, unsigned gap) {

    if (run.random()) {
        Bench bench("tb", random_horner_requests(run.random_count(), run.seed()), gap);
        bench.checker.keep_samples(false);
        bench.checker.inject_mismatch(run.inject(), run.inject_count());
        run.simulate(bench, sc_core::sc_max_time());
        std::cout << "interp_horner: clocks per result " << bench.checker.cycles_per_result() << '\n';
        run.report_random("random", bench.checker.checked(), bench.checker.mismatches());
        return run.finish(bench.checker.checked(), bench.checker.mismatches());
    }

    const auto line = make_line(width, m);
    struct tag {
        variant v;
        unsigned pixel;
    };
    std::vector<horner_request> reqs;
    std::vector<tag> tags;
    for (auto v : all_variants)
        for (const auto& iv : line.intervals) {
            const auto k = variant_coefs(v, iv);
            for (unsigned j = 0; j < iv.len; ++j) {
                reqs.push_back({k, uint64_t{j} << (interp::t_fmt.frac - m), is_quad(v)});
                tags.push_back({v, iv.first_pixel + j});
            }
        }

    Bench bench("tb", reqs, gap);
    bench.checker.inject_mismatch(run.inject(), run.inject_count());
    run.simulate(bench);

    std::ofstream csv;
    if (!csv_path.empty()) {
        csv.open(csv_path);
        csv << "unit,variant,pixel,t,exact,value,error\n";
    }
    const auto& s = bench.checker.samples();
    std::size_t i = 0;
    std::cout << "interp_horner: " << s.size() << " pixels (" << line.intervals.size() << " intervals of "
              << line.n() << ", the last " << line.intervals.back().len << " long, x " << all_variants.size()
              << " variants)\n";
    for (auto v : all_variants) {
        std::size_t n = 0, bad = 0;
        double max_err = 0.0;
        sc_core::sc_time first, last;
        for (; i < s.size() && tags[i].v == v; ++i, ++n) {
            const double value = to_real(s[i].out, interp::coef_fmt);
            const double exact = line.exact[tags[i].pixel];
            max_err = std::max(max_err, std::abs(value - exact));
            if (!s[i].matched) ++bad;
            if (n == 0) first = s[i].accepted;
            last = s[i].valid;
            if (csv.is_open())
                csv << "horner," << variant_name(v) << ',' << tags[i].pixel << ','
                    << to_real(s[i].req.t, interp::t_fmt) << ',' << exact << ',' << value << ',' << value - exact << '\n';
        }
        const double cpp = n ? (last - first) / interp_period() / static_cast<double>(n) : 0.0;
        std::cout << "  " << variant_name(v) << ": " << n << " pixels, mismatches " << bad
                  << ", max |I - exact| = " << max_err << ", clocks per pixel " << cpp << '\n';
        run.summary({run.bench(), variant_name(v), n, bad, fmt_levels(max_err), fmt_number(cpp),
                     gap == 0 ? "max |I_hw - exact intensity| (0..255); back-to-back"
                              : "max |I_hw - exact intensity| (0..255); gap " + std::to_string(gap)});
    }
    return run.finish(s.size(), bench.checker.mismatches(), s.size() == reqs.size() ? 0 : 1);
}

}  // namespace
