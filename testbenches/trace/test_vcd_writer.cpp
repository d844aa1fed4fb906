// The project's VCD writer (core/vcd_writer.h) against SystemC's own writer, the independent
// reference: both trace the same signals in the same run (vcd_file with vcd_writer_kind::both), and
// the files must be the same byte for byte from $timescale on (only $date may differ) - on the
// block-level UA 60553 device with its block delays, the Horner unit, and a small bench of corner
// cases whose file is also written out by hand (the whole pipeline: test_vcd_writer_pipeline.cpp).
// Then the escape hatch (SHADING_TRACE_WRITER) and the writer's reports. Each test elaborates once
// (its own process).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "core/report_ids.h"
#include "core/trace.h"
#include "core/vcd_writer.h"
#include "testbenches/interp/interp_horner_bench.h"
#include "testbenches/specular/specular_tb.h"
#include "testbenches/trace/vcd_compare.h"
#include "ua60553/ua60553.h"

using namespace shading;
using namespace shading::tb;
using sc_core::SC_MS;
using sc_core::SC_NS;
using sc_core::sc_time;

namespace {

// ---- A bench of corner cases, its file written out by hand ----

// never: written once at 0, never changes; flip: 0 -> 1 at 1 ns, back at 5 ms + 2 ns (a stamp past
// 2^32 ps); one: a one-bit sc_uint (written without 'b'); wide: 64 bits, both ends set, then all
// ones; twice: changes twice within the time step at 1 ns (0 -> 3 -> 17: only 17 is written); back:
// 0 -> 5 -> 0 within that step (nothing written); inner.bus: a nested scope; a write of the same value
// at 2 ns and an empty time step at 5 ms + 3 ns write nothing.
class corner_inner : public sc_core::sc_module {
public:
    sc_core::sc_signal<sc_dt::sc_uint<16>> bus{"bus"};
    explicit corner_inner(const sc_core::sc_module_name& n) : sc_module(n) {}
};

class corner_bench : public sc_core::sc_module {
public:
    sc_core::sc_signal<bool> never{"never"}, flip{"flip"};
    sc_core::sc_signal<sc_dt::sc_uint<1>> one{"one"};
    sc_core::sc_signal<sc_dt::sc_uint<64>> wide{"wide"};
    sc_core::sc_signal<sc_dt::sc_uint<5>> twice{"twice"}, back{"back"};
    corner_inner inner{"inner"};

    SC_HAS_PROCESS(corner_bench);
    explicit corner_bench(const sc_core::sc_module_name& n) : sc_module(n) { SC_THREAD(run); }

private:
    void run() {
        never.write(true);
        wait(1, SC_NS);
        flip.write(true);
        wide.write(0x8000000000000001ull);
        twice.write(3);
        back.write(5);
        wait(sc_core::SC_ZERO_TIME);
        twice.write(17);
        back.write(0);
        wait(1, SC_NS);
        one.write(1);
        wide.write(~0ull);
        inner.bus.write(10);
        never.write(true);  // the same value: no event, no line
        wait(5, SC_MS);
        flip.write(false);
        wait(1, SC_NS);
        flip.write(false);
    }
};

// What SystemC 2.3.4's writer writes for corner_bench traced from its root and run for 10 ms,
// from $timescale on: worked out from its source (sc_vcd_trace.cpp), independently of our writer.
std::string corner_expected() {
    const std::string ones(64, '1'), ends = "1" + std::string(62, '0') + "1";
    return "$timescale\n     1 ps\n$end\n\n"
           "$scope module SystemC $end\n"
           "$scope module corner $end\n"
           "$var wire    1  aaaaa  never       $end\n"
           "$var wire    1  aaaab  flip       $end\n"
           "$var wire    1  aaaac  one       $end\n"
           "$var wire   64  aaaad  wide [63:0]  $end\n"
           "$var wire    5  aaaae  twice [4:0]  $end\n"
           "$var wire    5  aaaaf  back [4:0]  $end\n"
           "$scope module inner $end\n"
           "$var wire   16  aaaag  bus [15:0]  $end\n"
           "$upscope $end\n"
           "$upscope $end\n"
           "$upscope $end\n"
           "$enddefinitions  $end\n\n"
           "$comment\nAll initial values are dumped below at time 0 sec = 0 timescale units.\n$end\n\n"
           "$dumpvars\n1aaaaa\n0aaaab\n0aaaac\nb0 aaaad\nb0 aaaae\nb0 aaaaf\nb0 aaaag\n$end\n\n"
           "#1000\n1aaaab\nb" + ends + " aaaad\nb10001 aaaae\n\n"
           "#2000\n1aaaac\nb" + ones + " aaaad\nb1010 aaaag\n\n"
           "#5000002000\n0aaaab\n\n"
           "#10000000000\n";
}


}  // namespace

TEST(VcdWriter, CornerCasesAsWorkedOutAndAsSystemCWritesThem) {
    const std::string base = temp_base("vcd_writer_corner");
    {
        corner_bench bench("corner");
        vcd_file vcd(base, vcd_writer_kind::both);
        vcd.trace(bench);
        sc_core::sc_start(10, SC_MS);
    }
    EXPECT_EQ(body(slurp(base + ".vcd")), corner_expected()) << first_difference(body(slurp(base + ".vcd")), corner_expected());
    expect_same_files(base, 4, 15);
}

TEST(VcdWriter, SameFileAsSystemCOnTheUA60553DeviceWithBlockDelays) {
    const std::string base = temp_base("vcd_writer_ua60553");
    std::vector<uint32_t> codes;
    for (uint32_t c = 0x7000; c < 0x7000 + 40 * 0x13; c += 0x13) codes.push_back(c);
    std::vector<surface> s{{10, {255, 180, 60}, codes}, {3, {17, 200, 255}, {0x0000, 0x8000, 0x7FFF}}};
    {
        specular_bench<device_ua60553> bench("tb", s, strobe_timing{},
                                             [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
                                                 return golden_ua60553(n, c, k, overflow_mode::saturate);
                                             });
        vcd_file vcd(base, vcd_writer_kind::both);
        vcd.trace(bench);
        ASSERT_TRUE(run_to_completion(bench, sc_time(1, SC_MS)));
        EXPECT_EQ(bench.checker.mismatches(), 0u);
    }
    expect_same_files(base, 200, 40);
}

TEST(VcdWriter, SameFileAsSystemCOnTheHornerUnit) {
    const std::string base = temp_base("vcd_writer_horner");
    {
        horner_bench bench("tb", random_horner_requests(30, 7));
        vcd_file vcd(base, vcd_writer_kind::both);
        vcd.trace(bench);
        ASSERT_TRUE(run_to_completion(bench, sc_time(1, SC_MS)));
        EXPECT_EQ(bench.checker.mismatches(), 0u);
    }
    expect_same_files(base, 200, 20);
}

// ---- The escape hatch and the reports ----

TEST(VcdWriter, EnvironmentSelectsTheWriter) {
    corner_bench bench("corner");
    const std::string base = temp_base("vcd_writer_env");
    {
        ASSERT_EQ(unsetenv("SHADING_TRACE_WRITER"), 0);
        vcd_file lean(base + "_unset");
        ASSERT_EQ(setenv("SHADING_TRACE_WRITER", "systemc", 1), 0);
        vcd_file systemc(base + "_sc");
        ASSERT_EQ(setenv("SHADING_TRACE_WRITER", "both", 1), 0);
        vcd_file both(base + "_both");
        report_log::get().expect(msg::trace);
        ASSERT_EQ(setenv("SHADING_TRACE_WRITER", "fast", 1), 0);
        vcd_file bad(base + "_bad");
        EXPECT_EQ(report_log::get().count(msg::trace), 1u) << "an unknown writer name is reported";
        EXPECT_NE(dynamic_cast<vcd_writer*>(lean.get()), nullptr);
        EXPECT_EQ(dynamic_cast<vcd_writer*>(systemc.get()), nullptr) << "SystemC's writer, not ours";
        EXPECT_NE(systemc.get(), nullptr);
        EXPECT_NE(dynamic_cast<vcd_writer*>(both.get()), nullptr);
        EXPECT_NE(dynamic_cast<vcd_writer*>(bad.get()), nullptr) << "an unknown name falls back to ours";
        for (vcd_file* v : {&lean, &systemc, &both, &bad}) v->trace(bench);
        sc_core::sc_start(10, SC_MS);
    }
    for (const char* f : {"_unset.vcd", "_sc.vcd", "_both.vcd", "_both_systemc.vcd", "_bad.vcd"})
        EXPECT_EQ(body(slurp(base + f)), corner_expected()) << f;
    EXPECT_FALSE(std::filesystem::exists(base + "_unset_systemc.vcd"));
    EXPECT_FALSE(std::filesystem::exists(base + "_sc_systemc.vcd"));
}

TEST(VcdWriter, UntracedTypeIsReported) {
    sc_core::sc_signal<int> counter{"counter"};
    sc_core::sc_signal<bool> flag{"flag"};
    report_log::get().expect(msg::trace);
    vcd_file vcd(temp_base("vcd_writer_untraced"), vcd_writer_kind::lean);
    sc_core::sc_trace(vcd.get(), counter, "counter");
    EXPECT_EQ(report_log::get().count(msg::trace), 1u) << "an int signal is not silently left out";
    sc_core::sc_trace(vcd.get(), flag, "flag");
    EXPECT_EQ(report_log::get().count(msg::trace), 1u) << "a bool is traced";
    sc_core::sc_start(1, SC_NS);
}

TEST(VcdWriter, UnopenablePathIsReportedAndTheRunGoesOn) {
    corner_bench bench("corner");
    report_log::get().expect(msg::trace);
    const std::string base = temp_base("vcd_writer_no_such_folder/sub/trace");
    {
        vcd_file vcd(base, vcd_writer_kind::lean);
        EXPECT_EQ(report_log::get().count(msg::trace), 1u);
        vcd.trace(bench);
        sc_core::sc_start(10, SC_MS);
    }
    EXPECT_EQ(report_log::get().count(msg::trace), 1u) << "reported once, when opened";
    EXPECT_EQ(sc_core::sc_time_stamp(), sc_time(10, SC_MS));
    EXPECT_FALSE(std::filesystem::exists(base + ".vcd"));
}

TEST(VcdWriter, ClosedBeforeAnyTimeStepIsReportedAndNotWritten) {
    // As SystemC's writer (its W715): nothing was traced, so no file.
    corner_bench bench("corner");
    const std::string base = temp_base("vcd_writer_empty");
    std::filesystem::remove(base + ".vcd");
    report_log::get().expect(msg::trace);
    {
        vcd_file vcd(base, vcd_writer_kind::lean);
        vcd.trace(bench);
    }
    EXPECT_EQ(report_log::get().count(msg::trace), 1u);
    EXPECT_FALSE(std::filesystem::exists(base + ".vcd"));
}

TEST(VcdWriter, TracingAfterTheStartIsReported) {
    corner_bench bench("corner");
    vcd_file vcd(temp_base("vcd_writer_late"), vcd_writer_kind::lean);
    vcd.trace(bench);
    sc_core::sc_start(2, SC_NS);
    report_log::get().expect(msg::trace);
    vcd.trace(bench.inner);
    EXPECT_EQ(report_log::get().count(msg::trace), 1u) << "one report per late signal";
}

#if defined(SC_VERSION_MAJOR) && SC_VERSION_MAJOR >= 3
TEST(VcdWriter, TimeUnitBelowOneFemtosecondIsReportedAndTheUnitKept) {
    // SystemC 3.0 adds as, zs and ys; a VCD counted in whole fs cannot be set to them (SystemC's own
    // writer reports them too). The kernel's default resolution, 1 ps, stays the file's unit.
    const std::string base = temp_base("vcd_writer_attosecond");
    report_log::get().expect(msg::trace);
    {
        vcd_writer w(base);
        w.set_time_unit(1, sc_core::SC_AS);
        EXPECT_EQ(report_log::get().count(msg::trace), 1u);
        sc_core::sc_start(1, SC_NS);
    }
    EXPECT_EQ(report_log::get().count(msg::trace), 1u);
    EXPECT_NE(slurp(base + ".vcd").find("$timescale\n     1 ps\n$end"), std::string::npos);
}
#endif
