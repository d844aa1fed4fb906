// Raster-line interpolator testbench program (modules/interp_line_unit.h, seed 004): streams the
// 200-pixel raster line's samples I1..I4 interval by interval into the joined coefficient unit and
// forward-difference evaluator, checks every pixel and `last` against the golden chain
// (golden_cubic_coefs + golden_fd), measures max |I - exact| against the line's exact intensity and
// the clocks from the first samples to the last pixel. Appends one summary row to $SHADING_SUMMARY.
// Returns mismatches + unexpected SystemC reports (+1 if the simulation did not finish).
//
//   interp_line_tb                           VCD traces/interp_line.vcd, view traces/interp_line.gtkw
//   interp_line_tb --case 2 --div3 exact --m 4 --no-vcd
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>

#include "common/report_log.h"
#include "common/sim_guard.h"
#include "interp/interp_line.h"
#include "interp/interp_line_bench.h"
#include "core/trace.h"

using namespace shading;
using namespace shading::tb;

namespace {

struct options {
    std::string vcd_path = "traces/interp_line", summary_path;
    bool no_vcd = false;
    unsigned width = 200, m = 5, sample_case = 1;
    interp::div3_mode div3 = interp::div3_mode::shift_add;
};

template <unsigned M, interp::sample_set SET, interp::div3_mode DIV>
int run(const options& o) {
    const auto line = make_line(o.width, M);
    line_bench<M, SET, DIV> bench("tb", line_intervals(line, SET));
    std::unique_ptr<vcd_file> vcd;
    if (!o.no_vcd) {
        vcd = std::make_unique<vcd_file>(o.vcd_path);
        vcd->trace(bench);
    }
    const bool finished = run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_SEC));
    vcd.reset();

    const auto& s = bench.checker.samples();
    double max_err = 0.0;
    for (std::size_t p = 0; p < s.size() && p < line.exact.size(); ++p)
        max_err = std::max(max_err, std::abs(to_real(s[p].out, interp::coef_fmt) - line.exact[p]));
    const auto golden = interp::golden_interp_line(line_intervals(line, SET), M, SET, DIV);
    const bool whole_line = bench.checker.pixels() == golden;
    const double clocks = bench.clocks_first_samples_to_last_pixel();
    const std::string name = std::string(SET == interp::sample_set::case1 ? "cubic1" : "cubic2") +
                             (DIV == interp::div3_mode::shift_add ? "_shiftadd" : "_exactdiv") + "_m" +
                             std::to_string(M);
    std::cout << "interp_line (" << name << "): " << line.intervals.size() << " intervals of " << line.n()
              << " pixels (last " << line.intervals.back().len << "), " << s.size() << " pixels, mismatches "
              << bench.checker.mismatches() << (whole_line ? "" : ", LINE DIFFERS FROM THE GOLDEN CHAIN")
              << "\n  max |I - exact| = " << max_err << " levels; " << clocks
              << " clocks from the first samples to the last pixel (" << bench.clocks_per_pixel()
              << " clocks per pixel; 2 clocks to the first pixel, then 1 per pixel); clock-phase violations "
              << bench.dut.phase_violations() << '\n';
    append_summary(o.summary_path, "interp_line", name, s.size(), bench.checker.mismatches(), max_err, false,
                   bench.clocks_per_pixel(), "coef unit + forward differences; max |I_hw - exact|");
    const std::size_t errors = bench.checker.mismatches() + report_log::get().unexpected() + (finished ? 0 : 1) +
                               (whole_line ? 0 : 1);
    if (!finished) std::cerr << "interp_line: the simulation did not finish\n";
    return static_cast<int>(errors);
}

template <unsigned M>
int run_m(const options& o) {
    using interp::div3_mode;
    using interp::sample_set;
    const bool sa = o.div3 == div3_mode::shift_add;
    if (o.sample_case == 1)
        return sa ? run<M, sample_set::case1, div3_mode::shift_add>(o) : run<M, sample_set::case1, div3_mode::exact>(o);
    return sa ? run<M, sample_set::case2, div3_mode::shift_add>(o) : run<M, sample_set::case2, div3_mode::exact>(o);
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    CLI::App app{"Raster-line interpolator (coefficient unit + forward differences) against the golden chain"};
    options o;
    o.summary_path = std::getenv("SHADING_SUMMARY") ? std::getenv("SHADING_SUMMARY") : "";
    const std::map<std::string, interp::div3_mode> div3_names{{"shift-add", interp::div3_mode::shift_add},
                                                              {"exact", interp::div3_mode::exact}};
    app.add_option("--vcd", o.vcd_path, "VCD path without the .vcd extension");
    app.add_flag("--no-vcd", o.no_vcd, "do not write a VCD");
    app.add_option("--width", o.width, "pixels of the raster line")->check(CLI::Range(1u, 100000u));
    app.add_option("--m", o.m, "interval of 2^m pixels")->check(CLI::Range(interp::m_min, interp::m_max));
    app.add_option("--case", o.sample_case, "sample set: 1 (t = 0, 1/4, 1/2, 1) or 2 (t = 0, 1/2, 3/4, 1)")
        ->check(CLI::Range(1u, 2u));
    app.add_option("--div3", o.div3, "division by 3: shift-add (seed 004 Fig. 2) or exact")
        ->transform(CLI::CheckedTransformer(div3_names, CLI::ignore_case));
    app.add_option("--summary", o.summary_path, "append a TSV summary row here (default: $SHADING_SUMMARY)");
    CLI11_PARSE(app, argc, argv);
    report_log::install();
    switch (o.m) {
        case 2: return run_m<2>(o);
        case 3: return run_m<3>(o);
        case 4: return run_m<4>(o);
        case 5: return run_m<5>(o);
        default: return run_m<6>(o);
    }
}
