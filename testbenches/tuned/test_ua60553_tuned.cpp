// The tuned UA 60553 variant (SystemC): the patent's constants on its generator, its RG1 path and
// the second named generator. The tests every specular device shares are typed tests in
// testbenches/specular/test_specular_devices.cpp. One elaboration per test.
#include <gtest/gtest.h>

#include <random>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/specular/specular_tb.h"
#include "ua60553/ua60553.h"
#include "tuned/ua60553_tuned.h"
#include "arith/ua60553_tuned_arith.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_ua60553_tuned {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_MS;
using sc_core::sc_time;

namespace {
specular_checker::golden_fn golden(overflow_mode mode) {
    return [mode](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        return golden_ua60553_tuned(n, c, k, mode);
    };
}
std::vector<uint32_t> random_codes(std::mt19937& rng, std::size_t k, uint32_t hi) {
    std::uniform_int_distribution<uint32_t> d(0, hi);
    std::vector<uint32_t> v{0, spec::cos_one};
    while (v.size() < k) v.push_back(d(rng));
    return v;
}
}  // namespace

TEST(UA60553Tuned, PatentConstantsWithoutSpecialCaseMatchDeviceUa60553ForNAtLeast2) {
    // The variant with the patent's constants differs from device_ua60553 only below n = 2:
    // checked against the UA 60553 golden model for n >= 2.
    const ua60553::tuned_generator as_patent{"p", "1100101", "1000000", false};
    std::mt19937 rng(31);
    std::vector<surface> s;
    for (unsigned n : {2u, 5u, 77u, 1000u}) s.push_back({n, {255, 255, 255}, random_codes(rng, 200, spec::cos_one)});
    specular_bench<device_ua60553_tuned> bench(
        "tb", s, strobe_timing{},
        [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
            return golden_ua60553(n, c, k, overflow_mode::saturate);
        },
        overflow_mode::saturate, as_patent);
    ASSERT_TRUE(run_to_completion(bench, sc_time(10, SC_MS)));
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.checker.samples(), 800u);
}

TEST(UA60553Tuned, RgOnePathIncludesTheKeyBlockAndShortStrobesAreReported) {
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::mismatch);
    std::vector<surface> s{{1, {255, 255, 255}, {0x6000, 0x7000}}};
    strobe_timing t;
    t.t_low = sc_time(10, sc_core::SC_NS);  // RG2 -> outputs takes 11.2 ns
    specular_bench<device_ua60553_tuned> bench("tb", s, t, golden(overflow_mode::saturate));
    ASSERT_TRUE(run_to_completion(bench, sc_time(1, SC_MS)));
    // RG1 -> MUL6 -> ADD15 -> key block -> MUL10 -> ADD11 -> MUL12: 0.2 + 3 + 1 + 0.1 + 3 + 1 + 3.
    EXPECT_EQ(bench.dut.chk_timing.path(0), sc_time(11.3, sc_core::SC_NS));
    EXPECT_EQ(bench.dut.chk_timing.violations(), 2u);
}

TEST(UA60553Tuned, RomMatchedGeneratorBitExactAgainstItsGolden) {
    // The second named generator on the same device: node 32 = -0.1001001b = -73/128.
    std::mt19937 rng(22802);
    std::vector<surface> s;
    for (unsigned n : {1u, 2u, 3u, 30u, 31u, 1000u}) s.push_back({n, {255, 40, 3}, random_codes(rng, 500, spec::cos_one)});
    specular_bench<device_ua60553_tuned> bench(
        "tb", s, strobe_timing{},
        [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
            return golden_ua60553_tuned(n, c, k, overflow_mode::saturate, ua60553::rom_matched);
        },
        overflow_mode::saturate, ua60553::rom_matched);
    ASSERT_TRUE(run_to_completion(bench, sc_time(10, SC_MS)));
    EXPECT_EQ(bench.checker.samples(), 3000u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.dut.a_gen.node32_k.read().to_uint64(), 0x100u - 73u) << "-0.5703125 on the Q1.7 bus";
    EXPECT_EQ(bench.dut.a_coef.read().to_uint64(), 1000u * 101u - 73u);
}

}  // namespace test_ua60553_tuned
