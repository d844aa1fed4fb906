// Horner-unit testbench program: evaluates one raster line, interval by interval and pixel by
// pixel, with the coefficients of every variant (case 1 / case 2 cubic with shift-and-add or
// exact /3, quadratic), back to back through the iterative Horner unit of seed 004, Fig. 4.
// Checks every micro-step against the golden model, measures clocks per pixel and the error
// against the exact intensity; writes a per-pixel CSV. Returns mismatches + unexpected reports.
//
//   interp_horner_tb                    VCD traces/interp_horner.vcd, view traces/interp_horner.gtkw
//   interp_horner_tb --csv out/interp_horner.csv
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

int sc_main(int argc, char* argv[]) {
    CLI::App app{"Seed 004 iterative Horner unit: one raster line, every variant, against the golden model"};
    std::string vcd_path = "traces/interp_horner", csv_path;
    std::string summary_path = std::getenv("SHADING_SUMMARY") ? std::getenv("SHADING_SUMMARY") : "";
    bool no_vcd = false;
    unsigned width = 200, m = 5;
    app.add_option("--vcd", vcd_path, "VCD path without the .vcd extension");
    app.add_flag("--no-vcd", no_vcd, "do not write a VCD");
    app.add_option("--csv", csv_path, "per-pixel CSV: unit,variant,pixel,t,exact,value,error");
    app.add_option("--width", width, "pixels of the raster line")->check(CLI::Range(1u, 100000u));
    app.add_option("--m", m, "interval of 2^m pixels, t = k/2^m")->check(CLI::Range(interp::m_min, 8u));
    app.add_option("--summary", summary_path, "append TSV summary rows here (default: $SHADING_SUMMARY)");
    CLI11_PARSE(app, argc, argv);
    report_log::install();

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

    horner_bench bench("tb", reqs);
    std::unique_ptr<vcd_file> vcd;
    if (!no_vcd) {
        vcd = std::make_unique<vcd_file>(vcd_path);
        vcd->trace(bench);
    }
    const bool finished = run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_SEC));
    vcd.reset();

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
        append_summary(summary_path, "interp_horner", variant_name(v), n, bad, max_err, false, cpp,
                       "max |I_hw - exact intensity| (0..255); back-to-back");
    }
    const std::size_t errors = bench.checker.mismatches() + report_log::get().unexpected() + (finished ? 0 : 1) +
                               (s.size() == reqs.size() ? 0 : 1);
    if (!finished) std::cerr << "interp_horner: the simulation did not finish\n";
    return static_cast<int>(errors);
}
