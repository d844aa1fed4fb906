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
#include "sqmul/sqmul.h"

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
          clk("clk", t.clk_period),
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
    // the walks of 100, 1001, 1023 (10 to 20 clocks): strobes before the result is valid, dropped by
    // both models alike (n = 5's 5 clocks end before the next surface reloads RG1, the long walks'
    // last ones are dropped by its first strobe). A 16 ns clock puts every strobe on a falling edge
    // of clk (the first at 16 + 32 + 8 ns; a pixel 80 ns, a surface's loads 32 ns): RG_P latches
    // before the new cos reaches MUL_P, in both models (a strobe just before a falling edge would
    // leave the block model's product unsettled there).
    report_log::get().expect(msg::input);
    report_log::get().expect(msg::timing);
    std::vector<surface> s;
    for (unsigned n : {0u, 1u, 5u, 100u, 1001u, 1023u}) s.push_back({n, {255, 1, 128}, {0x0000, 0x7000, 0x8000, 0x9000, 0xFFFF}});
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
    // An 8 ns clock: a LOAD 4 ns after its taking edge is too soon for RG2 (4.8 ns) whenever the
    // strobe falls in the last 0.8 ns before a rising edge (a pixel period of 177.1 ns drifts the
    // strobes against the clock); a 7.2 ns clock (LOAD 3.6 ns after: the last 1.2 ns) also has a
    // high phase (3.6 ns) not longer than the controller's select through MUL_P. The block model
    // then samples what its network really shows (mismatches against golden, reported); the fast
    // model takes settled words (sqmul_fast.h: not modelled), so only the reports are compared.
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::mismatch);
    report_log::get().expect(msg::setup);
    const sc_time period(GetParam(), SC_PS);
    strobe_timing t = sqmul_timing(period);
    t.t_high = sc_time(10200, SC_PS);
    std::vector<surface> s{{20, {255, 255, 255}, std::vector<uint32_t>(60, 0x7400)}};
    dual_bench b("tb", s, t, overflow_mode::saturate);
    ASSERT_TRUE(run_to_completion(b, sc_time(1, SC_MS)));
    EXPECT_GT(b.blk.chk_load.violations(), 0u);
    EXPECT_EQ(b.fst.load_violations(), b.blk.chk_load.violations());
    if (GetParam() < 7201) {
        EXPECT_GT(b.blk.chk_clk.violations(), 0u);
    }
    EXPECT_EQ(b.fst.clock_violations(), b.blk.chk_clk.violations());
    EXPECT_EQ(b.fst.timing_violations(), b.blk.chk_timing.violations());
}

INSTANTIATE_TEST_SUITE_P(ClockPs, SqmulFastTiming, ::testing::Values(8000, 7200));

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
