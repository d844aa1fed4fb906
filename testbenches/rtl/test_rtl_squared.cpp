// The squared-quadratic device's RTL twin (rtl/squared, verilated with --sc) co-simulated with the
// SystemC model (rtl_cosim_tb.h) on the same pins and clock, in both overflow modes: each RTL
// sample bit-exact against golden_squared and against the model's sample (inputs, instant,
// outputs) over every 16-bit cos code at n = 1, 3, 20, 1000, every n 0..1023 (cos codes near
// cos^n = 0.5, 0.1, 0.01), and 10^6 random pixels (four runs of 250 000, one ctest entry each, so
// each stays within seconds); the clocks per sample (output 29 rises k + 4 rising edges after the
// strobe) against the golden model's k; strobe 17 at every phase of the clock, each pixel
// validated once with its own golden colour; negative tests show that both comparisons can fail.
// Dropped and restarted samples and bad inputs: test_rtl_squared_cover.cpp.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "core/report_ids.h"
#include "arith/squared_arith.h"
#include "rtl_cosim_tb.h"
#include "rtl_squared_tb.h"
#include "testbenches/squared/squared_cover.h"
#include "squared/squared_device.h"
#include "verilated.h"

// The Verilated devices (testbenches/rtl/CMakeLists.txt).
#include "Vrtl_squared_saturate.h"
#include "Vrtl_squared_wrap.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_rtl_squared {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_MS;
using sc_core::sc_time;

template <typename T>
class RtlSquared : public ::testing::Test {
protected:
    using bench_t = rtl_cosim_bench<squared_device, typename T::rtl>;

    void SetUp() override { Verilated::traceEverOn(true); }

    // Runs the stream through both devices; every sample of each must match golden and the other.
    // With `falls` and `rises`: strobe 17's falls and the RTL's output-29 rise after each.
    void run(item_source<surface> surfaces, std::size_t expected_pixels, const strobe_timing& t = squared_timing(),
             std::vector<sc_time>* falls = nullptr, std::vector<sc_time>* rises = nullptr,
             latency_probe* model_probe = nullptr, unsigned* rtl_extra_rises = nullptr) {
        const auto golden = squared_golden(T::mode);
        bench_t bench("tb", std::move(surfaces), t, golden, golden, T::mode);
        latency_probe probe("probe");
        probe.ctl17(bench.ctl17);
        probe.out29_valid(bench.rtl_out29_valid);
        if (model_probe != nullptr) {  // the SystemC model's output 29, beside the RTL's `probe`
            model_probe->ctl17(bench.ctl17);
            model_probe->out29_valid(bench.out29_valid);
        }
        const char* dir = std::getenv("SHADING_TRACE");
        const std::string stem = dir && *dir ? std::string(dir) + "/" + current_test_name() : std::string();
        ASSERT_TRUE(run_cosim(bench, sc_time(10000, SC_MS), stem));
        EXPECT_EQ(bench.checker.samples(), expected_pixels);
        EXPECT_EQ(bench.rtl_checker.samples(), expected_pixels);
        EXPECT_EQ(bench.pairs(), expected_pixels);
        EXPECT_EQ(bench.unpaired(), 0u);
        EXPECT_EQ(bench.checker.mismatches(), 0u) << "SystemC model against golden";
        EXPECT_EQ(bench.rtl_checker.mismatches(), 0u) << "RTL against golden";
        EXPECT_EQ(bench.cross_mismatches(), 0u) << "RTL against the SystemC model";
        EXPECT_EQ(bench.dut.stage().ctl_sq.dropped(), 0u) << "no strobe came before a result was valid";
        if (falls) *falls = probe.falls;
        if (rises) *rises = probe.rises;
        if (rtl_extra_rises) *rtl_extra_rises = probe.extra_rises;
    }

    // Strobe 17 at every phase of the clock (phase_sweep_timing): n = 1, 3, 20, 1000, `pixels`
    // each, every cos code its own. Both devices validate every pixel once, with its golden colour
    // (the bench: samples, golden, RTL against model), at the (k + 4)-th rising edge after its
    // strobe (squared_edges, counted by hand), never twice.
    void phase_sweep(const strobe_timing& t, std::size_t pixels) {
        const std::vector<unsigned> n{1, 3, 20, 1000};
        const auto s = phase_sweep_surfaces(n, pixels);
        const auto ns = pixel_ns(s);
        std::vector<sc_time> falls, rises;
        unsigned extra = 0;
        latency_probe model("model_probe");
        run(s, ns.size(), t, &falls, &rises, &model, &extra);
        EXPECT_EQ(phases_missed(falls, t.clk_period, sc_time(500, sc_core::SC_PS)), 0u) << "every 0.5 ns, edges included";
        EXPECT_EQ(phase_sweep_wrong(falls, rises, extra, ns, t.clk_period, sc_core::SC_ZERO_TIME, squared_edges), 0u)
            << "RTL";
        EXPECT_EQ(phase_sweep_wrong(model, ns, t.clk_period, sc_time(100, sc_core::SC_PS), squared_edges), 0u)
            << "SystemC model (output 29 a gate's delay, 0.1 ns, after the RTL's)";
    }

    void sweep(uint32_t first, uint64_t last) {
        std::vector<uint32_t> codes;
        for (uint64_t c = first; c <= last; ++c) codes.push_back(static_cast<uint32_t>(c));
        const std::vector<unsigned> ns{1, 3, 20, 1000};
        std::vector<surface> s;
        for (unsigned n : ns) s.push_back({n, {255, 170, 3}, codes});
        run(s, ns.size() * codes.size());
    }

    void random_run(uint64_t seed) {
        constexpr std::size_t pixels = 250000;
        run(random_surfaces(pixels, seed), pixels);
    }
};

using variants = ::testing::Types<squared_variant<Vrtl_squared_saturate, overflow_mode::saturate>,
                                  squared_variant<Vrtl_squared_wrap, overflow_mode::wrap>>;

TYPED_TEST_SUITE(RtlSquared, variants, squared_variant_names);

// Every cos code at n = 1 (no squaring), 3, 20 and 1000 (k = 1, 4, 9): up to 1.0, then above it
// (reported by the model's range checker; ADD11 saturates to k_s*I or passes the wrapped bits on,
// and the RTL must agree either way).
TYPED_TEST(RtlSquared, EveryCosCodeUpToOne) { this->sweep(0, spec::cos_one); }
TYPED_TEST(RtlSquared, EveryCosCodeAboveOne) {
    report_log::get().expect(msg::input);
    this->sweep(spec::cos_one + 1, spec::cos_fmt.mask());
}

TYPED_TEST(RtlSquared, EveryNIncludingOutOfRange) {
    // Every n the generator sees (0..1023: n = 0 and 1001..1023 reported by the model's range
    // checker, once per load), each with the cos codes whose cos^n lies near 0.5, 0.1 and 0.01 and
    // two neighbours either side (squared_cover.h), and 0.5, 0.75, 0.9375, 1.0.
    report_log::get().expect(msg::input);
    const auto s = level_surfaces(0, (1u << squared::n_fmt.width) - 1);
    this->run(s, pixel_ns(s).size());
    EXPECT_EQ(report_log::get().count(msg::input), input_reports(s));
    // The codes reach the generator's whole range: at each n and level the nearest code's result is
    // neither 0 nor full scale (golden_squared: 0 < out < the output at cos = 1.0).
    unsigned flat = 0;
    for (const auto& x : s)
        for (double level : cos_pow_levels()) {
            const uint32_t c = cos_codes_near_levels(x.n, {level}, 0).front();
            const uint64_t out = golden_squared(x.n, c, {255, 0, 0}, TypeParam::mode).out[0];
            const uint64_t full = golden_squared(x.n, spec::cos_one, {255, 0, 0}, TypeParam::mode).out[0];
            if ((out == 0 || out >= full) && ++flat <= 10)
                ADD_FAILURE() << "n = " << x.n << ", level " << level << ": cos 0x" << std::hex << c << " gives " << out;
        }
    EXPECT_EQ(flat, 0u);
}

TYPED_TEST(RtlSquared, OutputTwentyNineRisesKPlusFourRisingEdgesAfterTheStrobe) {
    // Strobe 17 low for 5 ns only: output 29 rises with done, at the (k + 4)-th rising edge of clk
    // after the strobe fell (k from the golden model; squared_edges counts the synchroniser's two),
    // for every n 0..1023; the model's instant is the RTL's plus the AND gate's delay (compared by
    // the bench).
    report_log::get().expect(msg::input);
    std::vector<surface> s;
    for (unsigned n = 0; n < (1u << squared::n_fmt.width); ++n) s.push_back({n, {255, 255, 255}, {0x7000, 0x7F00}});
    const strobe_timing t = done_timing(26);  // k = 9: 13 edges
    std::vector<sc_time> falls, rises;
    this->run(s, s.size() * 2, t, &falls, &rises);
    const auto ns = pixel_ns(s);
    ASSERT_EQ(falls.size(), ns.size());
    ASSERT_EQ(rises.size(), ns.size());
    unsigned wrong = 0;
    for (std::size_t i = 0; i < ns.size(); ++i) {
        const sc_time want = rising_edge_after(falls[i], t.clk_period, squared_edges(ns[i]));
        if (rises[i] != want && ++wrong <= 10)
            ADD_FAILURE() << "n = " << ns[i] << ": strobe fell at " << falls[i] << ", output 29 rose at " << rises[i]
                          << ", want " << want << " (" << squared_edges(ns[i]) << " rising edges)";
    }
    EXPECT_EQ(wrong, 0u);
}

// Strobe 17 at every phase of a 20 ns clock, in 0.5 ns steps (41 pixels per n: one whole period
// and its edges), each pixel period 28 clocks + 0.5 ns (twice the 13 edges of the longest result,
// and more: the next surface's loads come half a pixel after the strobe).
TYPED_TEST(RtlSquared, StrobeSeventeenAtEveryPhaseOfTheClock) {
    this->phase_sweep(phase_sweep_timing(28, sc_time(500, sc_core::SC_PS), sc_time(20, sc_core::SC_NS)), 41);
}
// The same with a 25 % duty cycle (high 5 ns) and with a 7 ns clock (the shortest 0.5 ns grid
// the phase rules allow: low 3.5 ns > 3.2 ns), saturating.
TYPED_TEST(RtlSquared, StrobeSeventeenAtEveryPhaseOfAQuarterDutyClock) {
    this->phase_sweep(phase_sweep_timing(28, sc_time(500, sc_core::SC_PS), sc_time(20, sc_core::SC_NS), 0.25), 41);
}
TYPED_TEST(RtlSquared, StrobeSeventeenAtEveryPhaseOfASevenNanosecondClock) {
    this->phase_sweep(phase_sweep_timing(28, sc_time(500, sc_core::SC_PS), sc_time(7, sc_core::SC_NS)), 15);
}

// 10^6 random pixels per mode, in four runs (random_surfaces: n 1..1000, k_s*I 0..255 reloaded at
// random between surfaces of 1..16 pixels, cos 0..1.0).
TYPED_TEST(RtlSquared, Random0) { this->random_run(1); }
TYPED_TEST(RtlSquared, Random1) { this->random_run(2); }
TYPED_TEST(RtlSquared, Random2) { this->random_run(3); }
TYPED_TEST(RtlSquared, Random3) { this->random_run(4); }

TEST(RtlSquaredCheck, AnRtlThatDiffersFromTheModelIsCaught) {
    // Negative test: the wrapping RTL beside the saturating model, each checked against its own
    // golden model, at cos above 1.0 (saturate: k_s*I; wrap: the low wires): only the
    // RTL-against-model comparison fails, 3 times.
    Verilated::traceEverOn(true);
    report_log::get().expect(msg::mismatch);
    report_log::get().expect(msg::input);
    std::vector<surface> s{{20, {255, 255, 255}, {0x9000, 0xA000, 0xC000}}};
    rtl_cosim_bench<squared_device, Vrtl_squared_wrap> bench("tb", s, squared_timing(),
                                                             squared_golden(overflow_mode::saturate),
                                                             squared_golden(overflow_mode::wrap), overflow_mode::saturate);
    ASSERT_TRUE(run_cosim(bench, sc_time(1, SC_MS)));
    EXPECT_EQ(bench.pairs(), 3u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.rtl_checker.mismatches(), 0u);
    EXPECT_EQ(bench.cross_mismatches(), 3u);
    EXPECT_EQ(report_log::get().count(msg::mismatch), 3u);
}

TEST(RtlSquaredCheck, AnRtlThatDiffersFromGoldenIsCaught) {
    // Negative test: the RTL checked against the golden model of the next n fails on every pixel.
    Verilated::traceEverOn(true);
    report_log::get().expect(msg::mismatch);
    std::vector<surface> s{{20, {255, 255, 255}, {0x7000, 0x7800, 0x7C00}}};
    rtl_cosim_bench<squared_device, Vrtl_squared_saturate> bench(
        "tb", s, squared_timing(), squared_golden(overflow_mode::saturate),
        squared_golden(overflow_mode::saturate, 1), overflow_mode::saturate);
    ASSERT_TRUE(run_cosim(bench, sc_time(1, SC_MS)));
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.rtl_checker.mismatches(), 3u);
    EXPECT_EQ(bench.cross_mismatches(), 0u);
    EXPECT_EQ(report_log::get().count(msg::mismatch), 3u);
}

}  // namespace test_rtl_squared
