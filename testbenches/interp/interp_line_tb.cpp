// Raster-line interpolator testbench program (modules/interp_line_unit.h, the interpolation paper): streams the
// 200-pixel raster line's samples I1..I4 interval by interval into the joined coefficient unit and
// forward-difference evaluator, checks every pixel and `last` against the golden chain
// (golden_cubic_coefs + golden_fd), measures max |I - exact| against the line's exact intensity and
// the clocks from the first samples to the last pixel. Appends one summary row to $SHADING_SUMMARY.
// Options common to every bench: common/common_options.h.
//
//   interp_line_tb                           VCD traces/interp_line.vcd, view traces/interp_line.gtkw
//   interp_line_tb --case 2 --div3 exact --m 4 --no-vcd
//   interp_line_tb --random 1000000 --seed 7  random samples, intervals of 1..2^m pixels back to back
#include <cmath>
#include <iostream>

#include "testbenches/common/bench_runner.h"
#include "testbenches/options/bench_options.h"
#include "testbenches/interp/interp_line.h"
#include "testbenches/interp/interp_line_bench.h"

using namespace shading;
using namespace shading::tb;

namespace {

using options = interp_line_options;

template <unsigned M, interp::sample_set SET, interp::div3_mode DIV>
int run_variant(bench_runner& run, const options& o) {
    const std::string name = std::string(SET == interp::sample_set::case1 ? "cubic1" : "cubic2") +
                             (DIV == interp::div3_mode::shift_add ? "_shiftadd" : "_exactdiv") + "_m" +
                             std::to_string(M);
    if (run.random()) {
        line_bench<M, SET, DIV> bench("tb", random_line_intervals<M>(run.random_count(), run.seed()));
        bench.checker.keep_samples(false);
        bench.checker.inject_mismatch(run.inject(), run.inject_count());
        run.simulate(bench, sc_core::sc_max_time());
        std::cout << "interp_line (" << name << "): clocks per pixel " << bench.checker.cycles_per_result()
                  << ", clock-phase violations " << bench.dut.phase_violations() << '\n';
        run.report_random("random_" + name, bench.checker.checked(), bench.checker.mismatches());
        return run.finish(bench.checker.checked(), bench.checker.mismatches());
    }
    const auto line = make_line(o.width, M);
    line_bench<M, SET, DIV> bench("tb", line_intervals(line, SET));
    bench.checker.inject_mismatch(run.inject(), run.inject_count());
    run.simulate(bench);

    const auto& s = bench.checker.samples();
    double max_err = 0.0;
    for (std::size_t p = 0; p < s.size() && p < line.exact.size(); ++p)
        max_err = std::max(max_err, std::abs(to_real(s[p].out, interp::coef_fmt) - line.exact[p]));
    const auto golden = interp::golden_interp_line(line_intervals(line, SET), M, SET, DIV);
    const bool whole_line = bench.checker.pixels() == golden;
    const double clocks = bench.clocks_first_samples_to_last_pixel();
    std::cout << "interp_line (" << name << "): " << line.intervals.size() << " intervals of " << line.n()
              << " pixels (last " << line.intervals.back().len << "), " << s.size() << " pixels, mismatches "
              << bench.checker.mismatches() << (whole_line ? "" : ", LINE DIFFERS FROM THE GOLDEN CHAIN")
              << "\n  max |I - exact| = " << max_err << " levels; " << clocks
              << " clocks from the first samples to the last pixel (" << bench.clocks_per_pixel()
              << " clocks per pixel; 2 clocks to the first pixel, then 1 per pixel); clock-phase violations "
              << bench.dut.phase_violations() << '\n';
    run.summary({run.bench(), name, s.size(), bench.checker.mismatches(), fmt_levels(max_err),
                 fmt_number(bench.clocks_per_pixel()), "coef unit + forward differences; max |I_hw - exact|"});
    return run.finish(s.size(), bench.checker.mismatches(), whole_line ? 0 : 1);
}

template <unsigned M>
int run_m(bench_runner& run, const options& o) {
    using interp::div3_mode;
    using interp::sample_set;
    const bool sa = o.div3 == div3_mode::shift_add;
    if (o.sample_case == 1)
        return sa ? run_variant<M, sample_set::case1, div3_mode::shift_add>(run, o)
                  : run_variant<M, sample_set::case1, div3_mode::exact>(run, o);
    return sa ? run_variant<M, sample_set::case2, div3_mode::shift_add>(run, o)
              : run_variant<M, sample_set::case2, div3_mode::exact>(run, o);
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    options o;
    if (auto rc = parse_interp_line(argc, argv, o)) return *rc;
    bench_runner run("interp_line", o.bench);
    if (auto rc = run.start(argc, argv)) return *rc;
    switch (o.m) {
        case 2: return run_m<2>(run, o);
        case 3: return run_m<3>(run, o);
        case 4: return run_m<4>(run, o);
        case 5: return run_m<5>(run, o);
        default: return run_m<6>(run, o);
    }
}
