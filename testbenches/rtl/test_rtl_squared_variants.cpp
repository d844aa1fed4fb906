// The two designs the squared-quadratic device is compared with, verilated alone and checked
// bit-exact against their golden models on the device pins: the series variant
// (rtl/squared/squared_series_device.v: 9 squarers with bypass multiplexers, combinational, Fig. 3
// timing with no clock, no SystemC model; golden_squared) and the square-and-multiply device
// (rtl/sqmul/sqmul_device.v: one multiplier over the bits of n; golden_sqmul; co-simulated with its
// SystemC model in test_rtl_sqmul.cpp), both saturating
// (the synthesis table's variants; no range checker: n = 0, n > 1000 and cos > 1.0 are simply
// compared). Random pixels, every n 0..1023, every cos code at n = 1000, the baseline's clocks
// per sample for every n, and a negative test.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "core/report_ids.h"
#include "formats/squared_formats.h"
#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "rtl_squared_tb.h"
#include "testbenches/specular/specular_tb.h"
#include "verilated.h"

#include "Vrtl_sqmul_saturate.h"
#include "Vrtl_squared_series_saturate.h"

using namespace shading;
using namespace shading::tb;
using sc_core::SC_MS;
using sc_core::sc_time;

namespace {

constexpr auto sat = overflow_mode::saturate;

specular_checker::golden_fn series_golden() {
    return [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        datapath_nets r{};
        r.out = golden_squared(n, c, k, sat).out;
        return r;
    };
}

specular_checker::golden_fn sqmul_golden() {
    return [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        datapath_nets r{};
        r.out = golden_sqmul(n, c, k, sat).out;
        return r;
    };
}

// The RTL alone on the specular bench (stimulus, monitor, checker against `golden`); a latency
// probe on its strobe 17 and output 29. Returns the number of mismatches against golden.
template <typename Rtl>
std::size_t run_rtl(item_source<surface> surfaces, std::size_t expected_pixels, const strobe_timing& t,
                    specular_checker::golden_fn golden, latency_probe* probe = nullptr) {
    specular_bench<Rtl> bench("tb", std::move(surfaces), t, std::move(golden));
    if (probe != nullptr) {
        probe->ctl17(bench.ctl17);
        probe->out29_valid(bench.out29_valid);
    }
    EXPECT_TRUE(run_to_completion(bench, sc_time(10000, SC_MS)));
    EXPECT_EQ(bench.checker.samples(), expected_pixels);
    return bench.checker.mismatches();
}

std::vector<surface> every_n(std::vector<uint32_t> codes) {
    std::vector<surface> s;
    for (unsigned n = 0; n < (1u << squared::n_fmt.width); ++n) s.push_back({n, {255, 17, 96}, codes});
    return s;
}

std::vector<surface> every_cos_code(unsigned n) {
    std::vector<uint32_t> codes;
    for (uint64_t c = 0; c <= spec::cos_fmt.mask(); ++c) codes.push_back(static_cast<uint32_t>(c));
    return {{n, {255, 170, 3}, codes}};
}

class RtlSquaredVariants : public ::testing::Test {
protected:
    void SetUp() override { Verilated::traceEverOn(true); }
};

}  // namespace

// The series variant: Fig. 3's strobe timing (20 ns per pixel), no clock.
TEST_F(RtlSquaredVariants, SeriesRandom) {
    EXPECT_EQ(run_rtl<Vrtl_squared_series_saturate>(random_surfaces(250000, 11), 250000, strobe_timing{},
                                                   series_golden()), 0u);
}
TEST_F(RtlSquaredVariants, SeriesEveryN) {
    const auto s = every_n({0x4000, 0x6000, 0x7800, 0x7FF0, spec::cos_one});
    EXPECT_EQ(run_rtl<Vrtl_squared_series_saturate>(s, s.size() * 5, strobe_timing{}, series_golden()), 0u);
}
TEST_F(RtlSquaredVariants, SeriesEveryCosCodeAtN1000) {
    EXPECT_EQ(run_rtl<Vrtl_squared_series_saturate>(every_cos_code(1000), 65536, strobe_timing{}, series_golden()), 0u);
}

// The square-and-multiply baseline: 22 clocks per pixel (its longest result takes 20).
TEST_F(RtlSquaredVariants, SqmulRandom) {
    EXPECT_EQ(run_rtl<Vrtl_sqmul_saturate>(random_surfaces(250000, 12), 250000, sqmul_timing(), sqmul_golden()), 0u);
}
TEST_F(RtlSquaredVariants, SqmulEveryCosCodeAtN1000) {
    EXPECT_EQ(run_rtl<Vrtl_sqmul_saturate>(every_cos_code(1000), 65536, sqmul_timing(), sqmul_golden()), 0u);
}

TEST_F(RtlSquaredVariants, SqmulEveryNAndItsClocksPerSample) {
    // Every n 0..1023, bit-exact, with strobe 17 low for 5 ns: output 29 rises with done, at the
    // (squares + multiplies + 2)-th rising edge after the strobe fell (counts from golden_sqmul:
    // the taking edge, one per square and per multiplication, the done edge).
    const auto s = every_n({0x4000, 0x7800, spec::cos_one});
    const strobe_timing t = done_timing(42);  // n = 1023: 20 edges
    latency_probe probe("probe");
    EXPECT_EQ(run_rtl<Vrtl_sqmul_saturate>(s, s.size() * 3, t, sqmul_golden(), &probe), 0u);
    const auto ns = pixel_ns(s);
    ASSERT_EQ(probe.falls.size(), ns.size());
    ASSERT_EQ(probe.rises.size(), ns.size());
    unsigned wrong = 0;
    for (std::size_t i = 0; i < ns.size(); ++i) {
        const sc_time want = rising_edge_after(probe.falls[i], t.clk_period, sqmul_edges(ns[i]));
        if (probe.rises[i] != want && ++wrong <= 10)
            ADD_FAILURE() << "n = " << ns[i] << ": strobe fell at " << probe.falls[i] << ", output 29 rose at "
                          << probe.rises[i] << ", want " << want << " (" << sqmul_edges(ns[i]) << " rising edges)";
    }
    EXPECT_EQ(wrong, 0u);
    // Hand-worked: n = 1000 = 0b1111101000: 9 squares and 5 multiplications, 16 edges; n = 20: 7.
    EXPECT_EQ(sqmul_edges(1000), 16u);
    EXPECT_EQ(sqmul_edges(20), 7u);
}

TEST_F(RtlSquaredVariants, AnRtlThatDiffersFromItsGoldenIsCaught) {
    // Negative test: the baseline checked against the squared-quadratic law's golden model (another
    // approximation of cos^n) fails on every pixel.
    report_log::get().expect(msg::mismatch);
    std::vector<surface> s{{20, {255, 255, 255}, {0x7000, 0x7800, 0x7C00}}};
    EXPECT_EQ(run_rtl<Vrtl_sqmul_saturate>(s, 3, sqmul_timing(), series_golden()), 3u);
}
