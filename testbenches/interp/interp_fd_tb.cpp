// Forward-difference testbench program: evaluates one raster line with the coefficients of
// every variant (quadratics as cubics with A = 0), one pixel per clock, checks every pixel
// against the golden model and against the Horner unit's golden result at the same t (documented
// bound 0..2 LSB of Q16.16), measures the error against the exact intensity; writes a CSV.
// Returns mismatches + out-of-bound pixels + unexpected SystemC reports.
//
//   interp_fd_tb                        VCD traces/interp_fd.vcd, view traces/interp_fd.gtkw
//   interp_fd_tb --m 6 --csv out/interp_fd.csv
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>

#include "common/report_log.h"
#include "common/sim_guard.h"
#include "interp/interp_line.h"
#include "interp/interp_tb.h"
#include "core/trace.h"

using namespace shading;
using namespace shading::tb;

namespace {

struct options {
    std::string vcd_path = "traces/interp_fd", csv_path, summary_path;
    bool no_vcd = false;
    unsigned width = 200, m = 5;
};

template <unsigned M>
int run(const options& o) {
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
    std::unique_ptr<vcd_file> vcd;
    if (!o.no_vcd) {
        vcd = std::make_unique<vcd_file>(o.vcd_path);
        vcd->trace(bench);
    }
    const bool finished = run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_SEC));
    vcd.reset();

    std::ofstream csv;
    if (!o.csv_path.empty()) {
        csv.open(o.csv_path);
        csv << "unit,variant,pixel,t,exact,value,error\n";
    }
    const auto& s = bench.checker.samples();
    const bool in_bound = bench.checker.min_vs_horner() >= 0 && bench.checker.max_vs_horner() <= 2;
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
        append_summary(o.summary_path, "interp_fd", variant_name(v) + "_m" + std::to_string(M), n, bad, max_err, false, cpp,
                       in_bound ? "max |I_hw - exact|; FD-Horner within [0,2] LSB" : "FD-Horner OUT OF BOUND");
    }
    const std::size_t errors = bench.checker.mismatches() + report_log::get().unexpected() + (finished ? 0 : 1) +
                               (in_bound ? 0 : 1);
    if (!finished) std::cerr << "interp_fd: the simulation did not finish\n";
    return static_cast<int>(errors);
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    CLI::App app{"Forward-difference evaluator: one raster line, every variant, against the golden models"};
    options o;
    o.summary_path = std::getenv("SHADING_SUMMARY") ? std::getenv("SHADING_SUMMARY") : "";
    app.add_option("--vcd", o.vcd_path, "VCD path without the .vcd extension");
    app.add_flag("--no-vcd", o.no_vcd, "do not write a VCD");
    app.add_option("--csv", o.csv_path, "per-pixel CSV: unit,variant,pixel,t,exact,value,error");
    app.add_option("--width", o.width, "pixels of the raster line")->check(CLI::Range(1u, 100000u));
    app.add_option("--m", o.m, "interval of 2^m pixels")->check(CLI::Range(interp::m_min, interp::m_max));
    app.add_option("--summary", o.summary_path, "append TSV summary rows here (default: $SHADING_SUMMARY)");
    CLI11_PARSE(app, argc, argv);
    report_log::install();
    switch (o.m) {
        case 2: return run<2>(o);
        case 3: return run<3>(o);
        case 4: return run<4>(o);
        case 5: return run<5>(o);
        default: return run<6>(o);
    }
}
