// The squared-quadratic device's own tests (the shared ones are in test_specular_devices.cpp's
// typed suite): its latency in clocks against hand-computed instants, the derived paths against
// hand sums of the default delays, each timing rule and bad input reported with its documented
// result, the trace and its view. Each TEST elaborates one bench: ctest runs each in its own process.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/common/vcd_names.h"
#include "core/report_ids.h"
#include "core/trace.h"
#include "arith/squared_arith.h"
#include "scene/scene.h"
#include "testbenches/specular/specular_view.h"
#include "squared/squared_device.h"
#include "squared_script.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_squared_device {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_NS;
using sc_core::SC_PS;
using sc_core::sc_time;

namespace {

using bench_t = scripted_bench<squared_device>;
const sc_time clk20(20, SC_NS);
const sc_time gate(100, SC_PS);  // output 29's AND gate (block_delays::gate)

// The first rising edge of a clock of `period` (rising at 0, period, ...) strictly after t.
sc_time next_rise(const sc_time& t, const sc_time& period) {
    const auto k = static_cast<uint64_t>(std::floor(t / period)) + 1;
    return period * static_cast<double>(k);
}

void run(bench_t& bench, const sc_time& limit = sc_time(1, sc_core::SC_MS)) {
    ASSERT_TRUE(run_to_completion(bench, limit)) << "the script did not finish";
}

void expect_golden(const pixel_sample& s, overflow_mode mode = overflow_mode::saturate) {
    EXPECT_EQ(s.out, golden_squared(s.n, s.cos, s.ksi, mode).out) << "n " << s.n << " cos 0x" << std::hex << s.cos;
}

}  // namespace

TEST(SquaredTiming, OutputTwentyNineRisesKPlusFourRisingEdgesAfterTheStrobe) {
    // Strobe 17 falls at 105 ns into each 400 ns slot and rises 10 ns later: output 29 waits for
    // the stage's done. Counted by hand: the first rising edge after the fall clocks the request
    // into sync17's first flip-flop, the second into its second, the third takes it (LOAD), k
    // more square, the next raises done: the (k + 4)-th rising edge, i.e. next_rise(fall) +
    // (k + 3) clocks, plus the AND gate's delay. n = 1000: 120 + 12 * 20 = 360 ns into the slot.
    const std::vector<std::pair<unsigned, unsigned>> nk{{1, 0}, {2, 1}, {3, 1}, {20, 4}, {512, 9}, {1000, 9}};
    bench_t bench("tb", clk20, [&](bench_t& b) {
        for (std::size_t j = 0; j < nk.size(); ++j) {
            b.until(sc_time(400.0 * j, SC_NS));
            b.load(nk[j].first, 255);
            b.strobe(sc_time(400.0 * j + 105, SC_NS), 0x7A00 + 0x100 * static_cast<uint32_t>(j), sc_time(10, SC_NS));
        }
        b.until(sc_time(400.0 * nk.size(), SC_NS));
    });
    run(bench);
    ASSERT_EQ(bench.power_up_rise.size(), 1u);
    EXPECT_EQ(bench.power_up_rise[0], gate) << "idle: output 29 follows strobe 17, high";
    ASSERT_EQ(bench.valid_rises.size(), nk.size());
    ASSERT_EQ(bench.samples.size(), nk.size());
    for (std::size_t j = 0; j < nk.size(); ++j) {
        const sc_time fall(400.0 * j + 105, SC_NS);
        const sc_time want = next_rise(fall, clk20) + clk20 * static_cast<double>(nk[j].second + 3) + gate;
        EXPECT_EQ(bench.valid_rises[j], want) << "n = " << nk[j].first;
        expect_golden(bench.samples[j]);
    }
    EXPECT_EQ(bench.dut.stage().ctl_sq.dropped(), 0u);
}

TEST(SquaredTiming, OutputTwentyNineFollowsStrobeSeventeenOnceTheResultIsReady) {
    // Strobe 17 held low for 270 ns, longer than any n needs (n = 1000: done at the 13th rising
    // edge after 105 ns, 360 ns): output 29 rises with it (Fig. 3), at 375 ns.
    bench_t bench("tb", clk20, [](bench_t& b) {
        b.load(1000, 200);
        b.strobe(sc_time(105, SC_NS), 0x7FF0, sc_time(270, SC_NS));
        b.until(sc_time(500, SC_NS));
    });
    run(bench);
    ASSERT_EQ(bench.valid_rises.size(), 1u);
    EXPECT_EQ(bench.valid_rises[0], sc_time(375, SC_NS) + gate);
    ASSERT_EQ(bench.samples.size(), 1u);
    expect_golden(bench.samples[0]);
}

TEST(SquaredTiming, DerivedPathsAreTheHandSumsOfTheDefaultDelays) {
    // Default delays: register 0.2, multiplier 3, adder 1, inverter 0.1, multiplexer 0.3 ns
    // (LZC one multiplexer, a barrel shifter of 4 rows four).
    bench_t bench("tb", clk20, [](bench_t&) {});
    sc_core::sc_start(sc_core::SC_ZERO_TIME);
    const auto& d = bench.dut;
    // RG2 -> MUL7 -> ADD9 -> MUL10 -> ADD11 -> MX_SQ: 0.2 + 3 + 1 + 3 + 1 + 0.3.
    EXPECT_EQ(d.rg2_to_load().delay, sc_time(8500, SC_PS)) << d.rg2_to_load().to_string();
    // RG1 -> LZC -> BSH1 -> INV_F -> MUL_E -> BSH2 -> ADD_A -> MUL10 -> ADD11 -> MX_SQ:
    // 0.2 + 0.3 + 1.2 + 0.1 + 3 + 1.2 + 1 + 3 + 1 + 0.3.
    EXPECT_EQ(d.rg1_to_load().delay, sc_time(11300, SC_PS)) << d.rg1_to_load().to_string();
    // High phase: the controller's select through MX_SQ (0.3); low phase: RG_SQ -> MUL12 (0.2 + 3),
    // which also covers the squaring loop RG_SQ -> MUL_SQ -> MX_SQ (3.5) less the high phase.
    EXPECT_EQ(d.min_high(), sc_time(300, SC_PS));
    EXPECT_EQ(d.min_low(), sc_time(3200, SC_PS));
    EXPECT_EQ(d.chk_clk.loop_path().delay, sc_time(3500, SC_PS)) << d.chk_clk.loop_path().to_string();
    // Strobes 20, 22, 24: RG3..5 -> MUL12..14 (0.2 + 3), checked at output 29's rise.
    EXPECT_EQ(d.chk_timing.path(0), sc_time(3200, SC_PS));
}

TEST(SquaredTiming, ClockLowPhaseOnePicosecondLongerThanItsPathIsSilent) {
    // A clock of 6.402 ns: low phase 3.201 ns > 3.2 ns (no strobe 17: a load needs 8.5 ns).
    const sc_time period(6402, SC_PS);
    bench_t bench("tb", period, [&](bench_t& b) {
        b.load(20, 255);
        b.until(sc_time(300, SC_NS));
    });
    run(bench);
    EXPECT_EQ(bench.dut.chk_clk.violations(), 0u);
}

TEST(SquaredTiming, ClockLowPhaseNotLongerThanItsPathIsReported) {
    report_log::get().expect(msg::timing);
    bench_t bench("tb", sc_time(6400, SC_PS), [](bench_t& b) {
        b.load(20, 255);
        b.until(sc_time(60, SC_NS));
    });
    run(bench);
    EXPECT_GT(bench.dut.chk_clk.low_violations(), 0u);
    EXPECT_EQ(bench.dut.chk_clk.high_violations(), 0u);
    EXPECT_GT(report_log::get().count(msg::timing), 0u);
}

TEST(SquaredTiming, LoadTooSoonAfterStrobeSeventeenIsReported) {
    // The load latches half a clock after the taking edge, the third rising edge after strobe 17
    // fell: at least 2.5 clocks after the strobe, 16 ns for the shortest clock the phase rules
    // allow (6.4 ns), so RG2's 8.5 ns path is always met there. A 3 ns clock (rising at 0, 3, ...;
    // its 1.5 ns low phases reported as well) breaks it: strobe 17 falling at 98.5 ns, 0.5 ns
    // before a rising edge, passes sync17 at 99 and 102 ns, is taken at 105 and loaded at 106.5 ns,
    // 8 ns after the strobe: reported once. Falling at 201 ns, on a rising edge, it is sampled at
    // 204 ns (the clock first), taken at 210 and loaded at 211.5 ns, 10.5 ns after: silent.
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::setup);  // at 3 ns, RG_SQ's input may change at its latching instant
    const sc_time clk3(3, SC_NS);
    bench_t bench("tb", clk3, [](bench_t& b) {
        b.load(1, 255);
        b.strobe(sc_time(98500, SC_PS), 0x7000, sc_time(5, SC_NS));
        b.strobe(sc_time(201, SC_NS), 0x7100, sc_time(5, SC_NS));
        b.until(sc_time(300, SC_NS));
    });
    run(bench);
    EXPECT_EQ(bench.dut.chk_load.violations(), 1u);
    EXPECT_GE(bench.dut.chk_clk.violations(), 10u);
    EXPECT_EQ(report_log::get().count(msg::timing), 1u + 10u);  // the phase checker reports 10
    ASSERT_EQ(bench.samples.size(), 2u);
}

TEST(SquaredTiming, NLoadedBetweenTheStrobeAndTheLoadIsReported) {
    // Strobe 17 falls at 105 ns; 120 and 140 ns clock it through sync17, 160 ns takes it and the
    // load latches at 170 ns; strobe 15 falling at 159 ns leaves RG1's 11.3 ns path 11 ns.
    report_log::get().expect(msg::timing);
    bench_t bench("tb", clk20, [](bench_t& b) {
        b.load(20, 255);
        b.until(sc_time(104, SC_NS));
        b.in18_cos.write(0x7800);
        b.until(sc_time(105, SC_NS));
        b.ctl17.write(false);
        b.until(sc_time(158, SC_NS));
        b.load_n(100);  // ctl15 falls at 159 ns
        b.until(sc_time(400, SC_NS));
        b.ctl17.write(true);
        b.until(sc_time(500, SC_NS));
    });
    run(bench);
    EXPECT_EQ(bench.dut.chk_load.violations(), 1u);
    EXPECT_EQ(report_log::get().count(msg::timing), 1u);
}

TEST(SquaredTiming, StrobeTwentyLatchingTooLateBeforeOutputTwentyNineIsReported) {
    // n = 1 (k = 0), k_s*I = 100: strobe 17 falls at 105 ns and stays low until 200 ns (done at the
    // fourth rising edge, 180 ns); strobe 20 latches k_s*I(R) = 200 at 199 ns, 1.1 ns before
    // output 29 rises (200.1 ns), less than RG3 -> MUL12's 3.2 ns: reported. The defined result:
    // the outputs sampled at that rise are not settled: output 25 still shows cos * 100
    // (0x7000 * 100 >> 7 = 22400 on Q9.8), and changes to cos * 200 = 44800 3.2 ns after the latch.
    report_log::get().expect(msg::timing);
    bench_t bench("tb", clk20, [](bench_t& b) {
        b.load(1, 100);
        b.until(sc_time(104, SC_NS));
        b.in18_cos.write(0x7000);
        b.until(sc_time(105, SC_NS));
        b.ctl17.write(false);
        b.until(sc_time(198, SC_NS));
        b.in19_ksi_r.write(200);
        b.until(sc_time(199, SC_NS));
        b.ctl20.write(false);
        b.until(sc_time(200, SC_NS));
        b.ctl17.write(true);
        b.until(sc_time(201, SC_NS));
        b.ctl20.write(true);
        b.until(sc_time(300, SC_NS));
    });
    run(bench);
    EXPECT_EQ(bench.dut.chk_timing.violations(), 1u);
    const auto texts = report_log::get().messages(msg::timing);
    ASSERT_EQ(texts.size(), 1u);
    const std::string& t = texts[0];
    EXPECT_NE(t.find("tb.dut.chk_timing: outputs validated at " + sc_time(200100, SC_PS).to_string() + ", only " +
                     sc_time(1100, SC_PS).to_string() + " after"),
              std::string::npos) << t;
    EXPECT_NE(t.find(std::string(bench.dut.chk_timing.ctl[0].name()) + " latched"), std::string::npos)
        << "strobe 20's input of the checker: " << t;
    EXPECT_NE(t.find("(its path to the outputs: rg3 -> mul12 = 3.2 ns)"), std::string::npos) << t;
    EXPECT_NE(t.find("the outputs sampled at this edge are not settled"), std::string::npos) << t;
    ASSERT_EQ(bench.valid_rises.size(), 1u);
    EXPECT_EQ(bench.valid_rises[0], sc_time(200, SC_NS) + gate);
    ASSERT_EQ(bench.samples.size(), 1u);
    EXPECT_EQ(bench.samples[0].ksi[0], 200u) << "the monitor saw RG3 latch the new k_s*I";
    EXPECT_EQ(bench.samples[0].out[0], 22400u) << "output 25 not yet settled: the old k_s*I's colour";
    EXPECT_EQ(bench.samples[0].out[0], golden_squared(1, 0x7000, {100, 100, 100}, overflow_mode::saturate).out[0]);
    EXPECT_EQ(bench.out25_r.read().to_uint64(), 44800u) << "settled after RG3 -> MUL12";
}

TEST(SquaredTiming, ClockHighPhaseNotLongerThanItsPathIsReported) {
    // A 20 ns clock at 1 % duty: high 0.2 ns, not longer than the controller's select through
    // MX_SQ (0.3 ns): every high phase is counted, the first 10 reported. n = 1 (k = 0), strobe 17
    // low 5 ns, so output 29 rises at done. The defined result, worked by hand: the select changes
    // at the rising edge and MX_SQ follows 0.3 ns later, after RG_SQ latched at the falling edge
    // 0.2 ns after it; so RG_SQ takes each input one clock late: at the LOAD's falling edge it
    // holds, at the done edge's it takes the quadratic, 0.1 ns after output 29 rose. Each sample
    // therefore shows the previous pixel's colour (the first: RG_SQ's power-up 0), at n = 1
    // cos * k_s*I (0x7000 * 255 >> 7 = 57120, 0x6000: 48960).
    report_log::get().expect(msg::timing);
    const std::vector<uint32_t> cs{0x7000, 0x6000, 0x5000};
    const std::map<uint64_t, uint64_t> shown{{0x7000, 0}, {0x6000, 57120}, {0x5000, 48960}};
    std::vector<surface> s{{1, {255, 255, 255}, cs}};
    const strobe_timing t = phase_sweep_timing(15, sc_core::SC_ZERO_TIME, clk20, 0.01);
    specular_bench<squared_device> bench("tb", s, t, [&shown](uint64_t, uint64_t c, const std::array<uint64_t, 3>&) {
        datapath_nets r{};
        const auto it = shown.find(c);
        const uint64_t v = it == shown.end() ? 1 : it->second;
        r.out = {v, v, v};
        return r;
    });
    ASSERT_TRUE(run_to_completion(bench, sc_time(1, sc_core::SC_MS)));
    EXPECT_EQ(bench.checker.samples(), cs.size());
    EXPECT_EQ(bench.checker.mismatches(), 0u) << "each sample the previous pixel's colour";
    EXPECT_GE(bench.dut.chk_clk.high_violations(), 10u);
    EXPECT_EQ(bench.dut.chk_clk.low_violations(), 0u);
    EXPECT_EQ(report_log::get().count(msg::timing), 10u);
    const auto texts = report_log::get().messages(msg::timing);
    ASSERT_EQ(texts.size(), 10u);
    EXPECT_NE(texts[0].find("tb.dut.chk_clk: high phase of"), std::string::npos) << texts[0];
    EXPECT_NE(texts[0].find("lasts " + sc_time(200, SC_PS).to_string() + ", not longer than the " +
                            sc_time(300, SC_PS).to_string() + " its paths take"),
              std::string::npos)
        << texts[0];
    EXPECT_NE(texts[0].find("are not settled"), std::string::npos) << texts[0];
    EXPECT_NE(texts[9].find("[10 violations reported; further ones are only counted]"), std::string::npos) << texts[9];
}

TEST(SquaredBadInput, StrobeBeforeTheResultIsValidIsReportedAndTheResultDropped) {
    // n = 1000 (k = 9): the first cos crosses sync17 at 120 and 140 ns, is taken at 160 ns and
    // still being squared when strobe 17 falls again at 190 ns: reported, that result never
    // validated; the second request crosses at 200 and 220 ns, is taken at 240 ns, and output 29
    // rises at 240 + 10 * 20 ns.
    report_log::get().expect(msg::timing);
    bench_t bench("tb", clk20, [](bench_t& b) {
        b.load(1000, 255);
        b.strobe(sc_time(105, SC_NS), 0x7000, sc_time(10, SC_NS));
        b.strobe(sc_time(190, SC_NS), 0x7F00, sc_time(10, SC_NS));
        b.until(sc_time(600, SC_NS));
    });
    run(bench);
    EXPECT_EQ(bench.dut.stage().ctl_sq.dropped(), 1u);
    EXPECT_EQ(report_log::get().count(msg::timing), 1u);
    const auto texts = report_log::get().messages(msg::timing);
    ASSERT_EQ(texts.size(), 1u);
    EXPECT_NE(texts[0].find("ctl17 fell at 190 ns before the previous result was valid (still being squared)"),
              std::string::npos) << texts[0];
    ASSERT_EQ(bench.valid_rises.size(), 1u);
    EXPECT_EQ(bench.valid_rises[0], sc_time(440, SC_NS) + gate);
    ASSERT_EQ(bench.samples.size(), 1u);
    EXPECT_EQ(bench.samples[0].cos, 0x7F00u);
    expect_golden(bench.samples[0]);
}

TEST(SquaredBadInput, TwoStrobesBeforeTheTakingEdgeReportTheFirstAsDropped) {
    report_log::get().expect(msg::timing);
    bench_t bench("tb", clk20, [](bench_t& b) {
        b.load(7, 128);
        b.strobe(sc_time(103, SC_NS), 0x6000, sc_time(2, SC_NS));
        b.strobe(sc_time(108, SC_NS), 0x6800, sc_time(2, SC_NS));
        b.until(sc_time(300, SC_NS));
    });
    run(bench);
    EXPECT_EQ(bench.dut.stage().ctl_sq.dropped(), 1u);
    ASSERT_EQ(bench.samples.size(), 1u);
    EXPECT_EQ(bench.samples[0].cos, 0x6800u);
    expect_golden(bench.samples[0]);
    // The second strobe keeps the request raised (reported: "not yet taken by clk"); k = 2 for
    // n = 7: through sync17 at 120 and 140 ns, taken at 160 ns, done at 160 + 3 * 20 ns.
    const auto texts = report_log::get().messages(msg::timing);
    ASSERT_EQ(texts.size(), 1u);
    EXPECT_NE(texts[0].find("(not yet taken by clk)"), std::string::npos) << texts[0];
    ASSERT_EQ(bench.valid_rises.size(), 1u);
    EXPECT_EQ(bench.valid_rises[0], sc_time(220, SC_NS) + gate);
}

TEST(SquaredBadInput, NZeroIsReportedAndReadAsNOne) {
    // n = 0: the LZC counts 10 zeros, a = 0, no squaring: the outputs are n = 1's, cos * k_s*I.
    report_log::get().expect(msg::input);
    const std::vector<uint32_t> cs{0x0000, 0x2345, 0x4000, 0x7FFF, 0x8000};
    bench_t bench("tb", clk20, [&](bench_t& b) {
        b.load(0, 255);
        for (std::size_t i = 0; i < cs.size(); ++i) b.strobe(sc_time(100.0 + 100 * i, SC_NS), cs[i], sc_time(10, SC_NS));
        b.until(sc_time(700, SC_NS));
    });
    run(bench);
    EXPECT_EQ(report_log::get().count(msg::input), 1u);
    ASSERT_EQ(bench.samples.size(), cs.size());
    for (std::size_t i = 0; i < cs.size(); ++i) {
        EXPECT_EQ(bench.samples[i].out, golden_squared(1, cs[i], {255, 255, 255}, overflow_mode::saturate).out);
        EXPECT_EQ(bench.samples[i].out[0], (uint64_t{cs[i]} * 255u) >> 7) << "cos * k_s*I on Q9.8";
        // n = 0 takes no squaring: output 29 rises 4 rising edges after the strobe (sync17's two,
        // the taking edge, done). The strobe falls at a rising edge (100 ns, 200 ns, ...): sync17's
        // first flip-flop samples it at the next one, as the controller orders them.
        EXPECT_EQ(bench.valid_rises[i], next_rise(sc_time(100.0 + 100 * i, SC_NS), clk20) + 3 * clk20 + gate);
    }
}

TEST(SquaredBadInput, NAbove1000IsReportedAndExtendsTheLaw) {
    report_log::get().expect(msg::input);
    bench_t bench("tb", clk20, [](bench_t& b) {
        b.load(1023, 255);
        b.strobe(sc_time(105, SC_NS), 0x7FFF, sc_time(250, SC_NS));
        b.until(sc_time(400, SC_NS));
    });
    run(bench);
    EXPECT_EQ(report_log::get().count(msg::input), 1u);
    ASSERT_EQ(bench.samples.size(), 1u);
    expect_golden(bench.samples[0]);
    // k = 9, a = 511/512 + 0: (1 - 2^-15)^1023 = 0.9693 within its 1 % of the code's cos^1023.
    const double q = static_cast<double>(bench.samples[0].out[0]) / 256.0 / 255.0;
    EXPECT_NEAR(q, std::pow(0x7FFF / 32768.0, 1023), 0.01);
}

TEST(SquaredBadInput, CosAboveOneSaturatesToFullIntensity) {
    // cos > 1.0 is reported; saturate mode clamps ADD11 to 1.0, which every square keeps: k_s*I.
    report_log::get().expect(msg::input);
    bench_t bench("tb", clk20, [](bench_t& b) {
        b.load(100, 201);
        b.strobe(sc_time(105, SC_NS), 0xC000, sc_time(250, SC_NS));
        b.strobe(sc_time(405, SC_NS), 0xFFFF, sc_time(250, SC_NS));
        b.until(sc_time(700, SC_NS));
    });
    run(bench);
    EXPECT_EQ(report_log::get().count(msg::input), 2u);
    ASSERT_EQ(bench.samples.size(), 2u);
    for (const auto& s : bench.samples) EXPECT_EQ(s.out[0], 201u << 8);
}

TEST(SquaredBadInput, CosAboveOneInWrapModeIsReportedAndBitExact) {
    report_log::get().expect(msg::input);
    bench_t bench(
        "tb", clk20,
        [](bench_t& b) {
            b.load(3, 255);
            b.strobe(sc_time(105, SC_NS), 0xC000, sc_time(250, SC_NS));
            b.strobe(sc_time(405, SC_NS), 0x9001, sc_time(250, SC_NS));
            b.until(sc_time(700, SC_NS));
        },
        overflow_mode::wrap);
    run(bench);
    EXPECT_EQ(report_log::get().count(msg::input), 2u);
    ASSERT_EQ(bench.samples.size(), 2u);
    for (const auto& s : bench.samples) expect_golden(s, overflow_mode::wrap);
}

TEST(SquaredConfig, ZeroDelaysAreAConfigurationError) {
    // With every delay zero, RG_SQ's own square would reach its input at the latching instant.
    report_log::get().expect(msg::config);
    report_log::get().expect(msg::setup);
    block_delays zero;
    zero.reg = zero.inverter = zero.adder = zero.multiplier = zero.rom = zero.gate = zero.mux = sc_core::SC_ZERO_TIME;
    bench_t bench("tb", clk20, [](bench_t&) {}, overflow_mode::saturate, zero);
    EXPECT_EQ(report_log::get().count(msg::config), 1u);
}

TEST(SquaredChecker, AMonitorSampleOffTheGoldenModelIsCaught) {
    // The comparison these tests make must be able to fail: the device's own sample against the
    // golden model of a neighbouring n differs.
    bench_t bench("tb", clk20, [](bench_t& b) {
        b.load(20, 255);
        b.strobe(sc_time(105, SC_NS), 0x7A00, sc_time(250, SC_NS));
        b.until(sc_time(400, SC_NS));
    });
    run(bench);
    ASSERT_EQ(bench.samples.size(), 1u);
    const auto& s = bench.samples[0];
    EXPECT_EQ(s.out, golden_squared(20, s.cos, s.ksi, overflow_mode::saturate).out);
    EXPECT_NE(s.out, golden_squared(21, s.cos, s.ksi, overflow_mode::saturate).out);
}

namespace {

// The bench squared_tb's default run builds: a sphere's raster line of 48 pixels at n = 10, 100 and
// 1000 (Fig. 3 with 15 clocks per pixel), traced into `stem`.vcd.
void trace_default_run(const std::string& stem) {
    std::vector<uint32_t> line;
    for (double c : scene::sphere_line_cos(0.2, 48, 0.3, 0.4, 1.0)) line.push_back(scene::cos_code(c));
    std::vector<surface> s;
    for (unsigned n : {10u, 100u, 1000u}) s.push_back({n, {255, 180, 60}, line});
    specular_bench<squared_device> bench("tb", s, squared_timing(), [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        datapath_nets r{};
        r.out = golden_squared(n, c, k, overflow_mode::saturate).out;
        return r;
    });
    vcd_file vcd(stem);
    vcd.trace(bench);
    sc_core::sc_start(bench.stim.duration() * 1.01 + sc_time(1, sc_core::SC_US));
    EXPECT_TRUE(bench.finished());
    EXPECT_EQ(bench.checker.samples(), 3u * 48u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
}

}  // namespace

TEST(SquaredTrace, VcdDeclaresTheDeviceNetsAndTheViewShowsOnlyThose) {
    const std::string stem = ::testing::TempDir() + "squared_trace";
    trace_default_run(stem);
    const auto declared = vcd_declared(stem + ".vcd");
    for (const char* net : {"tb.clk", "tb.ctl17", "tb.out29_valid", "tb.dut.rg1_n[9:0]", "tb.dut.z_lead[3:0]",
                            "tb.dut.a_coef[11:0]", "tb.dut.a_gen.mul_e_f_x_not_f[17:0]", "tb.dut.mul10_a_x_diff[19:0]",
                            "tb.dut.add11_q[18:0]", "tb.dut.sq_brdf[18:0]", "tb.dut.sq.mx_sq_sel[1:0]",
                            "tb.dut.sq.mul_sq_square[18:0]", "tb.dut.sq_done", "tb.out25_r[16:0]",
                            "tb.dut.sq.ctl_sq_req", "tb.dut.sq.sync17.stage1", "tb.dut.sq.sync17_req"})
        EXPECT_EQ(declared.count(std::string("SystemC.") + net), 1u) << net;
    for (const auto& n : declared) EXPECT_EQ(n.find(' '), std::string::npos) << n;
    const auto shown = gtkw_listed(source_path("traces/squared.gtkw"));
    EXPECT_GE(shown.size(), 35u);
    for (const auto& s : shown) EXPECT_EQ(declared.count(s), 1u) << s << " is in the view but not in the VCD";
}

TEST(SquaredTrace, GtkwaveViewReadsAtFirstSight) {
    // traces/squared.gtkw against the VCD of squared_tb's default run: dump file, marker inside the
    // window and off every edge, every bus a number in its format from src/floor/formats.
    const std::string stem = ::testing::TempDir() + "squared_view";
    trace_default_run(stem);
    view_formats f = specular_view_formats();
    f.erase("tb.dut.mul10_a_x_diff");
    f.erase("tb.dut.add11_brdf");
    f["tb.dut.mul10_a_x_diff"] = squared::mul10_fmt;
    f["tb.in16_n"] = f["tb.dut.rg1_n"] = squared::n_fmt;
    f["tb.dut.z_lead"] = qfmt{squared::z_width, false, 0};
    f["tb.dut.a_gen.bsh1_mant"] = squared::mant_fmt;
    f["tb.dut.a_gen.f_frac"] = f["tb.dut.a_gen.inv_f_not_f"] = squared::f_fmt;
    f["tb.dut.a_gen.mul_e_f_x_not_f"] = squared::e_fmt;
    f["tb.dut.a_gen.bsh2_e_shifted"] = qfmt{squared::esh_width, false, squared::esh_frac};
    f["tb.dut.a_gen.bend"] = squared::bend_fmt;
    f["tb.dut.a_gen.f_aligned"] = f["tb.dut.a_coef"] = squared::a_fmt;
    f["tb.dut.cos_aligned"] = f["tb.dut.add11_q"] = f["tb.dut.sq.mx_sq_next"] = f["tb.dut.sq_brdf"] =
        f["tb.dut.sq.mul_sq_square"] = squared::q_fmt;
    f["tb.dut.brdf_q15"] = spec::brdf_fmt;
    f["tb.dut.sq.mx_sq_sel"] = qfmt{2, false, 0};
    const auto problems = view_problems(source_path("traces/squared.gtkw"), stem + ".vcd", "squared", f,
                                        {"tb.ctl17", "tb.clk", "tb.out29_valid", "tb.out25_r", "tb.out26_g",
                                         "tb.out27_b", "tb.dut.sq_brdf", "tb.dut.sq.mx_sq_sel"});
    EXPECT_TRUE(problems.empty()) << joined(problems);
}

}  // namespace test_squared_device
