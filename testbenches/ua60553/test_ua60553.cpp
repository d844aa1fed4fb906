// The cycle-accurate UA 60553 device against its golden model, its timing checker and its
// bad-input handling. Each TEST elaborates one bench: ctest runs each in its own process.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "testbenches/common/report_log.h"
#include "testbenches/common/vcd_names.h"
#include "testbenches/specular/specular_view.h"
#include "core/report_ids.h"
#include "testbenches/specular/specular_tb.h"
#include "core/trace.h"
#include "ua60553/ua60553.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_ua60553 {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_NS;
using sc_core::SC_PS;
using sc_core::sc_time;

namespace {

using bench_t = specular_bench<device_ua60553>;

specular_checker::golden_fn golden_for(overflow_mode mode) {
    return [mode](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        return golden_ua60553(n, c, k, mode);
    };
}

std::vector<uint32_t> codes(uint32_t first, uint32_t last) {
    std::vector<uint32_t> v;
    for (uint32_t c = first; c <= last; ++c) v.push_back(c);
    return v;
}

// Runs the bench to the end of its stimulus, with a watchdog on simulated time. With
// SHADING_TRACE=<dir>, writes <dir>/<Suite.Test>.vcd (one name per test: ctest runs in parallel).
void run(bench_t& bench) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    for (char& ch : name)
        if (ch == '/') ch = '_';
    auto vcd = vcd_from_env(name);
    if (vcd) vcd->trace(bench);
    const sc_time limit = bench.stim.duration() * 1.01 + sc_time(1, sc_core::SC_US);
    sc_core::sc_start(limit);
    ASSERT_TRUE(bench.finished()) << "stimulus did not finish within " << limit;
    EXPECT_EQ(bench.checker.samples(), bench.stim.pixels()) << "the monitor dropped samples";
}

}  // namespace

// Every cos code 0..1.0 at n in {1, 2, 10, 100, 1000}, in both overflow modes.
class UA60553Exhaustive : public ::testing::TestWithParam<std::tuple<unsigned, overflow_mode>> {};

TEST_P(UA60553Exhaustive, EveryCosCodeBitExactAgainstTheGoldenModel) {
    const auto [n, mode] = GetParam();
    std::vector<surface> s{{n, {255, 170, 1}, codes(0, spec::cos_one)}};
    strobe_timing t;
    bench_t bench("tb", s, t, golden_for(mode), mode);
    run(bench);
    EXPECT_EQ(bench.checker.samples(), spec::cos_one + 1);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
}

INSTANTIATE_TEST_SUITE_P(
    NAndMode, UA60553Exhaustive,
    ::testing::Combine(::testing::Values(1u, 2u, 10u, 100u, 1000u),
                       ::testing::Values(overflow_mode::saturate, overflow_mode::wrap)),
    [](const auto& info) {
        return "n" + std::to_string(std::get<0>(info.param)) +
               (std::get<1>(info.param) == overflow_mode::saturate ? "_saturate" : "_wrap");
    });

// Random (n, cos, k_s*I) triples: every pixel reloads RG1 and RG3..RG5 first, as a new surface.
class UA60553Random : public ::testing::TestWithParam<overflow_mode> {};

TEST_P(UA60553Random, RandomTriplesBitExact) {
    std::mt19937 rng(60553);
    std::uniform_int_distribution<unsigned> n(1, 1000), c(0, spec::cos_one), k(0, 255);
    std::vector<surface> s;
    for (int i = 0; i < 3000; ++i) s.push_back({n(rng), {k(rng), k(rng), k(rng)}, {c(rng), c(rng)}});
    strobe_timing t;
    bench_t bench("tb", s, t, golden_for(GetParam()), GetParam());
    run(bench);
    EXPECT_EQ(bench.checker.samples(), 6000u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Mode, UA60553Random, ::testing::Values(overflow_mode::saturate, overflow_mode::wrap),
                         [](const auto& info) {
                             return info.param == overflow_mode::saturate ? "saturate" : "wrap";
                         });

// Fig. 3: the phase between latching and validating edge must exceed the critical path
// RG2 -> MUL7 -> ADD9 -> MUL10 -> ADD11 -> MUL12. With the default delays that is
// 0.2 + 3 + 1 + 3 + 1 + 3 = 11.2 ns (hand sum).
TEST(UA60553Timing, CriticalPathIsTheHandSumOfTheDefaultDelays) {
    std::vector<surface> s{{10, {255, 255, 255}, {0x7000}}};
    bench_t bench("tb", s, strobe_timing{}, golden_for(overflow_mode::saturate));
    sc_core::sc_start(sc_core::SC_ZERO_TIME);  // the paths are derived at end of elaboration
    const auto& dut = bench.dut;
    EXPECT_EQ(dut.rg2_to_outputs(), sc_time(11200, SC_PS));
    EXPECT_EQ(dut.chk_timing.critical_path(1).to_string(),
              "rg2 -> mul7 -> add9 -> mul10 -> add11 -> mul12 = 11.2 ns");
    EXPECT_EQ(dut.chk_timing.path(0), sc_time(11200, SC_PS));  // RG1 -> MUL6 -> ADD15 -> MUL10 ...
    EXPECT_EQ(dut.chk_timing.path(2), sc_time(3200, SC_PS));   // RG3 -> MUL12
}

TEST(UA60553Timing, StrobeOnePicosecondLongerThanTheCriticalPathIsSilentAndCorrect) {
    strobe_timing t;
    t.t_low = sc_time(11201, SC_PS);
    std::vector<surface> s{{100, {255, 255, 255}, codes(0x7000, 0x8000)}};
    bench_t bench("tb", s, t, golden_for(overflow_mode::saturate));
    run(bench);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.dut.chk_timing.violations(), 0u);
    EXPECT_EQ(report_log::get().count(msg::timing), 0u);
}

TEST(UA60553Timing, StrobeOnePicosecondShorterThanTheCriticalPathIsReported) {
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::mismatch);  // the outputs really are not settled
    strobe_timing t;
    t.t_low = sc_time(11199, SC_PS);
    std::vector<surface> s{{100, {255, 255, 255}, codes(0x7000, 0x7100)}};
    bench_t bench("tb", s, t, golden_for(overflow_mode::saturate));
    run(bench);
    EXPECT_EQ(bench.dut.chk_timing.violations(), 0x101u) << "one report per validating edge";
    EXPECT_EQ(report_log::get().count(msg::timing), 0x101u);
    EXPECT_GT(bench.checker.mismatches(), 0u) << "a too-short strobe samples unsettled outputs";
}

TEST(UA60553Timing, SurfaceLoadTooCloseToTheValidatingEdgeIsReported) {
    // RG1 -> MUL6 -> ADD15 -> MUL10 -> ADD11 -> MUL12 also takes 11.2 ns: a load pulse that ends
    // 10 ns before the first validating edge is too late.
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::mismatch);
    strobe_timing t;
    t.t_low = sc_time(4, SC_NS);
    t.load_pulse = sc_time(1, SC_NS);
    std::vector<surface> s{{1000, {255, 255, 255}, {0x7800}}};
    bench_t bench("tb", s, t, golden_for(overflow_mode::saturate));
    run(bench);
    EXPECT_GE(bench.dut.chk_timing.violations(), 1u);
}

// Bad inputs: each gets a report and the documented result.
TEST(UA60553BadInput, NZeroIsReportedAndGivesAEqualToK32) {
    report_log::get().expect(msg::input);
    std::vector<surface> s{{0, {255, 255, 255}, {0x0000, 0x4000, 0x6000, 0x8000}}};
    strobe_timing t;
    bench_t bench("tb", s, t, golden_for(overflow_mode::saturate));
    run(bench);
    EXPECT_EQ(report_log::get().count(msg::input), 1u);
    EXPECT_EQ(bench.dut.a_coef.read(), 64u) << "a = K32 = 0.1b on Q11.7";
    EXPECT_EQ(bench.checker.mismatches(), 0u);
}

TEST(UA60553BadInput, NAbove1000IsReportedAndFollowsTheLinearLaw) {
    report_log::get().expect(msg::input);
    std::vector<surface> s{{1001, {255, 255, 255}, codes(0x7F00, 0x8000)},
                           {1023, {255, 255, 255}, codes(0x7F00, 0x8000)}};
    strobe_timing t;
    bench_t bench("tb", s, t, golden_for(overflow_mode::saturate));
    run(bench);
    EXPECT_EQ(report_log::get().count(msg::input), 2u);
    EXPECT_EQ(bench.dut.a_coef.read(), 1023u * 101u + 64u);  // 1023 * 0.1100101b + 0.1b, no overflow
    EXPECT_EQ(bench.checker.mismatches(), 0u);
}

TEST(UA60553BadInput, CosAboveOneIsReportedAndSaturatesToFullIntensity) {
    report_log::get().expect(msg::input);
    std::vector<surface> s{{50, {255, 100, 3}, {0x8001, 0x9000, 0xC000, 0xFFFF}}};
    strobe_timing t;
    bench_t bench("tb", s, t, golden_for(overflow_mode::saturate));
    run(bench);
    EXPECT_EQ(report_log::get().count(msg::input), 4u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    // Hand-worked: q clamps to 1.0, so each output is k_s*I exactly (integer part, zero fraction).
    EXPECT_EQ(bench.out25_r.read(), 255u << 8);
    EXPECT_EQ(bench.out26_g.read(), 100u << 8);
    EXPECT_EQ(bench.out27_b.read(), 3u << 8);
}

TEST(UA60553BadInput, CosAboveOneInWrapModeIsReportedAndBitExact) {
    report_log::get().expect(msg::input);
    std::vector<surface> s{{50, {255, 100, 3}, codes(0x8001, 0x8400)}};
    strobe_timing t;
    bench_t bench("tb", s, t, golden_for(overflow_mode::wrap), overflow_mode::wrap);
    run(bench);
    EXPECT_EQ(report_log::get().count(msg::input), 0x400u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
}

TEST(UA60553BadInput, CosChangingAtTheLatchingEdgeIsReportedAndTheOldValueKept) {
    report_log::get().expect(msg::setup);
    strobe_timing t;
    t.cos_lead = sc_core::SC_ZERO_TIME;
    const std::vector<uint32_t> stream{0x4000, 0x6000, 0x7000, 0x8000};
    std::vector<surface> s{{10, {255, 255, 255}, stream}};
    // Expected, worked by hand from the register's rule: each latch keeps the previous code
    // (RG2 starts at 0), so pixel i shows the golden value of stream[i-1].
    auto previous = std::make_shared<uint64_t>(0);
    auto golden = [previous](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        const auto r = golden_ua60553(n, *previous, k, overflow_mode::saturate);
        *previous = c;
        return r;
    };
    bench_t bench("tb", s, t, golden);
    run(bench);
    EXPECT_EQ(report_log::get().count(msg::setup), stream.size());
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.dut.rg2_cos.read(), 0x7000u);
}

TEST(UA60553Trace, VcdDeclaresTheDatapathSignals) {
    const std::string path = "test_ua60553_trace";  // own name: ctest may run tests in parallel
    {
        std::vector<surface> s{{10, {255, 128, 64}, codes(0x7F00, 0x7F10)}};
        strobe_timing t;
        bench_t bench("tb", s, t, golden_for(overflow_mode::saturate));
        vcd_file vcd(path);
        vcd.trace(bench);
        run(bench);
    }
    std::ifstream in(path + ".vcd");
    ASSERT_TRUE(in.good()) << path << ".vcd was not written";
    // Collect the declared names: "$var wire <width> <id> <name> [msb:lsb] $end".
    std::set<std::string> names;
    bool timescale_ps = false, dut_scope = false;
    for (std::string line, prev; std::getline(in, line); prev = line) {
        std::istringstream words(line);
        std::string kw, type, width, id, name;
        words >> kw;
        if (kw == "$var" && (words >> type >> width >> id >> name)) names.insert(name);
        if (kw == "$scope" && line.find(" dut ") != std::string::npos) dut_scope = true;
        if (prev == "$timescale" && line.find("1 ps") != std::string::npos) timescale_ps = true;
    }
    EXPECT_TRUE(timescale_ps) << "time unit must be set explicitly to 1 ps";
    EXPECT_TRUE(dut_scope) << "the device's nets must sit in their own scope";
    for (const char* sig : {"ctl15", "ctl17", "in16_n", "in18_cos", "rg1_n", "rg2_cos", "mul6_n_x_k",
                            "node31_k", "node32_k", "a_coef", "mul7_cos2", "inv8_not_cos",
                            "add9_cos2_minus_cos", "mul10_a_x_diff", "add11_brdf", "out25_r",
                            "out26_g", "out27_b", "out29_valid", "node28_carry1", "node30_carry0"})
        EXPECT_EQ(names.count(sig), 1u) << sig;
    for (const auto& n : names) EXPECT_EQ(n.find_first_of("[] "), std::string::npos) << n;
    // The committed view traces/ua60553.gtkw shows only nets this VCD declares.
    const auto declared = vcd_declared(path + ".vcd");
    const auto shown = gtkw_listed(source_path("traces/ua60553.gtkw"));
    EXPECT_GE(shown.size(), 30u);
    for (const auto& s : shown) EXPECT_EQ(declared.count(s), 1u) << s << " is in the view but not in the VCD";
}

TEST(UA60553Trace, GtkwaveViewReadsAtFirstSight) {
    // traces/ua60553.gtkw against a VCD of the bench ua60553_tb builds (n = 10, default strobes),
    // long enough to pass the marker: dump file, marker inside the window and off every edge, every
    // bus a number in its format from src/floor/formats (vcd_names.h, view_problems).
    const std::string base = ::testing::TempDir() + "ua60553_view";
    {
        std::vector<surface> s{{10, {255, 180, 60}, codes(0x7000, 0x7040)}};
        strobe_timing t;
        bench_t bench("tb", s, t, golden_for(overflow_mode::saturate));
        vcd_file vcd(base);
        vcd.trace(bench);
        run(bench);
        EXPECT_EQ(bench.checker.mismatches(), 0u);
    }
    view_formats f = specular_view_formats();
    f["tb.in16_n"] = f["tb.dut.rg1_n"] = ua60553::n_fmt;
    f["tb.dut.a_gen.node31_k"] = f["tb.dut.a_gen.node32_k"] = ua60553::k_fmt;
    f["tb.dut.a_gen.mul6_n_x_k"] = ua60553::mul6_fmt;
    f["tb.dut.a_coef"] = ua60553::a_fmt;
    const auto problems = view_problems(source_path("traces/ua60553.gtkw"), base + ".vcd", "ua60553", f,
                                        {"tb.ctl17", "tb.out29_valid", "tb.out25_r", "tb.out26_g", "tb.out27_b"});
    EXPECT_TRUE(problems.empty()) << joined(problems);
}

TEST(UA60553Checker, AWrongGoldenValueIsCaught) {
    // The checker must be able to fail: a golden model off by one LSB on the red channel.
    report_log::get().expect(msg::mismatch);
    std::vector<surface> s{{10, {255, 255, 255}, codes(0x7000, 0x7009)}};
    auto wrong = [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        auto r = golden_ua60553(n, c, k, overflow_mode::saturate);
        r.out[0] += 1;
        return r;
    };
    strobe_timing t;
    bench_t bench("tb", s, t, wrong);
    run(bench);
    EXPECT_EQ(bench.checker.mismatches(), 10u);
    EXPECT_EQ(report_log::get().count(msg::mismatch), 10u);
}

}  // namespace test_ua60553
