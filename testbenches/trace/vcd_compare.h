// Comparing two VCD files of one run (vcd_file with vcd_writer_kind::both: ours at base.vcd,
// SystemC's at base_systemc.vcd) for the VCD writer's suites (test_vcd_writer, _pipeline).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <systemc>

namespace shading::tb {

inline std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The file from its $timescale block on: $date (the wall clock) and $version come before it.
inline std::string body(const std::string& vcd) {
    const auto at = vcd.find("$timescale");
    return at == std::string::npos ? std::string() : vcd.substr(at);
}

inline std::size_t count_lines_starting(const std::string& text, char c) {
    std::size_t n = text.size() > 0 && text[0] == c ? 1 : 0;
    for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 1))
        if (at + 1 < text.size() && text[at + 1] == c) ++n;
    return n;
}

// Where two texts first differ, with the line on each side (a failure that says where).
inline std::string first_difference(const std::string& a, const std::string& b) {
    std::istringstream sa(a), sb(b);
    std::string la, lb;
    for (std::size_t line = 1;; ++line) {
        const bool ga = static_cast<bool>(std::getline(sa, la)), gb = static_cast<bool>(std::getline(sb, lb));
        if (!ga && !gb) return "no difference";
        if (ga != gb || la != lb)
            return "line " + std::to_string(line) + " of the body: ours \"" + (ga ? la : "<end>") + "\", SystemC's \"" +
                   (gb ? lb : "<end>") + "\"";
    }
}

// Both files of a vcd_file(base, both): ours at base.vcd, SystemC's at base_systemc.vcd; the same
// bytes after the header, with at least `min_stamps` time stamps and `min_vars` variables in them.
inline void expect_same_files(const std::string& base, std::size_t min_stamps, std::size_t min_vars) {
    const std::string ours = slurp(base + ".vcd"), theirs = slurp(base + "_systemc.vcd");
    ASSERT_FALSE(body(ours).empty()) << base << ".vcd has no $timescale";
    ASSERT_FALSE(body(theirs).empty()) << base << "_systemc.vcd has no $timescale";
    EXPECT_TRUE(body(ours) == body(theirs)) << first_difference(body(ours), body(theirs));
    EXPECT_EQ(ours.substr(0, 6), "$date\n");
    EXPECT_NE(ours.find("$version\n " + std::string(sc_core::sc_version()) + "\n$end\n"), std::string::npos);
    EXPECT_GE(count_lines_starting(body(theirs), '#'), min_stamps) << "too short a run to compare";
    EXPECT_GE(count_lines_starting(body(theirs), '$'), min_vars) << "too few variables to compare";
    if (!::testing::Test::HasFailure()) {  // kept for a look when they differ
        std::filesystem::remove(base + ".vcd");
        std::filesystem::remove(base + "_systemc.vcd");
    }
}

// A file name in GoogleTest's temporary folder.
inline std::string temp_base(const std::string& stem) { return ::testing::TempDir() + stem; }

}  // namespace shading::tb
