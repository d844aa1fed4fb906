// The square-and-multiply device's block model (sqmul/sqmul_device.h) against its golden model
// (golden_sqmul) on every n 0..1023 with cos codes where cos^n is 0.5, 0.1 and 0.01, in both modes;
// its clocks per sample against floor(log2 n) + popcount(n) + 3 worked out here (and by hand at a
// few n) and against the instants of output 29; the controller's steps at n = 5 by hand; the
// derived paths against hand sums of the default delays; each timing rule and bad input reported
// with its documented result; the trace and its view. Each TEST elaborates one bench: ctest runs
// each in its own process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/common/vcd_names.h"
#include "core/report_ids.h"
#include "core/trace.h"
#include "arith/sqmul_arith.h"
#include "scene/scene.h"
#include "testbenches/specular/specular_tb.h"
#include "testbenches/rtl/rtl_squared_tb.h"
#include "testbenches/specular/specular_view.h"
#include "testbenches/squared/squared_script.h"
#include "sqmul/sqmul_count.h"
#include "sqmul/sqmul_device.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_sqmul_device {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_MS;
using sc_core::SC_NS;
using sc_core::SC_PS;
using sc_core::sc_time;

namespace {

using bench_t = scripted_bench<sqmul_device>;
const sc_time clk20(20, SC_NS);
const sc_time gate(100, SC_PS);  // output 29's AND gate (block_delays::gate)

// The first rising edge of a clock of `period` (rising at 0, period, ...) strictly after t.
sc_time next_rise(const sc_time& t, const sc_time& period) {
    const auto k = static_cast<uint64_t>(std::floor(t / period)) + 1;
    return period * static_cast<double>(k);
}

// Rising edges from strobe 17's fall to done: sync17's two, the taking edge, floor(log2 n) squares
// and popcount(n) - 1 multiplications, the done edge: floor(log2 n) + popcount(n) + 3, n = 0 read
// as 1.
unsigned clocks_per_sample(unsigned n) {
    if (n == 0) n = 1;
    unsigned log2 = 0, ones = 0;
    for (unsigned v = n; v > 1; v >>= 1) ++log2;
    for (unsigned v = n; v != 0; v >>= 1) ones += v & 1u;
    return log2 + ones + 3;
}

void run(bench_t& bench, const sc_time& limit = sc_time(1, SC_MS)) {
    ASSERT_TRUE(run_to_completion(bench, limit)) << "the script did not finish";
}

void expect_golden(const pixel_sample& s, overflow_mode mode = overflow_mode::saturate) {
    EXPECT_EQ(s.out, golden_sqmul(s.n, s.cos, s.ksi, mode).out) << "n " << s.n << " cos 0x" << std::hex << s.cos;
}

specular_checker::golden_fn golden(overflow_mode mode) {
    return [mode](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        datapath_nets r{};
        r.out = golden_sqmul(n, c, k, mode).out;
        return r;
    };
}

// The cos codes around cos^n = 0.5, 0.1, 0.01 (one below, at, one above each), n = 0 read as 1.
std::vector<uint32_t> codes_around_levels(unsigned n) {
    std::vector<uint32_t> v;
    for (double level : {0.5, 0.1, 0.01}) {
        const auto c = static_cast<uint32_t>(std::lround(std::pow(level, 1.0 / std::max(n, 1u)) * spec::cos_one));
        for (uint32_t d : {c - 1, c, c + 1}) v.push_back(std::min<uint32_t>(d, spec::cos_one));
    }
    return v;
}

}  // namespace

TEST(SqmulClocks, HandWorkedCountsAtAFewN) {
    // floor(log2 n) + popcount(n) + 3, worked by hand: 5 = 0b101: 2 + 2 + 3; 20 = 0b10100: 4 + 2 + 3;
    // 100 = 0b1100100: 6 + 3 + 3; 1000 = 0b1111101000: 9 + 6 + 3; 1023: 9 + 10 + 3; 1 and 0: 4.
    EXPECT_EQ(clocks_per_sample(5), 7u);
    EXPECT_EQ(clocks_per_sample(20), 9u);
    EXPECT_EQ(clocks_per_sample(100), 12u);
    EXPECT_EQ(clocks_per_sample(1000), 18u);
    EXPECT_EQ(clocks_per_sample(1023), 22u);
    EXPECT_EQ(clocks_per_sample(1), 4u);
    EXPECT_EQ(clocks_per_sample(0), 4u);
    // The golden model walks as many steps (sync17's two edges, the taking and the done edge
    // around them).
    for (unsigned n = 0; n < 1024; ++n) {
        const auto g = golden_sqmul(n, 0x7000, {0, 0, 0}, overflow_mode::saturate);
        EXPECT_EQ(g.squares + g.multiplies + 4, clocks_per_sample(n)) << "n = " << n;
    }
}

TEST(SqmulCount, StepsAtNFiveByHand) {
    // n = 5 = 0b101: z = 7, f = n << 7's 9 low wires = 0b010000000. The strobe raises req (the
    // complement of `taken`, 0 at power-up); while sync17 still shows 0 the edges hold; the edge
    // that sees it taken LOADs; bit 0: SQUARE; bit 1: SQUARE then MULTIPLY (cos on MX_B); then the
    // done edge (HOLD, ack = taken = req).
    sqmul::sqmul_count c;
    EXPECT_TRUE(c.done());
    EXPECT_FALSE(c.strobe());
    EXPECT_TRUE(c.req());
    EXPECT_FALSE(c.done());
    EXPECT_TRUE(c.strobe()) << "a second strobe before the taking edge drops the first";
    EXPECT_TRUE(c.req()) << "and keeps the request raised";
    const unsigned z = 7, f = 0b010000000;
    for (int i = 0; i < 2; ++i) {
        const auto s = c.rising(false, z, f);  // the request still crossing sync17
        EXPECT_EQ(s.p, sqmul::p_hold);
        EXPECT_TRUE(c.pending());
        EXPECT_FALSE(c.done());
    }
    const std::vector<std::pair<sqmul::p_select, sqmul::b_select>> want{
        {sqmul::p_load, sqmul::b_p}, {sqmul::p_product, sqmul::b_p}, {sqmul::p_product, sqmul::b_p},
        {sqmul::p_product, sqmul::b_cos}, {sqmul::p_hold, sqmul::b_p}};
    for (std::size_t i = 0; i < want.size(); ++i) {
        const auto s = c.rising(true, z, f);
        EXPECT_EQ(s.p, want[i].first) << "edge " << i + 1;
        EXPECT_EQ(s.b, want[i].second) << "edge " << i + 1;
        EXPECT_EQ(c.done(), i + 1 == want.size()) << "edge " << i + 1;
    }
    // The next strobe lowers req (taken = 1); a strobe while busy abandons the result.
    EXPECT_FALSE(c.strobe());
    EXPECT_FALSE(c.req());
    EXPECT_EQ(c.rising(false, z, f).p, sqmul::p_load);
    EXPECT_TRUE(c.strobe());
    EXPECT_TRUE(c.req()) << "a new request, taken once it has crossed";
}

TEST(SqmulTiming, OutputTwentyNineRisesAfterTheWalk) {
    // Strobe 17 falls at 105 ns into each 600 ns slot and rises 10 ns later: output 29 waits for
    // done, at next_rise(fall) + (clocks - 1) clocks, plus the AND gate's delay (n = 1023: 22
    // edges, 120 + 21 * 20 = 540 ns into its slot).
    const std::vector<unsigned> ns{1, 2, 3, 5, 20, 100, 1000, 1023};
    bench_t bench("tb", clk20, [&](bench_t& b) {
        for (std::size_t j = 0; j < ns.size(); ++j) {
            b.until(sc_time(600.0 * j, SC_NS));
            b.load(ns[j], 255);
            b.strobe(sc_time(600.0 * j + 105, SC_NS), 0x7A00 + 0x100 * static_cast<uint32_t>(j), sc_time(10, SC_NS));
        }
        b.until(sc_time(600.0 * ns.size(), SC_NS));
    });
    report_log::get().expect(msg::input);  // n = 1023
    run(bench);
    ASSERT_EQ(bench.power_up_rise.size(), 1u);
    EXPECT_EQ(bench.power_up_rise[0], gate) << "idle: output 29 follows strobe 17, high";
    ASSERT_EQ(bench.valid_rises.size(), ns.size());
    ASSERT_EQ(bench.samples.size(), ns.size());
    for (std::size_t j = 0; j < ns.size(); ++j) {
        const sc_time fall(600.0 * j + 105, SC_NS);
        const sc_time want = next_rise(fall, clk20) + clk20 * static_cast<double>(clocks_per_sample(ns[j]) - 1) + gate;
        EXPECT_EQ(bench.valid_rises[j], want) << "n = " << ns[j];
        expect_golden(bench.samples[j]);
    }
    // n = 20: strobe at 2505 ns, through sync17 at 2520 and 2540 ns, taken at 2560 ns, 4 squares
    // and 1 multiplication, done at the 9th rising edge, 2680 ns.
    EXPECT_EQ(bench.valid_rises[4], sc_time(2680, SC_NS) + gate);
    EXPECT_EQ(bench.dut.stage.ctl.dropped(), 0u);
}

TEST(SqmulTiming, EveryNTakesItsClocksPerSample) {
    // Every n 0..1023: strobe 17 low for 5 ns (output 29 rises with done), 48 clocks per pixel.
    report_log::get().expect(msg::input);
    std::vector<surface> s;
    for (unsigned n = 0; n < 1024; ++n) s.push_back({n, {255, 255, 255}, {0x7000}});
    const strobe_timing t = done_timing(48);
    specular_bench<sqmul_device> bench("tb", s, t, golden(overflow_mode::saturate));
    latency_probe probe("probe");
    probe.ctl17(bench.ctl17);
    probe.out29_valid(bench.out29_valid);
    ASSERT_TRUE(run_to_completion(bench, sc_time(10, SC_MS)));
    EXPECT_EQ(bench.checker.samples(), 1024u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    ASSERT_EQ(probe.falls.size(), 1024u);
    ASSERT_EQ(probe.rises.size(), 1024u);
    unsigned wrong = 0;
    for (unsigned n = 0; n < 1024; ++n) {
        const sc_time want =
            next_rise(probe.falls[n], clk20) + clk20 * static_cast<double>(clocks_per_sample(n) - 1) + gate;
        if (probe.rises[n] != want && ++wrong <= 10)
            ADD_FAILURE() << "n = " << n << ": fell " << probe.falls[n] << ", rose " << probe.rises[n] << ", want " << want;
    }
    EXPECT_EQ(wrong, 0u);
}

class SqmulEveryN : public ::testing::TestWithParam<overflow_mode> {};

TEST_P(SqmulEveryN, CosCodesAroundHalfATenthAndAHundredthMatchGolden) {
    report_log::get().expect(msg::input);  // n = 0 and 1001..1023
    std::vector<surface> s;
    for (unsigned n = 0; n < 1024; ++n) s.push_back({n, {255, 170, 3}, codes_around_levels(n)});
    specular_bench<sqmul_device> bench("tb", s, sqmul_timing(), golden(GetParam()), GetParam());
    ASSERT_TRUE(run_to_completion(bench, sc_time(100, SC_MS)));
    EXPECT_EQ(bench.checker.samples(), 1024u * 9u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.dut.chk_in16_n.violations(), 24u) << "n = 0 and 1001..1023";
    EXPECT_EQ(bench.dut.stage.ctl.dropped(), 0u);
    // At n = 20, cos^n = 0.5: the device's output within 0.2 % of 255 * 0.5 (real cos^n).
    const double c = std::lround(std::pow(0.5, 1.0 / 20) * spec::cos_one) / double(spec::cos_one);
    const auto g = golden_sqmul(20, static_cast<uint64_t>(c * spec::cos_one), {255, 0, 0}, GetParam());
    EXPECT_NEAR(g.out[0] / 256.0, 255 * std::pow(c, 20), 255 * std::pow(c, 20) * 0.002);
}

INSTANTIATE_TEST_SUITE_P(Mode, SqmulEveryN, ::testing::Values(overflow_mode::saturate, overflow_mode::wrap),
                         [](const ::testing::TestParamInfo<overflow_mode>& i) {
                             return i.param == overflow_mode::saturate ? std::string("Saturate") : std::string("Wrap");
                         });

TEST(SqmulTiming, DerivedPathsAreTheHandSumsOfTheDefaultDelays) {
    // Default delays: register 0.2, multiplier 3, adder 1, multiplexer 0.3 ns (LZC one
    // multiplexer, a barrel shifter of 4 rows four).
    bench_t bench("tb", clk20, [](bench_t&) {});
    sc_core::sc_start(sc_core::SC_ZERO_TIME);
    const auto& d = bench.dut;
    // RG2 -> sat_cos -> MX_B -> MUL_P -> MX_P: 0.2 + 1 + 0.3 + 3 + 0.3 (the graph knows no select:
    // the path a multiplication by cos takes, longer than the LOAD's own through MX_P alone).
    EXPECT_EQ(d.rg2_to_load().delay, sc_time(4800, SC_PS)) << d.rg2_to_load().to_string();
    // RG1 -> LZC -> BSH1 -> the controller's f: 0.2 + 0.3 + 1.2.
    EXPECT_EQ(d.rg1_to_ctrl().delay, sc_time(1700, SC_PS)) << d.rg1_to_ctrl().to_string();
    // High phase: the controller's MX_B select through MUL_P and MX_P (0.3 + 3 + 0.3); low phase:
    // RG_P -> MUL12 (0.2 + 3); the loop RG_P -> MX_B -> MUL_P -> MX_P (3.8) less the high phase.
    EXPECT_EQ(d.min_high(), sc_time(3600, SC_PS));
    EXPECT_EQ(d.min_low(), sc_time(3200, SC_PS));
    EXPECT_EQ(d.chk_clk.loop_path().delay, sc_time(3800, SC_PS)) << d.chk_clk.loop_path().to_string();
    // Strobes 20, 22, 24: RG3..5 -> MUL12..14 (0.2 + 3), checked at output 29's rise.
    EXPECT_EQ(d.chk_timing.path(0), sc_time(3200, SC_PS));
}

TEST(SqmulTiming, WrapModeHasNoSaturatorDelay) {
    // Wrap mode: sat_cos is wires, RG2 -> MX_B -> MUL_P -> MX_P is 0.2 + 0.3 + 3 + 0.3.
    bench_t bench("tb", clk20, [](bench_t&) {}, overflow_mode::wrap);
    sc_core::sc_start(sc_core::SC_ZERO_TIME);
    EXPECT_EQ(bench.dut.rg2_to_load().delay, sc_time(3800, SC_PS)) << bench.dut.rg2_to_load().to_string();
}

TEST(SqmulTiming, ClockPhasesOnePicosecondLongerThanTheirPathsAreSilent) {
    // High 3.601 ns > 3.6, low 3.601 ns > 3.2: a 7.202 ns clock.
    bench_t bench("tb", sc_time(7202, SC_PS), [](bench_t& b) {
        b.load(20, 255);
        b.until(sc_time(300, SC_NS));
    });
    run(bench);
    EXPECT_EQ(bench.dut.chk_clk.violations(), 0u);
}

TEST(SqmulTiming, ClockHighPhaseNotLongerThanItsPathIsReported) {
    report_log::get().expect(msg::timing);
    bench_t bench("tb", sc_time(7200, SC_PS), [](bench_t& b) {
        b.load(20, 255);
        b.until(sc_time(60, SC_NS));
    });
    run(bench);
    EXPECT_GT(bench.dut.chk_clk.high_violations(), 0u);
    EXPECT_EQ(bench.dut.chk_clk.low_violations(), 0u);
    EXPECT_GT(report_log::get().count(msg::timing), 0u);
}

TEST(SqmulTiming, LoadTooSoonAfterStrobeSeventeenIsReported) {
    // The load latches half a clock after the taking edge, the third rising edge after strobe 17
    // fell: at least 2.5 clocks after the strobe, over 18 ns for the shortest clock the phase
    // rules allow (just over 7.2 ns), so RG2's 4.8 ns path is always met there. A 1.6 ns clock (rising at 0, 1.6,
    // ...; its 0.8 ns phases reported as well) breaks it: strobe 17 falling at 100.3 ns, 0.5 ns
    // before a rising edge, passes sync17 at 100.8 and 102.4 ns, is taken at 104 and loaded at
    // 104.8 ns, 4.5 ns after the strobe: reported once. Falling at 200 ns, on a rising edge, it is
    // sampled at 201.6 ns (the clock first), taken at 204.8 and loaded at 205.6 ns, 5.6 ns after:
    // silent. n = 1: no product, so the load alone writes RG_P.
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::setup);  // at 1.6 ns, RG_P's input may change at its latching instant
    bench_t bench("tb", sc_time(1600, SC_PS), [](bench_t& b) {
        b.load(1, 255);
        b.strobe(sc_time(100300, SC_PS), 0x7000, sc_time(5, SC_NS));
        b.strobe(sc_time(200, SC_NS), 0x7100, sc_time(5, SC_NS));
        b.until(sc_time(300, SC_NS));
    });
    run(bench);
    EXPECT_EQ(bench.dut.chk_load.violations(), 1u);
    EXPECT_GE(bench.dut.chk_clk.violations(), 10u);
    EXPECT_EQ(report_log::get().count(msg::timing), 1u + 10u);  // the phase checker reports 10
    ASSERT_EQ(bench.samples.size(), 2u);
}

TEST(SqmulTiming, NLoadedJustBeforeTheTakingEdgeIsReported) {
    // Strobe 17 falls at 105 ns; 120 and 140 ns clock it through sync17, 160 ns takes it; strobe 15
    // falling at 158.5 ns leaves RG1's 1.7 ns path into the controller 1.5 ns: reported. Strobe 15
    // at 174 ns (after the taking edge) is not this LOAD's: silent.
    report_log::get().expect(msg::timing);
    bench_t bench("tb", clk20, [](bench_t& b) {
        b.load(20, 255);
        b.until(sc_time(104, SC_NS));
        b.in18_cos.write(0x7800);
        b.until(sc_time(105, SC_NS));
        b.ctl17.write(false);
        b.until(sc_time(157500, SC_PS));
        b.load_n(100);  // ctl15 falls at 158.5 ns
        b.until(sc_time(173, SC_NS));
        b.load_n(3);  // at 174 ns
        b.until(sc_time(400, SC_NS));
        b.ctl17.write(true);
        b.until(sc_time(500, SC_NS));
    });
    run(bench);
    EXPECT_EQ(bench.dut.chk_load.violations(), 1u);
    EXPECT_EQ(report_log::get().count(msg::timing), 1u);
}

TEST(SqmulBadInput, StrobeBeforeTheResultIsValidIsReportedAndTheResultDropped) {
    // n = 1000 (18 clocks): the first cos crosses sync17 at 120 and 140 ns, is taken at 160 ns and
    // still being walked when strobe 17 falls again at 190 ns: reported, that result never
    // validated; the second request crosses at 200 and 220 ns, is taken at 240 ns, and output 29
    // rises at 240 + 15 * 20 ns.
    report_log::get().expect(msg::timing);
    bench_t bench("tb", clk20, [](bench_t& b) {
        b.load(1000, 255);
        b.strobe(sc_time(105, SC_NS), 0x7000, sc_time(10, SC_NS));
        b.strobe(sc_time(190, SC_NS), 0x7F00, sc_time(10, SC_NS));
        b.until(sc_time(700, SC_NS));
    });
    run(bench);
    EXPECT_EQ(bench.dut.stage.ctl.dropped(), 1u);
    EXPECT_EQ(report_log::get().count(msg::timing), 1u);
    const auto texts = report_log::get().messages(msg::timing);
    ASSERT_EQ(texts.size(), 1u);
    EXPECT_NE(texts[0].find("ctl17 fell at 190 ns before the previous result was valid (still being walked)"),
              std::string::npos) << texts[0];
    ASSERT_EQ(bench.valid_rises.size(), 1u);
    EXPECT_EQ(bench.valid_rises[0], sc_time(540, SC_NS) + gate);
    ASSERT_EQ(bench.samples.size(), 1u);
    EXPECT_EQ(bench.samples[0].cos, 0x7F00u);
    expect_golden(bench.samples[0]);
}

TEST(SqmulBadInput, TwoStrobesBeforeTheTakingEdgeReportTheFirstAsDropped) {
    report_log::get().expect(msg::timing);
    bench_t bench("tb", clk20, [](bench_t& b) {
        b.load(7, 128);
        b.strobe(sc_time(103, SC_NS), 0x6000, sc_time(2, SC_NS));
        b.strobe(sc_time(108, SC_NS), 0x6800, sc_time(2, SC_NS));
        b.until(sc_time(300, SC_NS));
    });
    run(bench);
    EXPECT_EQ(bench.dut.stage.ctl.dropped(), 1u);
    ASSERT_EQ(bench.samples.size(), 1u);
    EXPECT_EQ(bench.samples[0].cos, 0x6800u);
    expect_golden(bench.samples[0]);
    // The second strobe keeps the request raised (reported: "not yet taken by clk"); n = 7 = 0b111:
    // 2 + 3 + 3 = 8 edges: through sync17 at 120 and 140 ns, taken at 160 ns, done at 160 + 5 * 20 ns.
    const auto texts = report_log::get().messages(msg::timing);
    ASSERT_EQ(texts.size(), 1u);
    EXPECT_NE(texts[0].find("(not yet taken by clk)"), std::string::npos) << texts[0];
    ASSERT_EQ(bench.valid_rises.size(), 1u);
    EXPECT_EQ(bench.valid_rises[0], sc_time(260, SC_NS) + gate);
}

TEST(SqmulBadInput, NZeroIsReportedAndReadAsNOne) {
    // n = 0: the LZC counts 10 zeros, no square: the outputs are cos * k_s*I.
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
        EXPECT_EQ(bench.samples[i].out[0], (uint64_t{cs[i]} * 255u) >> 7) << "cos * k_s*I on Q9.8";
        // Four rising edges (sync17's two, the taking edge, done); a strobe at a rising edge's
        // instant is sampled by sync17's first flip-flop at the next one.
        EXPECT_EQ(bench.valid_rises[i], next_rise(sc_time(100.0 + 100 * i, SC_NS), clk20) + 3 * clk20 + gate);
    }
}

TEST(SqmulBadInput, NAbove1000IsReportedAndWalkedAsAnyOther) {
    report_log::get().expect(msg::input);
    bench_t bench("tb", clk20, [](bench_t& b) {
        b.load(1023, 255);
        b.strobe(sc_time(105, SC_NS), 0x7FFF, sc_time(450, SC_NS));
        b.until(sc_time(700, SC_NS));
    });
    run(bench);
    EXPECT_EQ(report_log::get().count(msg::input), 1u);
    ASSERT_EQ(bench.samples.size(), 1u);
    expect_golden(bench.samples[0]);
    // (1 - 2^-15)^1023 = 0.9693: within 0.1 % of the real power.
    const double q = static_cast<double>(bench.samples[0].out[0]) / 256.0 / 255.0;
    EXPECT_NEAR(q, std::pow(0x7FFF / 32768.0, 1023), 0.001);
}

TEST(SqmulBadInput, CosAboveOneSaturatesToFullIntensity) {
    // cos > 1.0 is reported; saturate mode clamps the loaded cos to 1.0: every product stays 1.0.
    report_log::get().expect(msg::input);
    bench_t bench("tb", clk20, [](bench_t& b) {
        b.load(100, 201);
        b.strobe(sc_time(105, SC_NS), 0xC000, sc_time(450, SC_NS));
        b.strobe(sc_time(705, SC_NS), 0xFFFF, sc_time(450, SC_NS));
        b.until(sc_time(1300, SC_NS));
    });
    run(bench);
    EXPECT_EQ(report_log::get().count(msg::input), 2u);
    ASSERT_EQ(bench.samples.size(), 2u);
    for (const auto& s : bench.samples) EXPECT_EQ(s.out[0], 201u << 8);
}

TEST(SqmulBadInput, CosAboveOneInWrapModeIsReportedAndBitExact) {
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
    // n = 3 = 0b11, cos = 0xC000 = 1.5: the square 2.25 keeps 0.25 on its 19 wires (Q1.18, mod 2),
    // times 1.5 is 0.375 = 0x3000 on Q1.15.
    EXPECT_EQ(bench.samples[0].out[0], (uint64_t{0x3000} * 255u) >> 7);
}

TEST(SqmulConfig, ZeroDelaysAreAConfigurationError) {
    // With every delay zero, RG_P's own product would reach its input at the latching instant.
    report_log::get().expect(msg::config);
    report_log::get().expect(msg::setup);
    block_delays zero;
    zero.reg = zero.inverter = zero.adder = zero.multiplier = zero.rom = zero.gate = zero.mux = sc_core::SC_ZERO_TIME;
    bench_t bench("tb", clk20, [](bench_t&) {}, overflow_mode::saturate, zero);
    EXPECT_EQ(report_log::get().count(msg::config), 1u);
}

TEST(SqmulChecker, AMonitorSampleOffTheGoldenModelIsCaught) {
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
    EXPECT_EQ(s.out, golden_sqmul(20, s.cos, s.ksi, overflow_mode::saturate).out);
    EXPECT_NE(s.out, golden_sqmul(21, s.cos, s.ksi, overflow_mode::saturate).out);
}

namespace {

// The bench sqmul_tb's default run builds: a sphere's raster line of 48 pixels at n = 10, 100 and
// 1000 (Fig. 3 with 24 clocks per pixel), traced into `stem`.vcd.
void trace_default_run(const std::string& stem) {
    std::vector<uint32_t> line;
    for (double c : scene::sphere_line_cos(0.2, 48, 0.3, 0.4, 1.0)) line.push_back(scene::cos_code(c));
    std::vector<surface> s;
    for (unsigned n : {10u, 100u, 1000u}) s.push_back({n, {255, 180, 60}, line});
    specular_bench<sqmul_device> bench("tb", s, sqmul_timing(), golden(overflow_mode::saturate));
    vcd_file vcd(stem);
    vcd.trace(bench);
    sc_core::sc_start(bench.stim.duration() * 1.01 + sc_time(1, sc_core::SC_US));
    EXPECT_TRUE(bench.finished());
    EXPECT_EQ(bench.checker.samples(), 3u * 48u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
}

}  // namespace

TEST(SqmulTrace, VcdDeclaresTheDeviceNetsAndTheViewShowsOnlyThose) {
    const std::string stem = ::testing::TempDir() + "sqmul_trace";
    trace_default_run(stem);
    const auto declared = vcd_declared(stem + ".vcd");
    for (const char* net : {"tb.clk", "tb.ctl17", "tb.out29_valid", "tb.dut.rg1_n[9:0]", "tb.dut.z_lead[3:0]",
                            "tb.dut.f_frac[8:0]", "tb.dut.cos_p[18:0]", "tb.dut.p_brdf[18:0]",
                            "tb.dut.stage.mx_p_sel[1:0]", "tb.dut.stage.mx_b_sel", "tb.dut.stage.mul_p_product[18:0]",
                            "tb.dut.p_done", "tb.out25_r[16:0]", "tb.dut.stage.ctl_req",
                            "tb.dut.stage.sync17.stage1", "tb.dut.stage.sync17_req"})
        EXPECT_EQ(declared.count(std::string("SystemC.") + net), 1u) << net;
    for (const auto& n : declared) EXPECT_EQ(n.find(' '), std::string::npos) << n;
    const auto shown = gtkw_listed(source_path("traces/sqmul.gtkw"));
    EXPECT_GE(shown.size(), 25u);
    for (const auto& s : shown) EXPECT_EQ(declared.count(s), 1u) << s << " is in the view but not in the VCD";
}

TEST(SqmulTrace, GtkwaveViewReadsAtFirstSight) {
    // traces/sqmul.gtkw against the VCD of sqmul_tb's default run: dump file, marker inside the
    // window and off every edge, every bus a number in its format from src/floor/formats.
    const std::string stem = ::testing::TempDir() + "sqmul_view";
    trace_default_run(stem);
    view_formats f = specular_view_formats();
    for (const char* k : {"tb.dut.mul7_cos2", "tb.dut.inv8_not_cos", "tb.dut.add9_cos2_minus_cos",
                          "tb.dut.mul10_a_x_diff", "tb.dut.add11_brdf"})
        f.erase(k);
    f["tb.in16_n"] = f["tb.dut.rg1_n"] = sqmul::n_fmt;
    f["tb.dut.z_lead"] = qfmt{sqmul::z_width, false, 0};
    f["tb.dut.bsh1_mant"] = qfmt{sqmul::mant_fmt.width, false, 0};
    f["tb.dut.f_frac"] = qfmt{sqmul::f_fmt.width, false, 0};
    f["tb.dut.cos_aligned"] = f["tb.dut.cos_p"] = f["tb.dut.p_brdf"] = f["tb.dut.stage.mx_b_operand"] =
        f["tb.dut.stage.mul_p_product"] = f["tb.dut.stage.mx_p_next"] = sqmul::p_fmt;
    f["tb.dut.brdf_q15"] = spec::brdf_fmt;
    f["tb.dut.stage.mx_p_sel"] = qfmt{2, false, 0};
    const auto problems = view_problems(source_path("traces/sqmul.gtkw"), stem + ".vcd", "sqmul", f,
                                        {"tb.ctl17", "tb.clk", "tb.out29_valid", "tb.out25_r", "tb.out26_g",
                                         "tb.out27_b", "tb.dut.p_brdf", "tb.dut.stage.mx_p_sel"});
    EXPECT_TRUE(problems.empty()) << joined(problems);
}

}  // namespace test_sqmul_device
