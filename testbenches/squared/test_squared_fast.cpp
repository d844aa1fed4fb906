// The squared-quadratic device's fast pin-level model (squared/squared_fast.h) beside its block
// model: both on the same input pins and clock, each with its own outputs, monitor and checker.
// Every change of outputs 25-27 and 29 is recorded with its instant: the two waveforms must be
// identical (the block model's multipliers change once per latch, so there is nothing the fast
// model may skip), every validated sample must equal the golden model, the reports must come in
// the same numbers, and the fast model's paths must be the block model's derived ones.
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "core/report_ids.h"
#include "arith/squared_arith.h"
#include "testbenches/specular/specular_tb.h"
#include "testbenches/squared/squared_phase_sweep.h"
#include "squared/squared.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_squared_fast {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_MS;
using sc_core::SC_NS;
using sc_core::SC_PS;
using sc_core::sc_time;

namespace {

specular_checker::golden_fn golden(overflow_mode mode) {
    return [mode](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        datapath_nets r{};
        r.out = golden_squared(n, c, k, mode).out;
        return r;
    };
}

// Every change of a model's outputs: (instant, R, G, B, 29).
using change = std::tuple<sc_time, uint64_t, uint64_t, uint64_t, bool>;

class pin_recorder : public sc_core::sc_module {
public:
    sc_core::sc_in<out_t> r{"r"}, g{"g"}, b{"b"};
    sc_core::sc_in<bool> v{"v"};
    std::vector<change> log;

    SC_HAS_PROCESS(pin_recorder);
    explicit pin_recorder(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_change);
        sensitive << r << g << b << v;
        dont_initialize();
    }

private:
    void on_change() {
        change c{sc_core::sc_time_stamp(), r.read().to_uint64(), g.read().to_uint64(), b.read().to_uint64(), v.read()};
        if (!log.empty() && std::get<0>(log.back()) == std::get<0>(c)) log.back() = c;  // one entry per instant
        else log.push_back(c);
    }
};

class dual_bench : public sc_core::sc_module, public fig1_inputs {
public:
    sc_core::sc_clock clk;
    sc_core::sc_signal<out_t> blk25{"blk25"}, blk26{"blk26"}, blk27{"blk27"};
    sc_core::sc_signal<out_t> fst25{"fst25"}, fst26{"fst26"}, fst27{"fst27"};
    sc_core::sc_signal<bool> blk29{"blk29"}, fst29{"fst29"};

    specular_checker blk_checker, fst_checker;
    squared_model<abstraction::block> blk;
    squared_model<abstraction::fast> fst;
    specular_stimulus stim;
    specular_monitor blk_mon, fst_mon;
    pin_recorder blk_rec, fst_rec;

    dual_bench(const sc_core::sc_module_name& name, item_source<surface> s, strobe_timing t, overflow_mode mode,
               const block_delays& d = {})
        : sc_module(name),
          clk("clk", t.clk_period, t.clk_duty),
          blk_checker(golden(mode)), fst_checker(golden(mode)),
          blk("blk", mode, d), fst("fst", mode, d),
          stim("stim", std::move(s), t),
          blk_mon("blk_mon", [this](const pixel_sample& p) { blk_checker.check(p); }),
          fst_mon("fst_mon", [this](const pixel_sample& p) { fst_checker.check(p); }),
          blk_rec("blk_rec"), fst_rec("fst_rec") {
        blk.clk(clk);
        fst.clk(clk);
        for (auto* m : {&blk_mon, &fst_mon}) bind_fig1_inputs(*m, *this);
        bind_fig1_inputs(stim, *this);
        bind_fig1_inputs(blk, *this);
        bind_fig1_inputs(fst, *this);
        blk.out25_r(blk25); blk.out26_g(blk26); blk.out27_b(blk27); blk.out29_valid(blk29);
        fst.out25_r(fst25); fst.out26_g(fst26); fst.out27_b(fst27); fst.out29_valid(fst29);
        blk_mon.out25_r(blk25); blk_mon.out26_g(blk26); blk_mon.out27_b(blk27); blk_mon.out29_valid(blk29);
        fst_mon.out25_r(fst25); fst_mon.out26_g(fst26); fst_mon.out27_b(fst27); fst_mon.out29_valid(fst29);
        blk_rec.r(blk25); blk_rec.g(blk26); blk_rec.b(blk27); blk_rec.v(blk29);
        fst_rec.r(fst25); fst_rec.g(fst26); fst_rec.b(fst27); fst_rec.v(fst29);
    }

    bool finished() const { return stim.finished(); }
};

// Both models against golden, and against each other, pin change by pin change (`pixels`: the
// samples each must have validated, or any number when 0).
void expect_same_pins(const dual_bench& b, std::size_t pixels) {
    if (pixels != 0) {
        EXPECT_EQ(b.blk_checker.samples(), pixels);
    }
    EXPECT_GT(b.blk_checker.samples(), 0u);
    EXPECT_EQ(b.fst_checker.samples(), b.blk_checker.samples());
    EXPECT_EQ(b.blk_checker.mismatches(), 0u);
    EXPECT_EQ(b.fst_checker.mismatches(), 0u);
    ASSERT_EQ(b.blk_rec.log.size(), b.fst_rec.log.size()) << "the outputs changed a different number of times";
    std::size_t differ = 0;
    for (std::size_t i = 0; i < b.blk_rec.log.size(); ++i)
        if (b.blk_rec.log[i] != b.fst_rec.log[i] && ++differ <= 5)
            ADD_FAILURE() << "change " << i << ": block at " << std::get<0>(b.blk_rec.log[i]) << " (" << std::get<1>(b.blk_rec.log[i])
                          << ", 29 = " << std::get<4>(b.blk_rec.log[i]) << "), fast at " << std::get<0>(b.fst_rec.log[i])
                          << " (" << std::get<1>(b.fst_rec.log[i]) << ", 29 = " << std::get<4>(b.fst_rec.log[i]) << ")";
    EXPECT_EQ(differ, 0u);
}

}  // namespace

class SquaredFastRandom : public ::testing::TestWithParam<overflow_mode> {};

TEST_P(SquaredFastRandom, SamePinWaveformAsTheBlockModelAndGolden) {
    // The bench programs' random stream: random n, k_s*I reloads and cos, 3000 pixels.
    dual_bench b("tb", random_surfaces(3000, 17), squared_timing(), GetParam());
    ASSERT_TRUE(run_to_completion(b, sc_time(10, SC_MS)));
    expect_same_pins(b, 3000);
    EXPECT_GT(b.blk_rec.log.size(), 3000u * 2) << "every pixel changes the outputs and output 29";
}

INSTANTIATE_TEST_SUITE_P(Mode, SquaredFastRandom, ::testing::Values(overflow_mode::saturate, overflow_mode::wrap),
                         [](const ::testing::TestParamInfo<overflow_mode>& i) {
                             return i.param == overflow_mode::saturate ? std::string("Saturate") : std::string("Wrap");
                         });

TEST(SquaredFast, EveryCosCodeAtTheLargestSquaringCount) {
    std::vector<uint32_t> all;
    for (uint32_t c = 0; c <= spec::cos_one; ++c) all.push_back(c);
    std::vector<surface> s{{1000, {255, 170, 3}, all}};
    dual_bench b("tb", s, squared_timing(), overflow_mode::saturate);
    ASSERT_TRUE(run_to_completion(b, sc_time(100, SC_MS)));
    expect_same_pins(b, all.size());
}

TEST(SquaredFast, BadInputsGiveTheSameReportsAndPins) {
    // n = 0 and 1001..1023, cos above 1.0 in wrap mode, and a strobe period of 5 clocks, short for
    // k >= 2 (k + 4 rising edges from the strobe to done): strobes before the result is valid,
    // dropped by both models alike. Each surface's last result comes before the next surface's
    // loads (k = 0: 4 edges, at most 80 ns, the loads from 90 ns after the strobe) or is dropped by
    // its first strobe (k >= 4: more than 140 ns, that strobe at 132 ns).
    report_log::get().expect(msg::input);
    report_log::get().expect(msg::timing);
    std::vector<surface> s;
    for (unsigned n : {0u, 1u, 16u, 100u, 1001u, 1023u}) s.push_back({n, {255, 1, 128}, {0x0000, 0x7000, 0x8000, 0x9000, 0xFFFF}});
    strobe_timing t = squared_timing();
    t.t_low = 4 * t.clk_period;
    dual_bench b("tb", s, t, overflow_mode::wrap);
    ASSERT_TRUE(run_to_completion(b, sc_time(1, SC_MS)));
    EXPECT_EQ(b.blk.chk_in16_n.violations(), 3u);
    EXPECT_EQ(b.fst.n_violations(), 3u);
    EXPECT_EQ(b.blk.chk_in18_cos.violations(), 12u);
    EXPECT_EQ(b.fst.cos_violations(), 12u);
    EXPECT_GT(b.blk.stage().ctl_sq.dropped(), 0u);
    EXPECT_EQ(b.fst.dropped(), b.blk.stage().ctl_sq.dropped());
    expect_same_pins(b, 0);
}

class SquaredFastTiming : public ::testing::TestWithParam<int> {};

TEST_P(SquaredFastTiming, ViolationsAreReportedInTheSameNumbers) {
    // A 6.4 ns clock has a low phase (3.2 ns) not longer than RG_SQ -> MUL12 (reported each
    // period), but every value still settles before output 29 rises (the gate's 0.1 ns after the
    // rising edge): both models' output waveforms are compared change by change, as the reports.
    // A 3 ns clock also breaks RG2's path into the load (the load latches 2.5 clocks after the
    // strobe at the soonest, 7.5 ns < 8.5 ns, whenever the strobe falls within 1 ns before a rising
    // edge: the strobes drift against the clock) and the squaring loop (3.5 ns): the block model
    // then latches what its network really shows (mismatches against golden, reported), the fast
    // model settled words (squared_fast.h: not modelled), so there only the reports are compared.
    report_log::get().expect(msg::timing);
    const bool settles = GetParam() > 6000;
    if (!settles) {
        report_log::get().expect(msg::mismatch);
        report_log::get().expect(msg::setup);  // RG_SQ's input may change at its very latching instant
    }
    const sc_time period(GetParam(), SC_PS);
    strobe_timing t = squared_timing(period);
    t.t_high = sc_time(7300, SC_PS);
    std::vector<surface> s{{20, {255, 255, 255}, std::vector<uint32_t>(40, 0x7400)}};
    dual_bench b("tb", s, t, overflow_mode::saturate);
    ASSERT_TRUE(run_to_completion(b, sc_time(1, SC_MS)));
    EXPECT_GT(b.blk.chk_clk.violations(), 0u);
    EXPECT_EQ(b.fst.clock_violations(), b.blk.chk_clk.violations());
    EXPECT_EQ(b.fst.load_violations(), b.blk.chk_load.violations());
    EXPECT_EQ(b.fst.timing_violations(), b.blk.chk_timing.violations());
    if (settles) {
        EXPECT_EQ(b.blk.chk_load.violations(), 0u) << "2.5 clocks of 6.4 ns exceed RG2's 8.5 ns";
        expect_same_pins(b, 40);
    } else {
        EXPECT_GT(b.blk.chk_load.violations(), 0u);
    }
}

INSTANTIATE_TEST_SUITE_P(ClockPs, SquaredFastTiming, ::testing::Values(6400, 3000));

// Strobe 17 at every phase of the clock, in 0.5 ns steps over a whole period and its edges
// (phase_sweep_timing: a pixel period of 28 clocks + 0.5 ns, strobe 17 low 5.5 ns), n = 1, 3, 20,
// 1000, each pixel its own cos: both models validate every pixel exactly once, with its golden
// colour, at the (k + 4)-th rising edge after its strobe plus the AND gate's 0.1 ns, and their
// waveforms are identical. The hand count: the first rising edge after the fall clocks the request
// into sync17's first flip-flop, the second into its second, the third takes it, k squares, done.
class SquaredFastPhase : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(SquaredFastPhase, EveryStrobePhaseValidatesEachPixelOnce) {
    const sc_time period(GetParam().first, SC_PS), step(500, SC_PS);
    const strobe_timing t = phase_sweep_timing(28, step, period, GetParam().second / 100.0);
    const std::vector<unsigned> n{1, 3, 20, 1000};
    const auto s = phase_sweep_surfaces(n, static_cast<std::size_t>(period / step) + 1);
    const auto ns = pixel_ns(s);
    dual_bench b("tb", s, t, overflow_mode::saturate);
    latency_probe blk_probe("blk_probe"), fst_probe("fst_probe");
    blk_probe.ctl17(b.ctl17); blk_probe.out29_valid(b.blk29);
    fst_probe.ctl17(b.ctl17); fst_probe.out29_valid(b.fst29);
    ASSERT_TRUE(run_to_completion(b, sc_time(10, SC_MS)));
    expect_same_pins(b, ns.size());
    const auto edges = [](unsigned m) { return 3 + golden_squared_a(m).k + 1; };
    const sc_time gate(100, SC_PS);
    EXPECT_EQ(phases_missed(blk_probe.falls, period, step), 0u) << "every 0.5 ns of the period, its edges included";
    EXPECT_EQ(phase_sweep_wrong(blk_probe, ns, period, gate, edges), 0u) << "block model";
    EXPECT_EQ(phase_sweep_wrong(fst_probe, ns, period, gate, edges), 0u) << "fast model";
    EXPECT_EQ(b.blk.stage().ctl_sq.dropped(), 0u);
    EXPECT_EQ(b.fst.dropped(), 0u);
    EXPECT_EQ(b.blk.chk_clk.violations() + b.blk.chk_load.violations() + b.blk.chk_timing.violations(), 0u);
}

INSTANTIATE_TEST_SUITE_P(ClockPsDuty, SquaredFastPhase,
                         ::testing::Values(std::pair<int, int>{20000, 50}, std::pair<int, int>{20000, 25},
                                           std::pair<int, int>{20000, 75}, std::pair<int, int>{7000, 50}),
                         [](const ::testing::TestParamInfo<std::pair<int, int>>& i) {
                             return "P" + std::to_string(i.param.first) + "ps_duty" + std::to_string(i.param.second);
                         });

TEST(SquaredFast, PathsAreTheBlockModelsDerivedOnes) {
    block_delays d;
    d.multiplier = sc_time(2500, SC_PS);
    d.mux = sc_time(400, SC_PS);
    d.adder = sc_time(1100, SC_PS);
    std::vector<surface> s{{20, {255, 255, 255}, {0x7000}}};
    dual_bench b("tb", s, squared_timing(), overflow_mode::saturate, d);
    sc_core::sc_start(sc_core::SC_ZERO_TIME);
    EXPECT_EQ(b.fst.rg1_to_load(), b.blk.rg1_to_load().delay) << b.blk.rg1_to_load().to_string();
    EXPECT_EQ(b.fst.rg2_to_load(), b.blk.rg2_to_load().delay) << b.blk.rg2_to_load().to_string();
    EXPECT_EQ(b.fst.min_high(), b.blk.min_high());
    EXPECT_EQ(b.fst.min_low(), b.blk.min_low());
    EXPECT_EQ(b.fst.colour_path(), b.blk.chk_timing.path(0));
}

}  // namespace test_squared_fast
