// Clock-phase requirements of the interpolation paper's units, derived from the elaborated blocks
// (monitors/phase_checker.h: derive(), core/timing_graph.h), against hand sums of the default
// delays (core/comb_delay.h: register clock-to-output 0.2 ns, inverter and key block 0.1 ns,
// adder 1 ns, multiplier and constant divider 3 ns, multiplexer 0.3 ns; a shift-and-add network
// takes max(P tree, Q tree + inverter) + 1 ns for P + ~Q + 1, each tree ceil(log2 terms) adder
// levels; the shift-and-add /3, 1 positive and 3 negative terms, max(0, 2 + 0.1) + 1 = 3.1 ns).
// The hand sums are the independent check; a second set of tests changes one block kind's delay
// and sees the requirement move by exactly the change along the slowest path.
// Each TEST elaborates its own units (one process per test).
#include <gtest/gtest.h>

#include <systemc>

#include "interp/coef_unit_cubic_partial_sum.h"
#include "interp/coef_unit_quad.h"
#include "interp/fd_eval.h"
#include "interp/horner_unit.h"
#include "interp/interp_line_unit.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_interp_timing {

using namespace shading;
using interp::div3_grouping;
using interp::div3_mode;
using interp::sample_set;
using sc_core::SC_PS;
using sc_core::sc_time;

namespace {

using sample_t = sc_dt::sc_uint<interp::sample_fmt.width>;
using coef_t = sc_dt::sc_uint<interp::coef_fmt.width>;
using t_t = sc_dt::sc_uint<interp::t_fmt.width>;

// Pins: a unit with every port bound to a net, so it elaborates (the requirements are derived at
// end_of_elaboration from the port bindings).
template <sample_set SET, div3_mode DIV, div3_grouping G>
struct cubic_pins : sc_core::sc_module {
    sc_core::sc_signal<bool> clk{"clk"};
    sc_core::sc_vector<sc_core::sc_signal<sample_t>> in{"in", 4};
    sc_core::sc_vector<sc_core::sc_signal<coef_t>> out{"out", 4};
    coef_unit_cubic_t<SET, DIV, G> dut;
    cubic_pins(const sc_core::sc_module_name& name, const interp_delays& t = {}) : sc_module(name), dut("dut", t) {
        dut.clk(clk);
        dut.i1(in[0]); dut.i2(in[1]); dut.i3(in[2]); dut.i4(in[3]);
        dut.a(out[0]); dut.b(out[1]); dut.c(out[2]); dut.d(out[3]);
    }
};

struct quad_pins : sc_core::sc_module {
    sc_core::sc_signal<bool> clk{"clk"};
    sc_core::sc_vector<sc_core::sc_signal<sample_t>> in{"in", 3};
    sc_core::sc_vector<sc_core::sc_signal<coef_t>> out{"out", 3};
    coef_unit_quad dut;
    quad_pins(const sc_core::sc_module_name& name, const interp_delays& t = {}) : sc_module(name), dut("dut", t) {
        dut.clk(clk);
        dut.i1(in[0]); dut.i2(in[1]); dut.i3(in[2]);
        dut.a(out[0]); dut.b(out[1]); dut.c(out[2]);
    }
};

struct horner_pins : sc_core::sc_module {
    sc_core::sc_signal<bool> clk{"clk"}, start{"start"}, deg2{"deg2"}, done{"done"}, busy{"busy"};
    sc_core::sc_vector<sc_core::sc_signal<coef_t>> k{"k", 4};
    sc_core::sc_signal<t_t> t{"t"};
    sc_core::sc_signal<coef_t> i_t{"i_t"};
    horner_unit dut;
    horner_pins(const sc_core::sc_module_name& name, const interp_delays& d = {}) : sc_module(name), dut("dut", d) {
        dut.clk(clk); dut.start(start); dut.deg2(deg2);
        dut.a(k[0]); dut.b(k[1]); dut.c(k[2]); dut.d(k[3]);
        dut.t(t); dut.i_t(i_t); dut.done(done); dut.busy(busy);
    }
};

template <unsigned M>
struct fd_pins : sc_core::sc_module {
    sc_core::sc_signal<bool> clk{"clk"}, start{"start"}, valid{"valid"}, last{"last"};
    sc_core::sc_signal<typename fd_eval<M>::len_t> len{"len"};
    sc_core::sc_vector<sc_core::sc_signal<coef_t>> k{"k", 4};
    sc_core::sc_signal<coef_t> i_px{"i_px"};
    fd_eval<M> dut;
    fd_pins(const sc_core::sc_module_name& name, const interp_delays& t = {}) : sc_module(name), dut("dut", t) {
        dut.clk(clk); dut.start(start); dut.len(len);
        dut.a(k[0]); dut.b(k[1]); dut.c(k[2]); dut.d(k[3]);
        dut.i_px(i_px); dut.valid(valid); dut.last(last);
    }
};

template <unsigned M, sample_set SET, div3_mode DIV, div3_grouping G = div3_grouping::whole_sum>
struct line_pins : sc_core::sc_module {
    using unit = interp_line_unit<M, SET, DIV, G>;
    sc_core::sc_signal<bool> clk{"clk"}, start{"start"}, valid{"valid"}, last{"last"}, ready{"ready"};
    sc_core::sc_signal<typename unit::len_t> len{"len"};
    sc_core::sc_vector<sc_core::sc_signal<sample_t>> in{"in", 4};
    sc_core::sc_signal<coef_t> i_px{"i_px"};
    unit dut;
    line_pins(const sc_core::sc_module_name& name, const interp_delays& t = {}) : sc_module(name), dut("dut", t) {
        dut.clk(clk); dut.start(start); dut.len(len);
        dut.i1(in[0]); dut.i2(in[1]); dut.i3(in[2]); dut.i4(in[3]);
        dut.i_px(i_px); dut.valid(valid); dut.last(last); dut.ready(ready);
    }
};

void elaborate() { sc_core::sc_start(sc_core::SC_ZERO_TIME); }

constexpr auto whole = div3_grouping::whole_sum;
constexpr auto partial = div3_grouping::partial_sum;

}  // namespace

// Coefficient units, /3 on the whole weighted sum. The samples go straight into the registers, so
// the high phase needs only their setup time (0). Low: rg_i's 0.2 ns plus the slowest coefficient.
// Case 1: -S_C has 3 positive, 4 negative terms: max(2, 2 + 0.1) + 1 = 3.1 ns, then /3 (8(-S_A):
// 4 and 2 terms, max(2, 1.1) + 1 = 3 ns, and B: 3 and 3, 3.1 ns, are no slower). Case 2: -S_C has
// 6 positive terms (3 adder levels), 2 negative: max(3, 1.1) + 1 = 4 ns. Quadratic: b has 1
// positive, 3 negative terms: 3.1 ns; no division.
TEST(InterpTiming, CoefUnitsWholeSumAreTheHandSums) {
    cubic_pins<sample_set::case1, div3_mode::shift_add, whole> c1sa("c1sa");
    cubic_pins<sample_set::case1, div3_mode::exact, whole> c1ex("c1ex");
    cubic_pins<sample_set::case2, div3_mode::shift_add, whole> c2sa("c2sa");
    cubic_pins<sample_set::case2, div3_mode::exact, whole> c2ex("c2ex");
    quad_pins quad("quad");
    elaborate();
    EXPECT_EQ(c1sa.dut.min_low(), sc_time(6400, SC_PS)) << c1sa.dut.chk_clock.output_path().to_string();  // 0.2 + 3.1 + 3.1
    EXPECT_EQ(c1ex.dut.min_low(), sc_time(6300, SC_PS));  // 0.2 + 3.1 + 3
    EXPECT_EQ(c2sa.dut.min_low(), sc_time(7300, SC_PS));  // 0.2 + 4 + 3.1
    EXPECT_EQ(c2ex.dut.min_low(), sc_time(7200, SC_PS));  // 0.2 + 4 + 3
    EXPECT_EQ(quad.dut.min_low(), sc_time(3300, SC_PS));  // 0.2 + 3.1
    EXPECT_EQ(c2sa.dut.chk_clock.output_path().to_string(), "rg_i1 -> net_c -> div3_c = 7.3 ns");
    for (auto t : {c1sa.dut.min_high(), c1ex.dut.min_high(), c2sa.dut.min_high(), c2ex.dut.min_high(),
                   quad.dut.min_high()})
        EXPECT_EQ(t, sc_core::SC_ZERO_TIME);
}

// The interpolation paper's grouping: per coefficient a network for the divided part -> /3 and one for the
// integer part, then the subtractor (inverter on the subtrahend + adder). Case 1, A: net (2 terms,
// 1 ns) + /3 against net + inverter (1.1 ns), then 1 ns: 1 + 3.1 + 1 = 5.1 ns (C: the same; B 3.1).
// Case 2, C: the 4-term net (2 ns) + /3 + the inverter (the quotient is subtracted) + 1 ns = 6.2 ns.
TEST(InterpTiming, CoefUnitsPartialSumGroupingAreTheHandSums) {
    cubic_pins<sample_set::case1, div3_mode::shift_add, partial> c1sa("c1sa");
    cubic_pins<sample_set::case1, div3_mode::exact, partial> c1ex("c1ex");
    cubic_pins<sample_set::case2, div3_mode::shift_add, partial> c2sa("c2sa");
    cubic_pins<sample_set::case2, div3_mode::exact, partial> c2ex("c2ex");
    elaborate();
    EXPECT_EQ(c1sa.dut.min_low(), sc_time(5300, SC_PS));  // 0.2 + 1 + 3.1 + 1
    EXPECT_EQ(c1ex.dut.min_low(), sc_time(5200, SC_PS));  // 0.2 + 1 + 3 + 1
    EXPECT_EQ(c2sa.dut.min_low(), sc_time(6400, SC_PS));  // 0.2 + 2 + 3.1 + 0.1 + 1
    EXPECT_EQ(c2ex.dut.min_low(), sc_time(6300, SC_PS));  // 0.2 + 2 + 3 + 0.1 + 1
    EXPECT_EQ(c2sa.dut.chk_clock.output_path().to_string(), "rg_i1 -> net_c_div -> div3_c -> inv_c -> sub_c = 6.4 ns");
    for (auto t : {c1sa.dut.min_high(), c1ex.dut.min_high(), c2sa.dut.min_high(), c2ex.dut.min_high()})
        EXPECT_EQ(t, sc_core::SC_ZERO_TIME);
}

// Horner. High: the selects switch at the rising edge and RG latches at the falling one, so
// MX1 -> MUL -> MX2 -> Sm must settle in between: 0.3 + 3 + 0.3 + 1 = 4.6 ns. Low: RG's
// clock-to-output 0.2 ns puts I(t) on i_t before the rising edge that reads it; the loop RG -> ...
// -> RG (0.2 + 4.6 = 4.8 ns) spans both phases and needs no more.
TEST(InterpTiming, HornerIsTheHandSums) {
    horner_pins h("h");
    elaborate();
    EXPECT_EQ(h.dut.min_high(), sc_time(4600, SC_PS)) << h.dut.chk_clock.high_path().to_string();
    EXPECT_EQ(h.dut.min_low(), sc_time(200, SC_PS));
    EXPECT_EQ(h.dut.chk_clock.loop_path().delay, sc_time(4800, SC_PS));
    EXPECT_EQ(h.dut.chk_clock.output_path().to_string(), "rg -> out_wire = 0.2 ns");
}

// Forward differences. High: at the accepting rising edge the controller selects LOAD and A..D may
// just have settled, so the deepest set-up network (D1 and D2: three positive terms, two adder
// levels) and the multiplexer must settle before the falling edge: 1 + 1 + 0.3 = 2.3 ns. Low: RG_P's
// clock-to-output 0.2 ns puts the pixel on i_px (out_align is wiring); the recurrence RG -> ADD ->
// MX -> RG (0.2 + 1 + 0.3 = 1.5 ns) spans both phases and fits in 2.3 + 0.2.
TEST(InterpTiming, ForwardDifferencesAreTheHandSums) {
    fd_pins<5> f5("f5");
    fd_pins<2> f2("f2");
    elaborate();
    for (auto* u : {&f5.dut.chk_clock, &f2.dut.chk_clock}) {
        EXPECT_EQ(u->min_high(), sc_time(2300, SC_PS)) << u->high_path().to_string();
        EXPECT_EQ(u->min_low(), sc_time(200, SC_PS));
        EXPECT_EQ(u->loop_path().delay, sc_time(1500, SC_PS));
    }
}

// The raster-line interpolator: the units keep their own requirements; the path between them,
// rg_i -> network -> /3 -> A..D -> FD set-up -> MX -> FD register, runs from one falling edge to the
// next. Whole sum, case 2, shift-and-add: its slowest coefficient C, 0.2 + 4 + 3.1 (= coef's 7.3) +
// 2 (setup_d1: 3 terms, 2 adder levels) + 0.3 (MX) = 9.6 ns; case 1: net_c 3.1, so 8.7 ns. Partial
// sum, case 2: C 6.4 + 2.3 = 8.7 ns; case 1: A and C 5.3 + 2.3 = 7.6 ns. Covered by the two
// units' phase checks (low + high), so the top adds no checker.
TEST(InterpTiming, LinePathBetweenTheUnitsIsTheHandSumAndCoveredByTheirPhases) {
    line_pins<5, sample_set::case2, div3_mode::shift_add> c2sa("c2sa");
    line_pins<5, sample_set::case1, div3_mode::shift_add> c1sa("c1sa");
    line_pins<5, sample_set::case2, div3_mode::shift_add, partial> c2sa_partial("c2sa_partial");
    line_pins<5, sample_set::case1, div3_mode::shift_add, partial> c1sa_partial("c1sa_partial");
    elaborate();
    EXPECT_EQ(c2sa.dut.sample_to_load().delay, sc_time(9600, SC_PS)) << c2sa.dut.sample_to_load().to_string();
    EXPECT_EQ(c2sa.dut.sample_to_load().to_string(), "coef.rg_i1 -> coef.net_c -> coef.div3_c -> fd.setup_d1 -> fd.mx_d1 = 9.6 ns");
    EXPECT_EQ(c1sa.dut.sample_to_load().delay, sc_time(8700, SC_PS));
    EXPECT_EQ(c2sa_partial.dut.sample_to_load().delay, sc_time(8700, SC_PS));
    EXPECT_EQ(c1sa_partial.dut.sample_to_load().delay, sc_time(7600, SC_PS));
    EXPECT_EQ(c2sa.dut.min_high(), sc_time(2300, SC_PS));
    EXPECT_EQ(c2sa.dut.min_low(), sc_time(7300, SC_PS));
    EXPECT_EQ(c1sa.dut.min_low(), sc_time(6400, SC_PS));
    EXPECT_LE(c2sa.dut.sample_to_load().delay, c2sa.dut.min_low() + c2sa.dut.min_high());
    EXPECT_LE(c1sa.dut.sample_to_load().delay, c1sa.dut.min_low() + c1sa.dut.min_high());
    EXPECT_LE(c2sa_partial.dut.sample_to_load().delay, c2sa_partial.dut.min_low() + c2sa_partial.dut.min_high());
    EXPECT_LE(c1sa_partial.dut.sample_to_load().delay, c1sa_partial.dut.min_low() + c1sa_partial.dut.min_high());
}

// One block kind slower, everything else at its default: each requirement moves by exactly the
// change along its slowest path (and no more where another path becomes the slowest).
TEST(InterpTiming, ASlowerBlockMovesTheRequirements) {
    interp_delays slow_reg;
    slow_reg.reg = sc_time(700, SC_PS);  // +0.5 ns clock-to-output
    interp_delays slow_mul;
    slow_mul.multiplier = sc_time(4000, SC_PS);  // +1 ns
    interp_delays slow_mux;
    slow_mux.mux = sc_time(800, SC_PS);  // +0.5 ns
    interp_delays slow_adder;
    slow_adder.adder = sc_time(2000, SC_PS);  // +1 ns (the blocks the units instantiate themselves)
    interp_delays slower_adder;
    slower_adder.adder = sc_time(3000, SC_PS);  // +2 ns
    interp_delays slow_inv;
    slow_inv.inverter = sc_time(1100, SC_PS);  // +1 ns
    cubic_pins<sample_set::case1, div3_mode::shift_add, whole> coef("coef", slow_reg);
    cubic_pins<sample_set::case1, div3_mode::shift_add, partial> partial_add("partial_add", slow_adder);
    cubic_pins<sample_set::case2, div3_mode::shift_add, partial> partial_inv("partial_inv", slow_inv);
    quad_pins quad("quad", slow_reg);
    horner_pins h_mul("h_mul", slow_mul);
    horner_pins h_reg("h_reg", slow_reg);
    fd_pins<5> f_mux("f_mux", slow_mux);
    fd_pins<5> f_adder("f_adder", slower_adder);
    line_pins<5, sample_set::case2, div3_mode::shift_add> line("line", slow_mux);
    elaborate();
    EXPECT_EQ(coef.dut.min_low(), sc_time(6900, SC_PS));         // 6.4 + 0.5
    EXPECT_EQ(partial_add.dut.min_low(), sc_time(6300, SC_PS));  // 5.3 + 1 (the subtractor)
    EXPECT_EQ(partial_inv.dut.min_low(), sc_time(7400, SC_PS));  // 6.4 + 1 (inv_c on the quotient)
    EXPECT_EQ(quad.dut.min_low(), sc_time(3800, SC_PS));         // 3.3 + 0.5
    EXPECT_EQ(h_mul.dut.min_high(), sc_time(5600, SC_PS));       // 4.6 + 1
    EXPECT_EQ(h_mul.dut.min_low(), sc_time(200, SC_PS));
    EXPECT_EQ(h_reg.dut.min_high(), sc_time(4600, SC_PS));
    EXPECT_EQ(h_reg.dut.min_low(), sc_time(700, SC_PS));         // 0.2 + 0.5
    EXPECT_EQ(f_mux.dut.min_high(), sc_time(2800, SC_PS));       // 2 + 0.8
    // Adders at 3 ns: the recurrence RG -> ADD -> MX -> RG is 0.2 + 3 + 0.3 = 3.5 ns, longer than the
    // high phase's 2.3 ns (the set-up networks keep their 1 ns adders): the low phase makes up 1.2 ns.
    EXPECT_EQ(f_adder.dut.min_high(), sc_time(2300, SC_PS));
    EXPECT_EQ(f_adder.dut.chk_clock.loop_path().delay, sc_time(3500, SC_PS));
    EXPECT_EQ(f_adder.dut.min_low(), sc_time(1200, SC_PS));
    EXPECT_EQ(line.dut.sample_to_load().delay, sc_time(10100, SC_PS));  // 9.6 + 0.5 (fd.mx_d1)
}

}  // namespace test_interp_timing
