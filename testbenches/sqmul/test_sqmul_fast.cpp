// The square-and-multiply device's fast pin-level model (sqmul/sqmul_fast.h) beside its block
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
#include "arith/sqmul_arith.h"
#include "testbenches/specular/specular_tb.h"
#include "testbenches/squared/squared_phase_sweep.h"
#include "sqmul/sqmul.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_sqmul_fast {

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
        r.out = golden_sqmul(n, c, k, mode).out;
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
    sqmul_model<abstraction::block> blk;
    sqmul_model<abstraction::fast> fst;
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

class SqmulFastRandom : public ::testing::TestWithParam<overflow_mode> {};

TEST_P(SqmulFastRandom, SamePinWaveformAsTheBlockModelAndGolden) {
    // The bench programs' random stream: random n, k_s*I reloads and cos, 3000 pixels.
    dual_bench b("tb", random_surfaces(3000, 17), sqmul_timing(), GetParam());
    ASSERT_TRUE(run_to_completion(b, sc_time(10, SC_MS)));
    expect_same_pins(b, 3000);
    EXPECT_GT(b.blk_rec.log.size(), 3000u * 2) << "every pixel changes the outputs and output 29";
}

INSTANTIATE_TEST_SUITE_P(Mode, SqmulFastRandom, ::testing::Values(overflow_mode::saturate, overflow_mode::wrap),
                         [](const ::testing::TestParamInfo<overflow_mode>& i) {
                             return i.param == overflow_mode::saturate ? std::string("Saturate") : std::string("Wrap");
                         });

TEST(SqmulFast, EveryCosCodeAtTheLongestWalk) {
    std::vector<uint32_t> all;
    for (uint32_t c = 0; c <= spec::cos_one; ++c) all.push_back(c);
    std::vector<surface> s{{1023, {255, 170, 3}, all}};  // 9 squares, 9 multiplications
    report_log::get().expect(msg::input);
    dual_bench b("tb", s, sqmul_timing(), overflow_mode::saturate);
    ASSERT_TRUE(run_to_completion(b, sc_time(100, SC_MS)));
    expect_same_pins(b, all.size());
}

TEST(SqmulFast, BadInputsGiveTheSameReportsAndPins) {
    // n = 0 and 1001..1023, cos above 1.0 in wrap mode, and a strobe period of 5 clocks, short for
    // the walks of 20, 100, 1001, 1023 (9 to 22 rising edges from the strobe to done): strobes
    // before the result is valid, dropped by both models alike. A 16 ns clock puts every strobe on a
    // falling edge of clk (the first at 16 + 32 + 8 ns; a pixel 80 ns, a surface's loads 32 ns):
    // RG_P latches before the new cos reaches MUL_P, in both models (a strobe just before a falling
    // edge would leave the block model's product unsettled there). The m-th rising edge after a
    // strobe comes 8 + (m - 1) * 16 ns after it, the next surface's loads 72 ns and its first
    // strobe 112 ns after a surface's last: each surface's last result comes before the loads
    // (n = 0, 1: 4 edges, 56 ns) or is dropped by that strobe (n = 20: 9 edges, 136 ns; longer).
    report_log::get().expect(msg::input);
    report_log::get().expect(msg::timing);
    std::vector<surface> s;
    for (unsigned n : {0u, 1u, 20u, 100u, 1001u, 1023u}) s.push_back({n, {255, 1, 128}, {0x0000, 0x7000, 0x8000, 0x9000, 0xFFFF}});
    strobe_timing t = sqmul_timing(sc_time(16, SC_NS));
    t.t_low = 4 * t.clk_period;  // t_high 1 clock: 5 clocks per pixel
    dual_bench b("tb", s, t, overflow_mode::wrap);
    ASSERT_TRUE(run_to_completion(b, sc_time(1, SC_MS)));
    EXPECT_EQ(b.blk.chk_in16_n.violations(), 3u);
    EXPECT_EQ(b.fst.n_violations(), 3u);
    EXPECT_EQ(b.blk.chk_in18_cos.violations(), 12u);
    EXPECT_EQ(b.fst.cos_violations(), 12u);
    EXPECT_GT(b.blk.stage.ctl.dropped(), 0u);
    EXPECT_EQ(b.fst.dropped(), b.blk.stage.ctl.dropped());
    expect_same_pins(b, 0);
}

class SqmulFastTiming : public ::testing::TestWithParam<int> {};

TEST_P(SqmulFastTiming, ViolationsAreReportedInTheSameNumbers) {
    // A 7.2 ns clock has a high phase (3.6 ns) not longer than the controller's select through
    // MUL_P and MX_P (reported each period); its LOAD latches 2.5 clocks (18 ns) or more after the
    // strobe, so RG2's 4.8 ns path is met. A 1.6 ns clock also breaks that path: the LOAD latches
    // 2.5 clocks (4 ns) after the first rising edge after the strobe, too soon whenever the strobe
    // falls within 0.8 ns before a rising edge (a pixel period of 47 ns drifts the strobes 0.6 ns
    // a pixel against the clock). The block model then samples what its network really shows
    // (mismatches against golden, reported); the fast model takes settled words (sqmul_fast.h: not
    // modelled), so only the reports are compared.
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::mismatch);
    report_log::get().expect(msg::setup);
    const sc_time period(GetParam(), SC_PS);
    strobe_timing t = sqmul_timing(period);
    t.t_high = sc_time(10200, SC_PS);
    std::vector<surface> s{{20, {255, 255, 255}, std::vector<uint32_t>(60, 0x7400)}};
    dual_bench b("tb", s, t, overflow_mode::saturate);
    ASSERT_TRUE(run_to_completion(b, sc_time(1, SC_MS)));
    EXPECT_GT(b.blk.chk_clk.violations(), 0u);
    EXPECT_EQ(b.fst.clock_violations(), b.blk.chk_clk.violations());
    EXPECT_EQ(b.fst.load_violations(), b.blk.chk_load.violations());
    EXPECT_EQ(b.fst.timing_violations(), b.blk.chk_timing.violations());
    if (GetParam() < 1920) {
        EXPECT_GT(b.blk.chk_load.violations(), 0u);
    } else {
        EXPECT_EQ(b.blk.chk_load.violations(), 0u) << "2.5 clocks of 7.2 ns exceed RG2's 4.8 ns";
    }
}

INSTANTIATE_TEST_SUITE_P(ClockPs, SqmulFastTiming, ::testing::Values(7200, 1600));

// Strobe 17 at every phase of the clock, in 0.5 ns steps over a whole period and its edges
// (phase_sweep_timing: a pixel period of 40 clocks + 0.5 ns, strobe 17 low 5.5 ns), n = 1, 3, 20,
// 1000, each pixel its own cos: both models validate every pixel exactly once, with its golden
// colour, at the (floor(log2 n) + popcount(n) + 3)-th rising edge after its strobe plus the AND
// gate's 0.1 ns, and their waveforms are identical. The hand count (from n's bits, not from a
// model): the first rising edge after the fall clocks the request into sync17's first flip-flop,
// the second into its second, the third takes it, floor(log2 n) squares and popcount(n) - 1
// multiplications, done; n = 1000: 2 + 1 + 9 + 5 + 1 = 18 edges, under half the pixel period.
class SqmulFastPhase : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(SqmulFastPhase, EveryStrobePhaseValidatesEachPixelOnce) {
    const sc_time period(GetParam().first, SC_PS), step(500, SC_PS);
    const strobe_timing t = phase_sweep_timing(40, step, period, GetParam().second / 100.0);
    const std::vector<unsigned> n{1, 3, 20, 1000};
    const auto s = phase_sweep_surfaces(n, static_cast<std::size_t>(period / step) + 1);
    const auto ns = pixel_ns(s);
    dual_bench b("tb", s, t, overflow_mode::saturate);
    latency_probe blk_probe("blk_probe"), fst_probe("fst_probe");
    blk_probe.ctl17(b.ctl17); blk_probe.out29_valid(b.blk29);
    fst_probe.ctl17(b.ctl17); fst_probe.out29_valid(b.fst29);
    ASSERT_TRUE(run_to_completion(b, sc_time(10, SC_MS)));
    expect_same_pins(b, ns.size());
    const auto edges = [](unsigned m) {
        unsigned log2 = 0, ones = 0;
        for (unsigned v = m; v > 1; v >>= 1) ++log2;
        for (unsigned v = m; v != 0; v >>= 1) ones += v & 1u;
        return 2 + 1 + log2 + (ones - 1) + 1;
    };
    EXPECT_EQ(edges(1000), 18u);
    const sc_time gate(100, SC_PS);
    EXPECT_EQ(phases_missed(blk_probe.falls, period, step), 0u) << "every 0.5 ns of the period, its edges included";
    EXPECT_EQ(phase_sweep_wrong(blk_probe, ns, period, gate, edges), 0u) << "block model";
    EXPECT_EQ(phase_sweep_wrong(fst_probe, ns, period, gate, edges), 0u) << "fast model";
    EXPECT_EQ(b.blk.stage.ctl.dropped(), 0u);
    EXPECT_EQ(b.fst.dropped(), 0u);
    EXPECT_EQ(b.blk.chk_clk.violations() + b.blk.chk_load.violations() + b.blk.chk_timing.violations(), 0u);
}

INSTANTIATE_TEST_SUITE_P(ClockPsDuty, SqmulFastPhase,
                         ::testing::Values(std::pair<int, int>{20000, 50}, std::pair<int, int>{20000, 25},
                                           std::pair<int, int>{20000, 75}, std::pair<int, int>{8000, 50}),
                         [](const ::testing::TestParamInfo<std::pair<int, int>>& i) {
                             return "P" + std::to_string(i.param.first) + "ps_duty" + std::to_string(i.param.second);
                         });

class SqmulFastPaths : public ::testing::TestWithParam<overflow_mode> {};

TEST_P(SqmulFastPaths, AreTheBlockModelsDerivedOnes) {
    block_delays d;
    d.multiplier = sc_time(2500, SC_PS);
    d.mux = sc_time(400, SC_PS);
    d.adder = sc_time(1100, SC_PS);
    std::vector<surface> s{{20, {255, 255, 255}, {0x7000}}};
    dual_bench b("tb", s, sqmul_timing(), GetParam(), d);
    sc_core::sc_start(sc_core::SC_ZERO_TIME);
    EXPECT_EQ(b.fst.rg1_to_ctrl(), b.blk.rg1_to_ctrl().delay) << b.blk.rg1_to_ctrl().to_string();
    EXPECT_EQ(b.fst.rg2_to_load(), b.blk.rg2_to_load().delay) << b.blk.rg2_to_load().to_string();
    EXPECT_EQ(b.fst.min_high(), b.blk.min_high());
    EXPECT_EQ(b.fst.min_low(), b.blk.min_low());
    EXPECT_EQ(b.fst.colour_path(), b.blk.chk_timing.path(0));
}

INSTANTIATE_TEST_SUITE_P(Mode, SqmulFastPaths, ::testing::Values(overflow_mode::saturate, overflow_mode::wrap),
                         [](const ::testing::TestParamInfo<overflow_mode>& i) {
                             return i.param == overflow_mode::saturate ? std::string("Saturate") : std::string("Wrap");
                         });

}  // namespace test_sqmul_fast
