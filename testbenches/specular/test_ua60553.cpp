#include <gtest/gtest.h>

#include "common/report_log.h"
#include "specular/specular_tb.h"
#include "ua60553.h"

using namespace shading;
using namespace shading::tb;

TEST(Smoke, Builds) {
    std::vector<surface> s{{10, {255, 128, 1}, {0, 0x4000, 0x8000}}};
    auto golden = [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        return golden_ua60553(n, c, k, overflow_mode::saturate);
    };
    specular_bench<device_ua60553> bench("tb", s, strobe_timing{}, golden, overflow_mode::saturate);
    sc_core::sc_start(sc_core::sc_time(1, sc_core::SC_US));
    EXPECT_TRUE(bench.finished());
    EXPECT_EQ(bench.checker.samples(), 3u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
}
