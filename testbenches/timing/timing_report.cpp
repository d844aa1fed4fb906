// Prints the timing paths derived from the elaborated specular devices (core/timing_graph.h):
// for each device, each strobe's checked path (the longest path from the registers it latches to
// the outputs) with the blocks on it, at the default delays of core/comb_delay.h and blocks/rom.h.
// Then the shading pipeline (square-and-multiply device, Horner and forward-difference evaluators)
// and the cell unit: each clocked unit's and the whole top's shortest high phase, low phase and
// period (their phase_checkers', derived from the elaborated structure; the top's hold the paths
// between units), the shortest clock they allow, and the benches' clock (pipeline_bench.h,
// cell_unit_bench.h) against it.
//   build/bin/timing_report
// Run by ctest (timing.report), so it keeps building and elaborating.
#include <algorithm>
#include <cstdio>
#include <systemc>

#include "core/timing_graph.h"
#include "pipeline_phases.h"
#include "testbenches/pipeline/cell_unit_bench.h"
#include "testbenches/pipeline/pipeline_bench.h"
#include "tuned/ua60553_tuned.h"
#include "ua22802/ua22802.h"
#include "ua60553/ua60553.h"

namespace {

// A device with every pin on a net of its own (the paths need the bindings complete).
template <typename Device>
struct bound : sc_core::sc_module {
    sc_core::sc_signal<bool> ctl[5], valid;
    sc_core::sc_signal<sc_dt::sc_uint<shading::ua60553::n_fmt.width>> n;
    sc_core::sc_signal<sc_dt::sc_uint<shading::spec::cos_fmt.width>> cos;
    sc_core::sc_signal<sc_dt::sc_uint<shading::spec::ksi_fmt.width>> ksi[3];
    sc_core::sc_signal<sc_dt::sc_uint<shading::spec::out_fmt.width>> out[3];
    Device dut;
    const char* title;

    bound(const sc_core::sc_module_name& name, const char* t) : sc_module(name), dut("dut"), title(t) {
        dut.ctl15(ctl[0]); dut.ctl17(ctl[1]); dut.ctl20(ctl[2]); dut.ctl22(ctl[3]); dut.ctl24(ctl[4]);
        dut.in16_n(n); dut.in18_cos(cos);
        dut.in19_ksi_r(ksi[0]); dut.in21_ksi_g(ksi[1]); dut.in23_ksi_b(ksi[2]);
        dut.out25_r(out[0]); dut.out26_g(out[1]); dut.out27_b(out[2]); dut.out29_valid(valid);
    }

    void print() const {
        // The timing checker's strobe i is the device's pin strobes[i].
        const char* strobes[] = {"ctl15", "ctl17", "ctl20", "ctl22", "ctl24"};
        std::printf("%s\n", title);
        for (std::size_t i = 0; i < dut.chk_timing.ctl.size(); ++i)
            std::printf("  %s: %s\n", strobes[i], dut.chk_timing.critical_path(i).to_string().c_str());
    }
};

double ns(const sc_core::sc_time& t) { return t.to_seconds() * 1e9; }

// Prints each checker's requirements and the clock they allow; false if the bench's clock `bench`
// at 50 % duty leaves a phase or the period too short.
bool print_pipeline(const sc_core::sc_object& top, const char* title, const sc_core::sc_time& bench) {
    std::vector<shading::timing::unit_phases> units;
    shading::timing::collect(top, units);
    std::printf("%s: required phases per clocked unit and the whole top (high, low, period)\n", title);
    for (const auto& u : units)
        std::printf("  %-40s %6.2f ns %6.2f ns %6.2f ns\n", u.unit.c_str(), ns(u.chk->min_high()),
                    ns(u.chk->min_low_phase()), ns(u.chk->min_period()));
    const auto b = shading::timing::shortest_clock(units);
    const bool ok = bench / 2 > b.high && bench / 2 > b.low_phase && bench > b.period;
    std::printf("  largest high %.2f ns, largest low %.2f ns, largest period %.2f ns\n", ns(b.high), ns(b.low_phase),
                ns(b.period));
    // The paths behind the three largest requirements (the first checker holding each).
    const auto at = [&](auto req, const sc_core::sc_time& t) {
        return std::find_if(units.begin(), units.end(), [&](const auto& u) { return (u.chk->*req)() == t; });
    };
    using pc = shading::phase_checker;
    if (const auto u = at(&pc::min_high, b.high); u != units.end())
        std::printf("    high: %s: %s\n", u->unit.c_str(), u->chk->high_path().to_string().c_str());
    if (const auto u = at(&pc::min_low_phase, b.low_phase); u != units.end())
        std::printf("    low: %s: %s\n", u->unit.c_str(), u->chk->output_path().to_string().c_str());
    if (const auto u = at(&pc::min_period, b.period); u != units.end())
        std::printf("    period: %s: %s\n", u->unit.c_str(), u->chk->loop_path().to_string().c_str());
    std::printf("  shortest period: 50 %% duty %.2f ns (%.1f MHz), best duty %.2f ns (%.1f MHz; high %.0f %%)\n",
                ns(b.half_duty()), 1e3 / ns(b.half_duty()), ns(b.best_duty()), 1e3 / ns(b.best_duty()),
                100 * ns(b.high) / ns(b.best_duty()));
    std::printf("  (a phase must be strictly longer than its requirement)\n");
    std::printf("  bench's clock %.0f ns at 50 %% duty (%.0f MHz): %s\n", ns(bench), 1e3 / ns(bench),
                ok ? "satisfies it" : "TOO SHORT");
    return ok;
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    if (argc > 1) {  // it takes no arguments: any is bad usage (exit 2)
        std::fprintf(stderr, "usage: %s (no arguments)\n", argv[0]);
        return 2;
    }
    bound<shading::device_ua60553> ua60553("ua60553", "UA 60553 (a_gen_linear: MUL6, ADD15)");
    bound<shading::device_ua60553_tuned> tuned("tuned", "UA 60553 tuned (a_gen_tuned: MUL6, ADD15, OR, key block)");
    bound<shading::device_ua22802> ua22802("ua22802", "UA 22802 (a_gen_rom: ROM)");
    using shading::pipeline::evaluator;
    shading::timing::bound_pipeline<shading::sqmul_device, evaluator::horner> horner("pipe_horner", 0);
    shading::timing::bound_pipeline<shading::sqmul_device, evaluator::fd> fd("pipe_fd", 0);
    shading::timing::bound_cell cell("cell");
    sc_core::sc_start(sc_core::SC_ZERO_TIME);  // end of elaboration: the checkers derive their paths
    ua60553.print();
    tuned.print();
    ua22802.print();
    const auto pipe_clock = shading::pipeline::pipeline_period();
    bool ok = print_pipeline(horner, "shading_pipeline<sqmul_device, horner>", pipe_clock);
    ok = print_pipeline(fd, "shading_pipeline<sqmul_device, fd> (fd_m 0: any m per interval)", pipe_clock) && ok;
    ok = print_pipeline(cell, "cell_unit", shading::tb::cell_period()) && ok;
    return ok && sc_core::sc_report_handler::get_count(sc_core::SC_WARNING) +
                             sc_core::sc_report_handler::get_count(sc_core::SC_ERROR) ==
                         0
               ? 0
               : 1;
}
