// The square-and-multiply device's RTL twin (rtl/sqmul, verilated with --sc) co-simulated with the
// SystemC block model (sqmul/sqmul_device.h; rtl_cosim_tb.h) on the same pins and clock, in both
// overflow modes: each RTL sample bit-exact against golden_sqmul and against the model's sample
// (inputs, instant of output 29's rise, outputs) over every 16-bit cos code at n = 1, 3, 20, 1023,
// every n 0..1023 with the cos codes where cos^n is near 0.5, 0.1 and 0.01, random pixels, and a
// stream whose strobes come before the long walks are done (dropped, restarted); the clocks per
// sample against floor(log2 n) + popcount(n) + 3 (strobe 17's request crossing the synchroniser
// sync17 in both); negative tests show both comparisons can fail.
// Random pixels: 10^6 per mode in four runs of 250 000 (one ctest entry each).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "core/report_ids.h"
#include "arith/sqmul_arith.h"
#include "rtl_cosim_tb.h"
#include "rtl_squared_tb.h"
#include "sqmul/sqmul_device.h"
#include "verilated.h"

// The Verilated devices (testbenches/rtl/CMakeLists.txt).
#include "Vrtl_sqmul_saturate.h"
#include "Vrtl_sqmul_wrap.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_rtl_sqmul {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_MS;
using sc_core::sc_time;

namespace {

template <typename Rtl, overflow_mode Mode>
struct variant {
    using rtl = Rtl;
    static constexpr overflow_mode mode = Mode;
};

specular_checker::golden_fn sqmul_golden_fn(overflow_mode m, unsigned n_offset = 0) {
    return [m, n_offset](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        datapath_nets r{};
        r.out = golden_sqmul(n + n_offset, c, k, m).out;
        return r;
    };
}

// Rising edges from strobe 17's fall to done, worked out here (not from a model): sync17's two,
// the taking edge, floor(log2 n) squares and popcount(n) - 1 multiplications, the done edge:
// floor(log2 n) + popcount(n) + 3, n = 0 read as 1.
unsigned walk_edges(unsigned n) {
    if (n == 0) n = 1;
    unsigned log2 = 0, ones = 0;
    for (unsigned v = n; v > 1; v >>= 1) ++log2;
    for (unsigned v = n; v != 0; v >>= 1) ones += v & 1u;
    return log2 + ones + 3;
}

template <typename T>
class RtlSqmul : public ::testing::Test {
protected:
    using bench_t = rtl_cosim_bench<sqmul_device, typename T::rtl>;

    void SetUp() override { Verilated::traceEverOn(true); }

    struct result {
        std::vector<sc_time> falls, rises;  // strobe 17's falls, the RTL's output-29 rise after each
        unsigned dropped = 0;               // the model's dropped strobes
    };

    // Runs the stream through both devices; every sample of each must match golden and the other.
    result run(item_source<surface> surfaces, std::size_t expected_pixels, const strobe_timing& t = sqmul_timing()) {
        const auto golden = sqmul_golden_fn(T::mode);
        bench_t bench("tb", std::move(surfaces), t, golden, golden, T::mode);
        latency_probe probe("probe");
        probe.ctl17(bench.ctl17);
        probe.out29_valid(bench.rtl_out29_valid);
        const char* dir = std::getenv("SHADING_TRACE");
        const std::string stem = dir && *dir ? std::string(dir) + "/" + current_test_name() : std::string();
        EXPECT_TRUE(run_cosim(bench, sc_time(10000, SC_MS), stem));
        EXPECT_EQ(bench.checker.samples(), expected_pixels);
        EXPECT_EQ(bench.rtl_checker.samples(), expected_pixels);
        EXPECT_EQ(bench.pairs(), expected_pixels);
        EXPECT_EQ(bench.unpaired(), 0u);
        EXPECT_EQ(bench.checker.mismatches(), 0u) << "SystemC model against golden";
        EXPECT_EQ(bench.rtl_checker.mismatches(), 0u) << "RTL against golden";
        EXPECT_EQ(bench.cross_mismatches(), 0u) << "RTL against the SystemC model";
        return {probe.falls, probe.rises, bench.dut.stage.ctl.dropped()};
    }

    void sweep(uint32_t first, uint64_t last) {
        std::vector<uint32_t> codes;
        for (uint64_t c = first; c <= last; ++c) codes.push_back(static_cast<uint32_t>(c));
        const std::vector<unsigned> ns{1, 3, 20, 1023};
        std::vector<surface> s;
        for (unsigned n : ns) s.push_back({n, {255, 170, 3}, codes});
        EXPECT_EQ(run(s, ns.size() * codes.size()).dropped, 0u);
    }

    void random_run(uint64_t seed) {
        constexpr std::size_t pixels = 250000;
        EXPECT_EQ(run(random_surfaces(pixels, seed), pixels).dropped, 0u);
    }
};

struct names {
    template <typename T>
    static std::string GetName(int) {
        return T::mode == overflow_mode::saturate ? "Saturate" : "Wrap";
    }
};

using variants = ::testing::Types<variant<Vrtl_sqmul_saturate, overflow_mode::saturate>,
                                  variant<Vrtl_sqmul_wrap, overflow_mode::wrap>>;

}  // namespace

TYPED_TEST_SUITE(RtlSqmul, variants, names);

// Every cos code at n = 1 (no step), 3, 20 and 1023 (the longest walk): up to 1.0, then above it
// (reported by the model's range checker; the loaded cos is clamped to 1.0 or kept as it is, and
// the RTL must agree either way).
TYPED_TEST(RtlSqmul, EveryCosCodeUpToOne) {
    report_log::get().expect(msg::input);  // n = 1023
    this->sweep(0, spec::cos_one);
}
TYPED_TEST(RtlSqmul, EveryCosCodeAboveOne) {
    report_log::get().expect(msg::input);
    this->sweep(spec::cos_one + 1, spec::cos_fmt.mask());
}

TYPED_TEST(RtlSqmul, EveryNWithCosCodesNearHalfATenthAndAHundredth) {
    // Every n the controller sees (0..1023: n = 0 and 1001..1023 reported by the model's range
    // checker), the codes one below, at and one above cos = level^(1/n) for each level.
    report_log::get().expect(msg::input);
    std::vector<surface> s;
    for (unsigned n = 0; n < (1u << sqmul::n_fmt.width); ++n) {
        std::vector<uint32_t> codes;
        for (double level : {0.5, 0.1, 0.01}) {
            const auto c = static_cast<uint32_t>(std::lround(std::pow(level, 1.0 / std::max(n, 1u)) * spec::cos_one));
            for (uint32_t d : {c - 1, c, c + 1}) codes.push_back(std::min<uint32_t>(d, spec::cos_one));
        }
        s.push_back({n, {255, 17, 96}, codes});
    }
    EXPECT_EQ(this->run(s, s.size() * 9).dropped, 0u);
}

TYPED_TEST(RtlSqmul, OutputTwentyNineRisesAfterTheWalkForEveryN) {
    // Strobe 17 low for 5 ns only: output 29 rises with done, at the (floor(log2 n) + popcount(n)
    // + 3)-th rising edge of clk after the strobe fell, for every n 0..1023; the model's instant is
    // the RTL's plus the AND gate's delay (compared by the bench for every sample).
    report_log::get().expect(msg::input);
    std::vector<surface> s;
    for (unsigned n = 0; n < (1u << sqmul::n_fmt.width); ++n) s.push_back({n, {255, 255, 255}, {0x7000, 0x7F00}});
    const strobe_timing t = done_timing(44);  // n = 1023: 22 edges
    const auto r = this->run(s, s.size() * 2, t);
    const auto ns = pixel_ns(s);
    ASSERT_EQ(r.falls.size(), ns.size());
    ASSERT_EQ(r.rises.size(), ns.size());
    unsigned wrong = 0;
    for (std::size_t i = 0; i < ns.size(); ++i) {
        const sc_time want = rising_edge_after(r.falls[i], t.clk_period, walk_edges(ns[i]));
        if (r.rises[i] != want && ++wrong <= 10)
            ADD_FAILURE() << "n = " << ns[i] << ": strobe fell at " << r.falls[i] << ", output 29 rose at " << r.rises[i]
                          << ", want " << want << " (" << walk_edges(ns[i]) << " rising edges)";
    }
    EXPECT_EQ(wrong, 0u);
    // Hand-worked: n = 20 = 0b10100: 2 + 1 + 4 squares + 1 multiplication + 1 = 9 edges;
    // n = 1000 = 0b1111101000: 2 + 1 + 9 + 5 + 1 = 18.
    EXPECT_EQ(walk_edges(20), 9u);
    EXPECT_EQ(walk_edges(1000), 18u);
}

TYPED_TEST(RtlSqmul, StrobesBeforeTheResultIsValidAreDroppedAlike) {
    // A pixel every 12 clocks (strobe 17 low 5 ns): walks of at most 6 edges (n = 0..4; done at
    // most 19.5 + 5 * 20 ns after the strobe) finish within the period, before the next surface
    // reloads RG1 (122.5 ns after it); walks of 15 edges or more (n = 95 = 0b1011111 the least; done
    // at least 14 * 20 ns after the strobe) are always abandoned by the next strobe (dropped,
    // reported; restarted with the new cos), also across a surface change (12 clocks + the 32 ns of
    // loads, 272 ns). Both devices must validate the same samples at the same instants; the model's
    // dropped count is the number of long walks a later strobe followed, worked out from the stream.
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::input);
    std::mt19937 rng(17);
    std::vector<unsigned> short_ns{0, 1, 2, 3, 4}, long_ns;
    for (unsigned n = 5; n < 1024; ++n)
        if (walk_edges(n) >= 15) long_ns.push_back(n);
    std::vector<surface> s;
    std::size_t short_pixels = 0, long_pixels = 0;
    std::uniform_int_distribution<uint32_t> code(0, spec::cos_one);
    for (unsigned i = 0; i < 60; ++i) {
        const bool is_long = i % 3 != 0;
        const auto& pool = is_long ? long_ns : short_ns;
        surface x{pool[rng() % pool.size()], {static_cast<unsigned>(rng() % 256), 255, 7}, {}};
        for (unsigned k = 1 + rng() % 6; k > 0; --k) x.cos_codes.push_back(code(rng));
        (is_long ? long_pixels : short_pixels) += x.cos_codes.size();
        s.push_back(x);
    }
    const bool last_long = walk_edges(s.back().n) >= 15;
    const auto r = this->run(s, short_pixels, done_timing(12));
    EXPECT_GT(long_pixels, 50u);
    EXPECT_EQ(r.dropped, long_pixels - (last_long ? 1 : 0)) << "every long walk but a final one";
    EXPECT_EQ(r.rises.size(), short_pixels);
}

// Random pixels per mode, in four runs (random_surfaces: n 1..1000, k_s*I 0..255 reloaded at
// random between surfaces of 1..16 pixels, cos 0..1.0).
TYPED_TEST(RtlSqmul, Random0) { this->random_run(1); }
TYPED_TEST(RtlSqmul, Random1) { this->random_run(2); }
TYPED_TEST(RtlSqmul, Random2) { this->random_run(3); }
TYPED_TEST(RtlSqmul, Random3) { this->random_run(4); }

TEST(RtlSqmulCheck, AnRtlThatDiffersFromTheModelIsCaught) {
    // Negative test: the wrapping RTL beside the saturating model, each checked against its own
    // golden model, at cos above 1.0 (saturate: k_s*I; wrap: the low wires): only the
    // RTL-against-model comparison fails, 3 times.
    Verilated::traceEverOn(true);
    report_log::get().expect(msg::mismatch);
    report_log::get().expect(msg::input);
    std::vector<surface> s{{20, {255, 255, 255}, {0x9000, 0xA000, 0xC000}}};
    rtl_cosim_bench<sqmul_device, Vrtl_sqmul_wrap> bench("tb", s, sqmul_timing(), sqmul_golden_fn(overflow_mode::saturate),
                                                         sqmul_golden_fn(overflow_mode::wrap), overflow_mode::saturate);
    ASSERT_TRUE(run_cosim(bench, sc_time(1, SC_MS)));
    EXPECT_EQ(bench.pairs(), 3u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.rtl_checker.mismatches(), 0u);
    EXPECT_EQ(bench.cross_mismatches(), 3u);
    EXPECT_EQ(report_log::get().count(msg::mismatch), 3u);
}

TEST(RtlSqmulCheck, AnRtlThatDiffersFromGoldenIsCaught) {
    // Negative test: the RTL checked against the golden model of the next n fails on every pixel.
    Verilated::traceEverOn(true);
    report_log::get().expect(msg::mismatch);
    std::vector<surface> s{{20, {255, 255, 255}, {0x7000, 0x7800, 0x7C00}}};
    rtl_cosim_bench<sqmul_device, Vrtl_sqmul_saturate> bench("tb", s, sqmul_timing(),
                                                             sqmul_golden_fn(overflow_mode::saturate),
                                                             sqmul_golden_fn(overflow_mode::saturate, 1),
                                                             overflow_mode::saturate);
    ASSERT_TRUE(run_cosim(bench, sc_time(1, SC_MS)));
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.rtl_checker.mismatches(), 3u);
    EXPECT_EQ(bench.cross_mismatches(), 0u);
    EXPECT_EQ(report_log::get().count(msg::mismatch), 3u);
}

}  // namespace test_rtl_sqmul
