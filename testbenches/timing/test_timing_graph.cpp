// Timing paths derived from the elaborated design (core/timing_graph.h) against hand sums of the
// default delays (core/comb_delay.h: register 0.2 ns, inverter and one gate 0.1 ns, adder 1 ns,
// multiplier 3 ns; blocks/rom.h: ROM 4 ns). Each TEST elaborates its own design (own process).
#include <gtest/gtest.h>

#include <algorithm>

#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "blocks/adder.h"
#include "blocks/constant.h"
#include "blocks/mul.h"
#include "blocks/reg.h"
#include "blocks/wire.h"
#include "testbenches/common/report_log.h"
#include "core/report_ids.h"
#include "core/timing_graph.h"
#include "monitors/timing_checker.h"
#include "pipeline_phases.h"
#include "testbenches/pipeline/pipeline_bench.h"
#include "tuned/ua60553_tuned.h"
#include "ua22802/ua22802.h"
#include "ua60553/ua60553.h"

using namespace shading;
using sc_core::SC_NS;
using sc_core::SC_PS;
using sc_core::sc_time;

namespace {

// A specular device with every pin bound to a net of its own, elaborated by elaborate().
template <typename Device>
struct pins : sc_core::sc_module {
    sc_core::sc_signal<bool> ctl[5], valid;
    sc_core::sc_signal<sc_dt::sc_uint<ua60553::n_fmt.width>> n;
    sc_core::sc_signal<sc_dt::sc_uint<spec::cos_fmt.width>> cos;
    sc_core::sc_signal<sc_dt::sc_uint<spec::ksi_fmt.width>> ksi[3];
    sc_core::sc_signal<sc_dt::sc_uint<spec::out_fmt.width>> out[3];
    Device dut;

    template <typename... Args>
    explicit pins(const sc_core::sc_module_name& name, Args&&... args)
        : sc_module(name), dut("dut", std::forward<Args>(args)...) {
        dut.ctl15(ctl[0]); dut.ctl17(ctl[1]); dut.ctl20(ctl[2]); dut.ctl22(ctl[3]); dut.ctl24(ctl[4]);
        dut.in16_n(n); dut.in18_cos(cos);
        dut.in19_ksi_r(ksi[0]); dut.in21_ksi_g(ksi[1]); dut.in23_ksi_b(ksi[2]);
        dut.out25_r(out[0]); dut.out26_g(out[1]); dut.out27_b(out[2]); dut.out29_valid(valid);
    }
};

void elaborate() { sc_core::sc_start(sc_core::SC_ZERO_TIME); }

std::string blocks(const timing_path& p) {
    std::string s;
    for (const auto& b : p.blocks) s += (s.empty() ? "" : " ") + b;
    return s;
}

// Every register of a specular device has a path to the outputs, and its strobe's checked path
// is that path (strobe i latches RG(i+1)).
template <typename Device>
void every_register_has_its_path(const Device& dut) {
    const timing_graph g(dut);
    const auto regs = g.registers();
    ASSERT_EQ(regs.size(), 5u) << g.describe();
    const sc_core::sc_object* by_strobe[] = {&dut.rg1, &dut.rg2, &dut.rg3, &dut.rg4, &dut.rg5};
    for (std::size_t i = 0; i < 5; ++i) {
        const auto p = g.to_outputs(*by_strobe[i]);
        EXPECT_TRUE(p.found) << by_strobe[i]->name();
        EXPECT_GT(p.delay, sc_time(200, SC_PS)) << by_strobe[i]->name();
        EXPECT_EQ(dut.chk_timing.path(i), p.delay) << "strobe " << i;
    }
}

}  // namespace

TEST(TimingGraph, UA60553Rg2PathIsTheHandSumOfTheDefaultDelays) {
    pins<device_ua60553> top("tb");
    elaborate();
    const timing_graph g(top.dut);
    const auto p = g.to_outputs(top.dut.rg2);
    // RG2 -> MUL7 -> ADD9 -> MUL10 -> ADD11 -> MUL12: 0.2 + 3 + 1 + 3 + 1 + 3 = 11.2 ns.
    EXPECT_EQ(p.delay, sc_time(11200, SC_PS)) << p.to_string();
    EXPECT_EQ(blocks(p), "rg2 mul7 add9 mul10 add11 mul12");
    EXPECT_EQ(p.to_string(), "rg2 -> mul7 -> add9 -> mul10 -> add11 -> mul12 = 11.2 ns");
    EXPECT_EQ(top.dut.chk_timing.path(1), p.delay);
    EXPECT_EQ(top.dut.rg2_to_outputs(), p.delay);
    // RG3..RG5 -> MUL12..14: 0.2 + 3.
    EXPECT_EQ(g.to_outputs(top.dut.rg3).to_string(), "rg3 -> mul12 = 3.2 ns");
    EXPECT_EQ(g.to_outputs(top.dut.rg5).to_string(), "rg5 -> mul14 = 3.2 ns");
}

TEST(TimingGraph, UA60553Rg1PathThroughThePatentGenerator) {
    pins<device_ua60553> top("tb");
    elaborate();
    const timing_graph g(top.dut);
    const auto p = g.to_outputs(top.dut.rg1);
    // RG1 -> MUL6 -> ADD15 -> MUL10 -> ADD11 -> MUL12: 0.2 + 3 + 1 + 3 + 1 + 3 = 11.2 ns.
    EXPECT_EQ(p.delay, sc_time(11200, SC_PS)) << p.to_string();
    EXPECT_EQ(p.to_string(), "rg1 -> a_gen.mul6 -> a_gen.add15 -> mul10 -> add11 -> mul12 = 11.2 ns");
    EXPECT_EQ(top.dut.chk_timing.path(0), p.delay);
    every_register_has_its_path(top.dut);
}

TEST(TimingGraph, TunedRg1PathIncludesTheKeyBlock) {
    pins<device_ua60553_tuned> top("tb");
    elaborate();
    const timing_graph g(top.dut);
    const auto p = g.to_outputs(top.dut.rg1);
    // RG1 -> MUL6 -> ADD15 -> key block -> MUL10 -> ADD11 -> MUL12: 0.2+3+1+0.1+3+1+3 = 11.3 ns
    // (the OR gate's 0.1 ns branch into the key block is shorter than MUL6 + ADD15).
    EXPECT_EQ(p.delay, sc_time(11300, SC_PS)) << p.to_string();
    EXPECT_EQ(blocks(p), "rg1 a_gen.mul6 a_gen.add15 a_gen.key_a mul10 add11 mul12");
    EXPECT_EQ(top.dut.chk_timing.path(0), p.delay);
    every_register_has_its_path(top.dut);
}

TEST(TimingGraph, RomRg1PathIsTheRomAccess) {
    pins<device_ua22802> top("tb");
    elaborate();
    const timing_graph g(top.dut);
    const auto p = g.to_outputs(top.dut.rg1);
    // RG1 -> ROM -> MUL10 -> ADD11 -> MUL12: 0.2 + 4 + 3 + 1 + 3 = 11.2 ns.
    EXPECT_EQ(p.delay, sc_time(11200, SC_PS)) << p.to_string();
    EXPECT_EQ(blocks(p), "rg1 a_gen.rom mul10 add11 mul12");
    EXPECT_EQ(top.dut.chk_timing.path(0), p.delay);
    every_register_has_its_path(top.dut);
}

TEST(TimingGraph, TunedSlowerGatesMoveTheRg1PathByTheKeyBlocksExcess) {
    // Gates at 0.6 ns: the OR gate's branch (0.6) stays shorter than MUL6 + ADD15 (4), so only
    // the key block's +0.5 ns shows: 11.3 -> 11.8 ns.
    block_delays t;
    t.gate = sc_time(600, SC_PS);
    pins<device_ua60553_tuned> top("tb", overflow_mode::saturate, ua60553::minimax, t);
    elaborate();
    EXPECT_EQ(top.dut.rg1_to_outputs(), sc_time(11800, SC_PS));
    EXPECT_EQ(top.dut.rg2_to_outputs(), sc_time(11200, SC_PS));
}

TEST(TimingGraph, ASlowerInverterBankMovesTheRg2PathByExactlyItsExcess) {
    // INV8 at 3.5 ns outruns MUL7's 3 ns: the path goes through INV8 and grows by 0.5 ns.
    block_delays t;
    t.inverter = sc_time(3500, SC_PS);
    pins<device_ua60553> top("tb", overflow_mode::saturate, ua60553::patent, t);
    elaborate();
    const auto p = timing_graph(top.dut).to_outputs(top.dut.rg2);
    EXPECT_EQ(p.to_string(), "rg2 -> inv8 -> add9 -> mul10 -> add11 -> mul12 = 11.7 ns");
    EXPECT_EQ(top.dut.chk_timing.path(1), sc_time(11700, SC_PS));
}

TEST(TimingGraph, ASlowerRomMovesOnlyTheRg1Path) {
    block_delays t;
    t.rom = sc_time(5, SC_NS);
    pins<device_ua22802> top("tb", overflow_mode::saturate, a_gen_rom::default_config(), t);
    elaborate();
    EXPECT_EQ(top.dut.chk_timing.path(0), sc_time(12200, SC_PS)) << "4 ns -> 5 ns ROM: +1 ns";
    EXPECT_EQ(top.dut.chk_timing.path(1), sc_time(11200, SC_PS));
}

namespace {

// A gate modelled without the timed_block interface: the graph cannot know its delay.
struct untimed_gate : sc_core::sc_module {
    sc_core::sc_in<sc_dt::sc_uint<8>> x{"x"};
    sc_core::sc_out<sc_dt::sc_uint<8>> y{"y"};
    SC_HAS_PROCESS(untimed_gate);
    explicit untimed_gate(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(run);
        sensitive << x;
    }
    void run() { y.write(~x.read()); }
};

enum class insert { nothing, multiplier, untimed_gate };

// Test-only top: RA -> ADD -> [inserted block] -> out, and RA -> ADD -> RB (register to register);
// RB -> MULB -> out2. The timing checker sees RA's and RB's strobe (or only RA's: `forget_rb`).
struct small_top : sc_core::sc_module {
    sc_core::sc_in<bool> clk_a{"clk_a"}, clk_b{"clk_b"};
    sc_core::sc_in<sc_dt::sc_uint<8>> in{"in"};
    sc_core::sc_out<sc_dt::sc_uint<8>> out{"out"}, out2{"out2"};
    sc_core::sc_signal<sc_dt::sc_uint<8>> ra_q{"ra_q"}, sum{"sum"}, rb_q{"rb_q"}, k{"k"};
    sc_core::sc_signal<bool> c0{"c0"};
    reg<8> ra{"ra"}, rb{"rb"};
    constant<sc_dt::sc_uint<8>> kk{"kk", 3};
    constant<bool> zero{"zero", false};
    adder<8, 8, 8> add;
    mul<8, 8, 8> mulb{"mulb", sc_time(1500, SC_PS)};
    std::unique_ptr<wire<sc_dt::sc_uint<8>>> w;
    std::unique_ptr<mul<8, 8, 8>> extra;
    std::unique_ptr<untimed_gate> gate;
    timing_checker chk;

    small_top(const sc_core::sc_module_name& name, insert what, const sc_time& add_delay, bool forget_rb = false)
        : sc_module(name), add("add", overflow_mode::wrap, 0, 255, add_delay), chk("chk", forget_rb ? 1 : 2) {
        ra.ctl(clk_a); ra.d(in); ra.q(ra_q);
        kk.y(k); zero.y(c0);
        add.a(ra_q); add.b(k); add.cin(c0); add.s(sum);
        rb.ctl(clk_b); rb.d(sum); rb.q(rb_q);
        mulb.a(rb_q); mulb.b(k); mulb.p(out2);
        if (what == insert::multiplier) {
            extra = std::make_unique<mul<8, 8, 8>>("extra", sc_time(2500, SC_PS));
            extra->a(sum); extra->b(k); extra->p(out);
        } else if (what == insert::untimed_gate) {
            gate = std::make_unique<untimed_gate>("gate");
            gate->x(sum); gate->y(out);
        } else {
            w = std::make_unique<wire<sc_dt::sc_uint<8>>>("w");
            w->x(sum); w->y(out);
        }
        chk.ctl[0](clk_a);
        if (!forget_rb) chk.ctl[1](clk_b);
        chk.valid(clk_a);
    }
};

struct small_bench : sc_core::sc_module {
    sc_core::sc_signal<bool> clk_a{"clk_a"}, clk_b{"clk_b"};
    sc_core::sc_signal<sc_dt::sc_uint<8>> in{"in"}, out{"out"}, out2{"out2"};
    small_top top;
    small_bench(const sc_core::sc_module_name& name, insert what, const sc_time& add_delay = sc_time(1, SC_NS),
                bool forget_rb = false)
        : sc_module(name), top("top", what, add_delay, forget_rb) {
        top.clk_a(clk_a); top.clk_b(clk_b); top.in(in); top.out(out); top.out2(out2);
    }
};

}  // namespace

TEST(TimingGraph, SmallTopPathsAreTheHandSums) {
    small_bench b("tb", insert::nothing);
    elaborate();
    const timing_graph g(b.top);
    EXPECT_EQ(g.to_outputs(b.top.ra).to_string(), "ra -> add -> w = 1.2 ns");  // 0.2 + 1 + wire 0
    EXPECT_EQ(g.to_outputs(b.top.rb).to_string(), "rb -> mulb = 1.7 ns");      // 0.2 + 1.5
    EXPECT_EQ(g.to_register(b.top.ra, b.top.rb).to_string(), "ra -> add = 1.2 ns");
    EXPECT_FALSE(g.to_register(b.top.rb, b.top.ra).found) << "no path from RB back to RA";
    EXPECT_EQ(b.top.chk.path(0), sc_time(1200, SC_PS));
    EXPECT_EQ(b.top.chk.path(1), sc_time(1700, SC_PS));
    EXPECT_FALSE(g.longest_from_channels(g.inputs(), g.outputs()).found)
        << "the input pin only reaches RA's d, which ends the path";
    EXPECT_EQ(g.longest_from_channels({timing_graph::channel_of(b.top.sum)}, g.outputs()).to_string(),
              "sum -> w = 0 ns");
    EXPECT_EQ(g.longest_from_channels({timing_graph::channel_of(b.top.rb_q)}, g.outputs()).to_string(),
              "rb_q -> mulb = 1.5 ns");
}

TEST(TimingGraph, ChangingOneBlocksDelayMovesThePathByExactlyThat) {
    small_bench b("tb", insert::nothing, sc_time(1750, SC_PS));
    elaborate();
    const timing_graph g(b.top);
    EXPECT_EQ(g.to_outputs(b.top.ra).delay, sc_time(1200 + 750, SC_PS)) << "adder 1 ns -> 1.75 ns";
    EXPECT_EQ(g.to_register(b.top.ra, b.top.rb).delay, sc_time(1200 + 750, SC_PS));
    EXPECT_EQ(g.to_outputs(b.top.rb).delay, sc_time(1700, SC_PS)) << "RB's path has no adder";
}

TEST(TimingGraph, InsertingABlockMovesThePathByExactlyItsDelay) {
    small_bench b("tb", insert::multiplier);
    elaborate();
    const timing_graph g(b.top);
    EXPECT_EQ(g.to_outputs(b.top.ra).to_string(), "ra -> add -> extra = 3.7 ns");  // 1.2 + 2.5
    EXPECT_EQ(b.top.chk.path(0), sc_time(3700, SC_PS));
}

TEST(TimingGraph, ABlockWithoutTheTimedInterfaceOnAPathIsReported) {
    tb::report_log::get().expect(msg::config);
    const unsigned before = tb::report_log::get().count(msg::config);
    small_bench b("tb", insert::untimed_gate);
    elaborate();  // the timing checker derives its paths here: the gate is reported
    EXPECT_GE(tb::report_log::get().count(msg::config), before + 1);
    const unsigned after_checker = tb::report_log::get().count(msg::config);
    const timing_graph g(b.top);
    g.to_outputs(b.top.ra);
    EXPECT_EQ(tb::report_log::get().count(msg::config), after_checker + 1) << "tb.top.gate has no delay";
}

TEST(TimingGraph, ARegisterNoStrobeOfTheCheckerLatchesIsReported) {
    // The checker is given RA's strobe only: RB's path would go unchecked.
    tb::report_log::get().expect(msg::config);
    const unsigned before = tb::report_log::get().count(msg::config);
    small_bench b("tb", insert::nothing, sc_time(1, SC_NS), true);
    elaborate();
    EXPECT_EQ(tb::report_log::get().count(msg::config), before + 1);
}

TEST(TimingGraph, ReadingAPathBeforeElaborationIsReported) {
    tb::report_log::get().expect(msg::config);
    const unsigned before = tb::report_log::get().count(msg::config);
    small_bench b("tb", insert::nothing);
    (void)b.top.chk.path(0);
    EXPECT_EQ(tb::report_log::get().count(msg::config), before + 1);
    elaborate();
}

// The shading pipeline's clock (square-and-multiply device, Horner evaluator): the largest
// requirements of its clocked units and of the whole top against hand sums of the default delays
// (core/comb_delay.h: adder 1 ns, multiplier 3 ns, mux 0.3 ns, register 0.2 ns, inverter bank
// 0.1 ns; setup 0).
TEST(PipelinePhases, HornerPipelineClockIsTheHandSumOfItsSlowestPaths) {
    timing::bound_pipeline<sqmul_device, pipeline::evaluator::horner> top("tb", 0);
    elaborate();
    std::vector<timing::unit_phases> units;
    timing::collect(top, units);
    // 3 channels x (coef_quad, coef_cubic, horner) + the device's stage + the whole top.
    ASSERT_EQ(units.size(), 11u);
    const auto b = timing::shortest_clock(units);
    // Low: coef_cubic's rg_i1 -> net_c -> div3_c (case 1), to its outputs. net_c: C's 3 positive
    // terms, a 2-adder tree (2 ns); its 4 negative ones, a 2-adder tree + inverter bank (2.1 ns);
    // the last adder: 2.1 + 1 = 3.1 ns. div3_c (x/2 - x/8 - x/32 - x/128): 3 negative terms, 2
    // adders + inverter bank, then the last adder: 3.1 ns. 0.2 + 3.1 + 3.1 = 6.4 ns.
    EXPECT_EQ(b.low_phase, sc_time(6400, SC_PS));
    const auto low_at = std::find_if(units.begin(), units.end(), [&](const auto& u) { return u.chk->min_low_phase() == b.low_phase; });
    ASSERT_NE(low_at, units.end());
    EXPECT_EQ(low_at->unit, "tb.dut.smp_r.coef_cubic");
    EXPECT_EQ(low_at->chk->output_path().to_string(), "rg_i1 -> net_c -> div3_c = 6.4 ns");
    // High, a path between units that the Horner unit's own checker starts at its pin a: the pixel
    // controller's degree select -> MX_A -> MX1 -> MUL -> MX2 -> SM: 0.3 + 0.3 + 3 + 0.3 + 1 = 4.9 ns.
    const auto& whole = *units.back().chk;
    EXPECT_EQ(units.back().unit, "tb.dut");
    EXPECT_EQ(b.high, sc_time(4900, SC_PS));
    EXPECT_EQ(whole.min_high(), sc_time(4900, SC_PS)) << whole.high_path().to_string();
    EXPECT_EQ(whole.high_path().blocks.front(), "ctl_pixel");
    // Period: coef_cubic's rg_i1 -> net_a (3 ns: A's terms, two adder levels and the last adder)
    // -> div3_a (3.1) -> MX_A (0.3) -> MX1 (0.3) -> MUL (3) -> MX2 (0.3) -> SM (1) into the Horner
    // accumulator: 0.2 + 3 + 3.1 + 0.3 + 0.3 + 3 + 0.3 + 1 = 11.2 ns, falling edge to falling edge.
    EXPECT_EQ(b.period, sc_time(11200, SC_PS));
    EXPECT_EQ(whole.min_period(), sc_time(11200, SC_PS)) << whole.loop_path().to_string();
    EXPECT_EQ(whole.loop_path().blocks.front(), "smp_r.coef_cubic.rg_i1");
    EXPECT_EQ(whole.loop_path().blocks.back(), "horner_r.horner.sm");
    EXPECT_EQ(b.best_duty(), sc_time(11300, SC_PS));  // 4.9 + 6.4 (> 11.2)
    EXPECT_EQ(b.half_duty(), sc_time(12800, SC_PS));  // 2 x 6.4 (> 11.2)
    // The benches' 20 ns clock at 50 % duty gives each phase 10 ns: longer than both, and the period.
    EXPECT_GT(pipeline::pipeline_period() / 2, b.low_phase);
    EXPECT_GT(pipeline::pipeline_period() / 2, b.high);
    EXPECT_GT(pipeline::pipeline_period(), b.period);
}

// A path between units is checked in simulation too: a high phase of 4.8 ns gives the Horner unit
// its own 4.6 ns, but not the 4.9 ns the pixel controller's select takes through MX_A into it;
// only the top's checker sees it (the low phase, 6.5 ns, is long enough for every unit).
TEST(PipelinePhases, AHighPhaseTooShortForAPathBetweenUnitsIsReportedByTheTop) {
    tb::report_log::get().expect(msg::timing);
    timing::test_clock clk(sc_time(4800, SC_PS), sc_time(6500, SC_PS));
    timing::bound_pipeline<sqmul_device, pipeline::evaluator::horner> top("tb", 0, &clk);
    sc_core::sc_start(sc_time(200, SC_NS));
    EXPECT_GT(top.dut.chk_clock.high_violations(), 10u);
    EXPECT_EQ(top.dut.chk_clock.low_violations(), 0u);
    std::vector<timing::unit_phases> units;
    timing::collect(top, units);
    for (const auto& u : units) {
        if (u.chk != &top.dut.chk_clock) {
            EXPECT_EQ(u.chk->violations(), 0u) << u.unit;
        }
    }
}

// And a period too short for a path between units: 2.7 + 3.4 ns gives every unit of the cell unit
// its phases (2.6, 3.3 ns) but not the 6.2 ns from a column coefficient unit into its evaluator.
TEST(PipelinePhases, APeriodTooShortForAPathBetweenUnitsIsReportedByTheTop) {
    tb::report_log::get().expect(msg::timing);
    timing::test_clock clk(sc_time(2700, SC_PS), sc_time(3400, SC_PS));
    timing::bound_cell top("tb", &clk);
    sc_core::sc_start(sc_time(100, SC_NS));
    EXPECT_EQ(top.dut.chk_clock.high_violations(), 0u);
    EXPECT_GT(top.dut.chk_clock.low_violations(), 10u);  // a short period counts as a low violation
    std::vector<timing::unit_phases> units;
    timing::collect(top, units);
    for (const auto& u : units) {
        if (u.chk != &top.dut.chk_clock) {
            EXPECT_EQ(u.chk->violations(), 0u) << u.unit;
        }
    }
}

// The cell unit's: its units' phases and, between them, the column coefficient unit into the
// column's forward differences over a whole period.
TEST(PipelinePhases, CellUnitClockIsTheHandSumOfItsSlowestPaths) {
    timing::bound_cell top("tb");
    elaborate();
    std::vector<timing::unit_phases> units;
    timing::collect(top, units);
    ASSERT_EQ(units.size(), 3u * 8u + 1u);  // 3 channels x (4 coefficient units, 4 evaluators) + the unit
    const auto b = timing::shortest_clock(units);
    // Low: cq_col_0's rg_i1 -> net_b (3.1) -> align_b (wiring) to its outputs: 0.2 + 3.1 = 3.3 ns.
    EXPECT_EQ(b.low_phase, sc_time(3300, SC_PS));
    // High: the evaluator's pin a -> setup_d1_m2 (2) -> MX_SETUP_D1 (0.3) -> MX_D1 (0.3) = 2.6 ns.
    EXPECT_EQ(b.high, sc_time(2600, SC_PS));
    // Period: rg_i1 -> net_b -> align_b -> the channel's MX_C (0.3) -> setup_d1_m2 -> MX_SETUP_D1 ->
    // MX_D1: 0.2 + 3.1 + 0.3 + 2 + 0.3 + 0.3 = 6.2 ns.
    const auto& whole = *units.back().chk;
    EXPECT_EQ(units.back().unit, "tb.dut");
    EXPECT_EQ(b.period, sc_time(6200, SC_PS));
    EXPECT_EQ(whole.min_period(), sc_time(6200, SC_PS)) << whole.loop_path().to_string();
    EXPECT_EQ(b.best_duty(), sc_time(6200, SC_PS));  // max(2.6 + 3.3, 6.2)
    EXPECT_EQ(b.half_duty(), sc_time(6600, SC_PS));  // 2 x 3.3
}
