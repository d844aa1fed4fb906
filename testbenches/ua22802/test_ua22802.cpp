// UA 22802 device (SystemC): its timing beside UA 60553's and its VCD. The tests every specular
// device shares (bit-exact against the golden model, every n, wrap mode, a wrong golden model
// caught) are typed tests in testbenches/specular/test_specular_devices.cpp. One elaboration per
// test (each runs in its own process under gtest_discover_tests).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <string>

#include "testbenches/common/report_log.h"
#include "testbenches/common/vcd_names.h"
#include "testbenches/specular/specular_view.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/specular/specular_tb.h"
#include "core/trace.h"
#include "ua22802/ua22802.h"
#include "arith/ua22802_arith.h"
#include "ua60553/ua60553.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_ua22802 {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_MS;
using sc_core::sc_time;

namespace {
specular_checker::golden_fn golden(overflow_mode mode) {
    return [mode](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        return golden_ua22802(n, c, k, mode);
    };
}
}  // namespace

TEST(UA22802, SameTimingAsUa60553AndShortStrobesAreReported) {
    // Both devices in one elaboration: the RG2 path (per pixel) and the RG1 path (per surface)
    // are the same, so the same strobe timing serves both.
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::mismatch);  // outputs sampled before they settle
    const unsigned before = report_log::get().count(msg::timing);
    device_ua60553 ref60553("ref60553");
    std::vector<surface> s{{300, {200, 100, 50}, {0x7000, 0x7800, 0x8000}}};
    strobe_timing t;
    t.t_low = sc_time(8, sc_core::SC_NS);  // RG2 -> outputs takes 0.2 + 3 + 1 + 3 + 1 + 3 = 11.2 ns
    specular_bench<device_ua22802> bench("tb", s, t, golden(overflow_mode::saturate));
    // ref60553 is not wired into a bench; its unbound ports would stop elaboration, so bind them.
    sc_core::sc_signal<bool> b[6];
    sc_core::sc_signal<n_t> n;
    sc_core::sc_signal<cos_t> c;
    sc_core::sc_signal<ksi_t> k[3];
    sc_core::sc_signal<out_t> o[3];
    ref60553.ctl15(b[0]); ref60553.ctl17(b[1]); ref60553.ctl20(b[2]); ref60553.ctl22(b[3]);
    ref60553.ctl24(b[4]); ref60553.out29_valid(b[5]); ref60553.in16_n(n); ref60553.in18_cos(c);
    ref60553.in19_ksi_r(k[0]); ref60553.in21_ksi_g(k[1]); ref60553.in23_ksi_b(k[2]);
    ref60553.out25_r(o[0]); ref60553.out26_g(o[1]); ref60553.out27_b(o[2]);
    ASSERT_TRUE(run_to_completion(bench, sc_time(1, SC_MS)));
    // The paths are derived at end of elaboration.
    EXPECT_EQ(bench.dut.chk_timing.path(0), ref60553.chk_timing.path(0));
    EXPECT_EQ(bench.dut.chk_timing.path(1), ref60553.chk_timing.path(1));
    EXPECT_EQ(bench.dut.chk_timing.path(1), sc_time(11.2, sc_core::SC_NS));
    EXPECT_EQ(bench.dut.chk_timing.violations(), 3u) << "every pixel's strobe is too short";
    EXPECT_EQ(report_log::get().count(msg::timing) - before, 3u);
    EXPECT_GE(bench.checker.mismatches(), 1u) << "unsettled outputs differ from the golden model";
}

TEST(UA22802Trace, MissingTraceFolderIsCreatedAndTheTestsVcdWritten) {
    // SHADING_TRACE names a folder that does not exist yet (README: SHADING_TRACE=/tmp/vcd): the run
    // creates it and writes <folder>/<Suite.Test>.vcd with the device's nets (SystemC's E701 for an
    // unopenable file used to abort the test).
    const std::string root = ::testing::TempDir() + "shading_trace_missing_folder";
    const std::string dir = root + "/vcd";
    std::filesystem::remove_all(root);
    ASSERT_FALSE(std::filesystem::exists(root));
    ASSERT_EQ(setenv("SHADING_TRACE", dir.c_str(), 1), 0);
    std::vector<surface> s{{5, {1, 2, 3}, {0x7000, 0x7100}}};
    specular_bench<device_ua22802> bench("tb", s, strobe_timing{}, golden(overflow_mode::saturate));
    ASSERT_TRUE(run_to_completion(bench, sc_time(1, SC_MS)));
    const std::string vcd = dir + "/UA22802Trace.MissingTraceFolderIsCreatedAndTheTestsVcdWritten.vcd";
    ASSERT_TRUE(std::filesystem::exists(vcd)) << vcd;
    const auto content = vcd_read(vcd);
    EXPECT_EQ(content.width.count("SystemC.tb.dut.rg2_cos[15:0]"), 1u);
    EXPECT_EQ(content.width.count("SystemC.tb.out25_r[16:0]"), 1u);
    EXPECT_GT(content.end, 0) << "no value changes were written";
    EXPECT_EQ(bench.checker.mismatches(), 0u);
}

TEST(UA22802, GtkwaveViewReadsAtFirstSight) {
    // traces/ua22802.gtkw against a VCD of the stream ua22802_tb writes up to its marker (n = 1, 2,
    // 3, 8, 48 pixels each, default strobes): dump file, marker inside the window and off every
    // edge, every bus a number in its format from src/floor/formats (vcd_names.h, view_problems).
    const std::string base = ::testing::TempDir() + "ua22802_view";
    std::vector<uint32_t> codes;
    for (uint32_t i = 0; i < 48; ++i) codes.push_back(0x0400 + 0x2A0 * i);
    std::vector<surface> s;
    for (unsigned n : {1u, 2u, 3u, 8u}) s.push_back({n, {255, 160, 48}, codes});
    {
        specular_bench<device_ua22802> bench("tb", s, strobe_timing{}, golden(overflow_mode::saturate));
        vcd_file vcd(base);
        vcd.trace(bench);
        ASSERT_TRUE(run_to_completion(bench, sc_time(1, SC_MS)));
        EXPECT_EQ(bench.checker.mismatches(), 0u);
    }
    view_formats f = specular_view_formats();
    f["tb.in16_n"] = f["tb.dut.rg1_n"] = ua22802::addr_fmt;
    f["tb.dut.a_coef"] = ua22802::a_fmt;
    const auto problems = view_problems(source_path("traces/ua22802.gtkw"), base + ".vcd", "ua22802", f,
                                        {"tb.ctl17", "tb.out29_valid", "tb.out25_r", "tb.out26_g", "tb.out27_b"});
    EXPECT_TRUE(problems.empty()) << joined(problems);
}

TEST(UA22802, GtkwaveSaveFileNamesEveryTracedNetItShows) {
    // traces/ua22802.gtkw is hand-written: every signal it lists must exist in the VCD the bench
    // writes (scope path + name + [msb:0]), or GTKWave silently drops it.
    const std::string vcd_base = ::testing::TempDir() + "ua22802_names";
    std::vector<surface> s{{5, {1, 2, 3}, {0x7000}}};
    specular_bench<device_ua22802> bench("tb", s, strobe_timing{}, golden(overflow_mode::saturate));
    {
        auto tf = std::make_unique<vcd_file>(vcd_base);
        tf->trace(bench);
        ASSERT_TRUE(run_to_completion(bench, sc_time(1, SC_MS)));
    }
    const auto traced = vcd_declared(vcd_base + ".vcd");
    ASSERT_GT(traced.size(), 20u);
    const auto shown = gtkw_listed(source_path("traces/ua22802.gtkw"));
    std::size_t listed = 0;
    for (const auto& line : shown) {
        ++listed;
        EXPECT_TRUE(traced.count(line)) << line << " is not in the VCD";
    }
    EXPECT_EQ(listed, 27u);
}

}  // namespace test_ua22802
