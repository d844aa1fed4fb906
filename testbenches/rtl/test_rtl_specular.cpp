// The RTL twin of each specular device (rtl/, verilated with --sc) co-simulated with the SystemC
// model (rtl_cosim_tb.h): UA 60553, UA 22802 and the tuned variant, each in both overflow modes,
// bit-exact against the model and the golden model over every 16-bit cos code at the usual n and
// 10^6 random stimuli (four random runs of 250 000 pixels each, one ctest entry per run, so each
// stays a few seconds); negative tests show that both comparisons can fail; the view test writes
// both VCDs and checks the saved GTKWave views against them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/common/vcd_names.h"
#include "core/report_ids.h"
#include "arith/specular_arith.h"
#include "arith/ua22802_arith.h"
#include "arith/ua60553_tuned_arith.h"
#include "rtl_cosim_tb.h"
#include "testbenches/specular/specular_view.h"
#include "tuned/ua60553_tuned.h"
#include "ua22802/ua22802.h"
#include "ua60553/ua60553.h"
#include "verilated.h"

// The Verilated devices (testbenches/rtl/CMakeLists.txt): Vrtl_<device>_<mode>.
#include "Vrtl_tuned_saturate.h"
#include "Vrtl_tuned_wrap.h"
#include "Vrtl_ua22802_saturate.h"
#include "Vrtl_ua22802_wrap.h"
#include "Vrtl_ua60553_saturate.h"
#include "Vrtl_ua60553_wrap.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_rtl_specular {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_MS;
using sc_core::sc_time;

namespace {

using golden_fn = datapath_nets (*)(uint64_t, uint64_t, const std::array<uint64_t, 3>&, overflow_mode);

template <typename Device, typename Rtl, overflow_mode Mode>
struct variant {
    using device = Device;
    using rtl = Rtl;
    static constexpr overflow_mode mode = Mode;
};

template <typename Device>
golden_fn golden_of();
template <>
golden_fn golden_of<device_ua60553>() { return [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k, overflow_mode m) { return golden_ua60553(n, c, k, m); }; }
template <>
golden_fn golden_of<device_ua22802>() { return &golden_ua22802; }
template <>
golden_fn golden_of<device_ua60553_tuned>() { return [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k, overflow_mode m) { return golden_ua60553_tuned(n, c, k, m); }; }

specular_checker::golden_fn bind_mode(golden_fn g, overflow_mode m) {
    return [g, m](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) { return g(n, c, k, m); };
}

template <typename T>
class RtlCosim : public ::testing::Test {
protected:
    using bench_t = rtl_cosim_bench<typename T::device, typename T::rtl>;

    void SetUp() override { Verilated::traceEverOn(true); }

    // Runs the stream through both devices; every sample of each must match golden and the other.
    void run(item_source<surface> surfaces, std::size_t expected_pixels) {
        const auto golden = bind_mode(golden_of<typename T::device>(), T::mode);
        bench_t bench("tb", std::move(surfaces), golden, golden, T::mode);
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
    }

    void sweep(uint32_t first, uint64_t last) {
        std::vector<uint32_t> codes;
        for (uint64_t c = first; c <= last; ++c) codes.push_back(static_cast<uint32_t>(c));
        const std::vector<unsigned> ns{1, 2, 3, 512, 1000};
        std::vector<surface> s;
        for (unsigned n : ns) s.push_back({n, {255, 170, 3}, codes});
        run(s, ns.size() * codes.size());
    }

    void random_run(uint64_t seed) {
        constexpr std::size_t pixels = 250000;
        run(random_surfaces(pixels, seed), pixels);
    }
};

struct names {
    template <typename T>
    static std::string GetName(int) {
        std::string d = std::is_same_v<typename T::device, device_ua60553>   ? "UA60553"
                        : std::is_same_v<typename T::device, device_ua22802> ? "UA22802"
                                                                              : "Tuned";
        return d + (T::mode == overflow_mode::saturate ? "Saturate" : "Wrap");
    }
};

using variants = ::testing::Types<
    variant<device_ua60553, Vrtl_ua60553_saturate, overflow_mode::saturate>,
    variant<device_ua60553, Vrtl_ua60553_wrap, overflow_mode::wrap>,
    variant<device_ua22802, Vrtl_ua22802_saturate, overflow_mode::saturate>,
    variant<device_ua22802, Vrtl_ua22802_wrap, overflow_mode::wrap>,
    variant<device_ua60553_tuned, Vrtl_tuned_saturate, overflow_mode::saturate>,
    variant<device_ua60553_tuned, Vrtl_tuned_wrap, overflow_mode::wrap>>;

}  // namespace

TYPED_TEST_SUITE(RtlCosim, variants, names);

// The n of the device suites' exhaustive sweep (testbenches/specular), every cos code: up to 1.0,
// then above it (the range checker reports those; ADD11 saturates them to k_s*I or passes the
// wrapped bits on, and the RTL must agree either way). Two runs, so each stays a few seconds.
TYPED_TEST(RtlCosim, EveryCosCodeUpToOneAtTheUsualN) { this->sweep(0, spec::cos_one); }
TYPED_TEST(RtlCosim, EveryCosCodeAboveOneAtTheUsualN) {
    report_log::get().expect(msg::input);
    this->sweep(spec::cos_one + 1, spec::cos_fmt.mask());
}

TYPED_TEST(RtlCosim, EveryNIncludingOutOfRange) {
    // Every word of UA 22802's ROM case table and every n the generators see (0..1023: n = 0 and
    // 1001..1023 are reported by the model's range checker), four cos codes each.
    report_log::get().expect(msg::input);
    std::vector<surface> s;
    for (unsigned n = 0; n < (1u << ua60553::n_fmt.width); ++n)
        s.push_back({n, {255, 17, 96}, {0x4000, 0x6000, 0x7800, spec::cos_one}});
    this->run(s, s.size() * 4);
}

// 10^6 random pixels per device and mode, in four runs (random_surfaces: n 1..1000, k_s*I 0..255
// reloaded at random between surfaces of 1..16 pixels, cos 0..1.0).
TYPED_TEST(RtlCosim, Random0) { this->random_run(1); }
TYPED_TEST(RtlCosim, Random1) { this->random_run(2); }
TYPED_TEST(RtlCosim, Random2) { this->random_run(3); }
TYPED_TEST(RtlCosim, Random3) { this->random_run(4); }

TEST(RtlCosimCheck, AnRtlThatDiffersFromTheModelIsCaught) {
    // Negative test: the patent's RTL (a(1) = 1.29) beside the ROM device's model (a(1) = 0), each
    // checked against its own golden model: only the RTL-against-model comparison fails, 3 times.
    Verilated::traceEverOn(true);
    report_log::get().expect(msg::mismatch);
    std::vector<surface> s{{1, {255, 255, 255}, {0x5000, 0x6000, 0x7000}}};
    rtl_cosim_bench<device_ua22802, Vrtl_ua60553_saturate> bench(
        "tb", s, bind_mode(golden_of<device_ua22802>(), overflow_mode::saturate),
        bind_mode(golden_of<device_ua60553>(), overflow_mode::saturate), overflow_mode::saturate);
    ASSERT_TRUE(run_cosim(bench, sc_time(1, SC_MS)));
    EXPECT_EQ(bench.pairs(), 3u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.rtl_checker.mismatches(), 0u);
    EXPECT_EQ(bench.cross_mismatches(), 3u);
    EXPECT_EQ(report_log::get().count(msg::mismatch), 3u);
}

TEST(RtlCosimCheck, AnRtlThatDiffersFromGoldenIsCaught) {
    // Negative test: the RTL checked against another device's golden model fails on every pixel.
    Verilated::traceEverOn(true);
    report_log::get().expect(msg::mismatch);
    std::vector<surface> s{{1, {255, 255, 255}, {0x5000, 0x6000, 0x7000}}};
    rtl_cosim_bench<device_ua60553, Vrtl_ua60553_saturate> bench(
        "tb", s, bind_mode(golden_of<device_ua60553>(), overflow_mode::saturate),
        bind_mode(golden_of<device_ua22802>(), overflow_mode::saturate), overflow_mode::saturate);
    ASSERT_TRUE(run_cosim(bench, sc_time(1, SC_MS)));
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.rtl_checker.mismatches(), 3u);
    EXPECT_EQ(bench.cross_mismatches(), 0u);
    EXPECT_EQ(report_log::get().count(msg::mismatch), 3u);
}

namespace {

// The formats the two views must show their buses in (vcd_names.h, view_problems), from
// src/floor/formats: the SystemC side's nets (specular_view.h) and the RTL's, named as each VCD does.
view_formats cosim_view_formats() {
    view_formats f = specular_view_formats();
    f["tb.in16_n"] = f["tb.dut.rg1_n"] = ua60553::n_fmt;
    f["tb.dut.a_coef"] = ua60553::a_fmt;
    for (const char* o : {"tb.rtl_out25_r", "tb.rtl_out26_g", "tb.rtl_out27_b"}) f[o] = spec::out_fmt;
    const std::string r = "tb.rtl.specular_device.";
    f[r + "rg1_n"] = ua60553::n_fmt;
    f[r + "generator.a_gen.node31_k"] = f[r + "generator.a_gen.node32_k"] = ua60553::k_fmt;
    f[r + "generator.a_gen.mul6_n_x_k"] = ua60553::mul6_fmt;
    f[r + "a_coef"] = ua60553::a_fmt;
    f[r + "rg2_cos"] = spec::cos_fmt;
    f[r + "mul7_cos2"] = spec::cos2_fmt;
    f[r + "inv8_not_cos"] = spec::inv8_fmt;
    f[r + "add9_cos2_minus_cos"] = spec::d_fmt;
    f[r + "mul10_a_x_diff"] = spec::mul10_fmt;
    f[r + "add11_brdf"] = spec::brdf_fmt;
    for (const char* k : {"rg3_ksi_r", "rg4_ksi_g", "rg5_ksi_b"}) f[r + k] = spec::ksi_fmt;
    for (const char* o : {"out25_r", "out26_g", "out27_b"}) f[r + o] = spec::out_fmt;
    return f;
}

// Verilator's VCD has no "SystemC" top scope, which the view reader expects: copies of the RTL's
// VCD and view with one added, so the same first-sight checks apply to both views.
std::string with_systemc_scope(const std::string& in, const std::string& out, bool is_view) {
    std::ifstream src(in);
    std::ofstream dst(out);
    if (!is_view) dst << "$scope module SystemC $end\n";
    for (std::string line; std::getline(src, line);)
        dst << (is_view && line.rfind("tb.rtl.", 0) == 0 ? "SystemC." : "") << line << '\n';
    return out;
}

}  // namespace

TEST(RtlCosimView, BothTracesAndTheirViewsReadAtFirstSight) {
    // UA 60553 (saturate) co-simulated, traced: n = 10, 65 pixels from cos 0x7000. With
    // SHADING_TRACE=traces this writes the VCDs the committed views open (traces/rtl_cosim.vcd,
    // traces/rtl_cosim_rtl.vcd); otherwise into the test's temporary folder.
    Verilated::traceEverOn(true);
    const char* dir = std::getenv("SHADING_TRACE");
    std::string base = ::testing::TempDir();
    if (dir != nullptr && *dir != '\0') {
        std::filesystem::create_directories(dir);
        base = std::string(dir) + "/";
    }
    const std::string stem = base + "rtl_cosim";
    std::vector<uint32_t> codes;
    for (uint32_t c = 0x7000; c <= 0x7040; ++c) codes.push_back(c);
    {
        const auto g = bind_mode(golden_of<device_ua60553>(), overflow_mode::saturate);
        std::vector<surface> s{{10, {255, 180, 60}, codes}};
        rtl_cosim_bench<device_ua60553, Vrtl_ua60553_saturate> bench("tb", s, g, g, overflow_mode::saturate);
        ASSERT_TRUE(run_cosim(bench, sc_time(1, SC_MS), stem));
        EXPECT_EQ(bench.pairs(), codes.size());
        EXPECT_EQ(bench.cross_mismatches() + bench.rtl_checker.mismatches() + bench.checker.mismatches(), 0u);
    }
    const auto f = cosim_view_formats();
    auto problems = view_problems(source_path("traces/rtl_cosim.gtkw"), stem + ".vcd", "rtl_cosim", f,
                                  {"tb.ctl17", "tb.out29_valid", "tb.rtl_out29_valid", "tb.out25_r",
                                   "tb.rtl_out25_r", "tb.out27_b", "tb.rtl_out27_b"});
    EXPECT_TRUE(problems.empty()) << "traces/rtl_cosim.gtkw:" << joined(problems);
    EXPECT_GE(gtkw_read(source_path("traces/rtl_cosim.gtkw")).traces.size(), 20u);

    const std::string tmp = ::testing::TempDir() + "rtl_cosim_rtl_scoped";
    const std::string view = with_systemc_scope(source_path("traces/rtl_cosim_rtl.gtkw"), tmp + ".gtkw", true);
    const std::string vcd = with_systemc_scope(stem + "_rtl.vcd", tmp + ".vcd", false);
    const std::string r = "tb.rtl.specular_device.";
    problems = view_problems(view, vcd, "rtl_cosim_rtl", f, {r + "ctl17", r + "out29_valid", r + "out25_r", r + "out27_b"});
    EXPECT_TRUE(problems.empty()) << "traces/rtl_cosim_rtl.gtkw:" << joined(problems);
    EXPECT_GE(gtkw_read(view).traces.size(), 20u);
}

}  // namespace test_rtl_specular
