// The view checker (common/vcd_names.h, view_problems) against hand-made faults: each fault a user
// would meet at first sight in GTKWave must be reported, and a view without faults reports none.
// No simulation: a tiny VCD and save files written by the test itself.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "testbenches/common/vcd_names.h"

namespace {

using namespace shading;
using namespace shading::tb;
namespace fs = std::filesystem;

// One clock, an unsigned Q1.15 bus `cos` and a signed Q2.30 bus `d`; `cos` changes at 100 ps.
const char* const kVcd = R"($timescale 1 ps $end
$scope module SystemC $end
$scope module tb $end
$var wire 1 ! clk $end
$var wire 16 " cos [15:0] $end
$var wire 32 # d [31:0] $end
$upscope $end
$upscope $end
$enddefinitions $end
#0
0!
b0 "
b0 #
#100
1!
b100000000000000 "
#200
0!
#300
)";

struct view_spec {
    std::string dumpfile = "v.vcd", savefile = "v.gtkw";
    std::string zoom_marker = "*-10.000000 150 -1";  // 2^10 ps per 200 px: the window spans ~5 ns
    std::string cos_flags = "@40000024", d_flags = "@40000424";
    int cos_shift = 15, d_shift = 30;
    int filler_rows = 0;  // group lines pushed above the buses
};

std::string write_view(const fs::path& dir, const view_spec& s) {
    std::ofstream g(dir / "v.gtkw");
    g << "[dumpfile] \"" << s.dumpfile << "\"\n[savefile] \"" << s.savefile << "\"\n[timestart] 0\n"
      << "[size] 1600 900\n[signals_width] 300\n[sst_width] 200\n" << s.zoom_marker << "\n@28\nSystemC.tb.clk\n";
    for (int i = 0; i < s.filler_rows; ++i) g << "@800200\n-Filler" << i << "\n@1000200\n-Filler" << i << "\n";
    g << "[fpshift_count] " << s.cos_shift << "\n" << s.cos_flags << "\nSystemC.tb.cos[15:0]\n"
      << "[fpshift_count] " << s.d_shift << "\n" << s.d_flags << "\nSystemC.tb.d[31:0]\n";
    return (dir / "v.gtkw").string();
}

class ViewChecker : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("view_checker_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::create_directories(dir_);
        std::ofstream(dir_ / "v.vcd") << kVcd;
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::vector<std::string> problems(const view_spec& s, const std::vector<std::string>& first = {"tb.cos"}) {
        const view_formats f{{"tb.cos", qfmt{16, false, 15}}, {"tb.d", qfmt{32, true, 30}}};
        return view_problems(write_view(dir_, s), (dir_ / "v.vcd").string(), "v", f, first);
    }
    static bool mentions(const std::vector<std::string>& p, const std::string& what) {
        for (const auto& line : p)
            if (line.find(what) != std::string::npos) return true;
        return false;
    }
    fs::path dir_;
};

TEST_F(ViewChecker, ACorrectViewHasNoProblem) {
    const auto p = problems({});
    EXPECT_TRUE(p.empty()) << joined(p);
}

TEST_F(ViewChecker, EachFaultIsReported) {
    view_spec hex;
    hex.cos_flags = "@22";  // hex, no shift
    EXPECT_TRUE(mentions(problems(hex), "tb.cos[15:0] is not shown in decimal")) << joined(problems(hex));

    view_spec shift;
    shift.d_shift = 15;
    EXPECT_TRUE(mentions(problems(shift), "tb.d shown with fixed-point shift 15")) << joined(problems(shift));

    view_spec sign;
    sign.d_flags = "@40000024";  // the signed bus shown unsigned
    EXPECT_TRUE(mentions(problems(sign), "tb.d is signed but shown unsigned")) << joined(problems(sign));

    view_spec dump;
    dump.dumpfile = "/abs/v.vcd";
    EXPECT_TRUE(mentions(problems(dump), "[dumpfile]")) << joined(problems(dump));

    view_spec on_edge;
    on_edge.zoom_marker = "*-10.000000 100 -1";  // cos and clk change at 100 ps
    EXPECT_TRUE(mentions(problems(on_edge), "changes at the marker")) << joined(problems(on_edge));

    view_spec outside;
    outside.zoom_marker = "*-10.000000 250000 -1";  // far right of the ~5 ns window
    EXPECT_TRUE(mentions(problems(outside), "outside the opening window")) << joined(problems(outside));

    view_spec low;
    low.filler_rows = 20;  // 40 group lines push cos below the 35 visible rows
    EXPECT_TRUE(mentions(problems(low), "below the 35 rows visible")) << joined(problems(low));
    EXPECT_TRUE(mentions(problems({}, {"tb.out"}), "not in the view"));
}

}  // namespace
