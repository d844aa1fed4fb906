// The squared-quadratic device's RTL twin (rtl/squared, verilated with --sc) co-simulated with the
// SystemC model (rtl_cosim_tb.h) on the same pins and clock, in both overflow modes: each RTL
// sample bit-exact against golden_squared and against the model's sample (inputs, instant,
// outputs) over every 16-bit cos code at n = 1, 3, 20, 1000, every n 0..1023 (cos codes near
// cos^n = 0.5, 0.1, 0.01), and 10^6 random pixels (four runs of 250 000, one ctest entry each, so
// each stays within seconds); the clocks per sample (output 29 rises k + 2 rising edges after the
// strobe) against the golden model's k; negative tests show that both comparisons can fail.
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

using namespace shading;
using namespace shading::tb;
using sc_core::SC_MS;
using sc_core::sc_time;

namespace {

template <typename T>
class RtlSquared : public ::testing::Test {
protected:
    using bench_t = rtl_cosim_bench<squared_device, typename T::rtl>;

    void SetUp() override { Verilated::traceEverOn(true); }

    // Runs the stream through both devices; every sample of each must match golden and the other.
    // With `falls` and `rises`: strobe 17's falls and the RTL's output-29 rise after each.
    void run(item_source<surface> surfaces, std::size_t expected_pixels, const strobe_timing& t = squared_timing(),
             std::vector<sc_time>* falls = nullptr, std::vector<sc_time>* rises = nullptr) {
        const auto golden = squared_golden(T::mode);
        bench_t bench("tb", std::move(surfaces), t, golden, golden, T::mode);
        latency_probe probe("probe");
        probe.ctl17(bench.ctl17);
        probe.out29_valid(bench.rtl_out29_valid);
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

}  // namespace

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

TYPED_TEST(RtlSquared, OutputTwentyNineRisesKPlusTwoRisingEdgesAfterTheStrobe) {
    // Strobe 17 low for 5 ns only: output 29 rises with done, at the (k + 2)-th rising edge of clk
    // after the strobe fell (k from the golden model), for every n 0..1023; the model's instant is
    // the RTL's plus the AND gate's delay (compared by the bench).
    report_log::get().expect(msg::input);
    std::vector<surface> s;
    for (unsigned n = 0; n < (1u << squared::n_fmt.width); ++n) s.push_back({n, {255, 255, 255}, {0x7000, 0x7F00}});
    const strobe_timing t = done_timing(24);  // k = 9: 11 edges
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
