// The README's number-format table against src/floor/formats: each row's formats, as a reader sees them
// ("Q1.15", "signed Q2.30", "10-bit integer"), parsed from README.md and compared with the qfmt
// constants the modules and golden models are built from. A width changed in src/floor/formats without
// the table (or the reverse) fails here.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "formats/interp_formats.h"
#include "formats/pipeline_formats.h"
#include "formats/specular_formats.h"
#include "formats/sqmul_formats.h"
#include "formats/squared_formats.h"
#include "formats/ua22802_formats.h"
#include "formats/ua60553_formats.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_format_table {

using namespace shading;

namespace {

// The rows of the table under "## Number formats": first cell -> second cell.
std::map<std::string, std::string> readme_rows() {
    std::ifstream f(std::string(SHADING_SOURCE_DIR) + "/README.md");
    std::map<std::string, std::string> rows;
    std::string line;
    bool in_section = false;
    while (std::getline(f, line)) {
        if (line.rfind("## ", 0) == 0) in_section = line == "## Number formats";
        if (!in_section || line.rfind("| ", 0) != 0) continue;
        std::vector<std::string> cells;
        std::stringstream ss(line.substr(2));
        std::string cell;
        while (std::getline(ss, cell, '|')) cells.push_back(cell.substr(0, cell.find_last_not_of(' ') + 1));
        if (cells.size() >= 2) rows[cells[0]] = cells[1].substr(cells[1].find_first_not_of(' '));
    }
    return rows;
}

// A format as the table writes it.
std::string written(const qfmt& f) {
    if (f.frac == 0 && !f.is_signed) return std::to_string(f.width) + "-bit integer";
    return std::string(f.is_signed ? "signed " : "") + "Q" + std::to_string(f.int_bits()) + "." + std::to_string(f.frac);
}

// The formats of one row, in the order the table lists them (separated by " / " or ", ").
std::vector<std::string> split_formats(const std::string& cell) {
    std::vector<std::string> out;
    const std::regex sep(" / |, ");
    for (std::sregex_token_iterator it(cell.begin(), cell.end(), sep, -1), end; it != end; ++it) out.push_back(*it);
    return out;
}

}  // namespace

TEST(FormatTable, ReadmeRowsMatchSrcFormats) {
    const std::map<std::string, std::vector<qfmt>> expected{
        {"cos = N·H (input 18)", {spec::cos_fmt}},
        {"n (input 16)", {ua60553::n_fmt}},
        {"k_s·I per channel (inputs 19, 21, 23)", {spec::ksi_fmt}},
        {"cos² (MUL7), INV8, ADD9 `cos² − cos`", {spec::cos2_fmt, spec::inv8_fmt, spec::d_fmt}},
        {"`a`: UA 60553 / UA 22802 ROM / squared device", {ua60553::a_fmt, ua22802::a_fmt, squared::a_fmt}},
        {"BRDF (ADD11 out)", {spec::brdf_fmt}},
        {"squared device: q and each square (RG_SQ)", {squared::q_fmt}},
        {"square-and-multiply device: P and each product (RG_P)", {sqmul::p_fmt}},
        {"outputs 25–27", {spec::out_fmt}},
        {"interpolation samples I1..I4, pixels", {interp::sample_fmt}},
        {"cell unit: lattice registers, column buffers", {interp::sample_fmt}},  // cell_channel's WI
        {"coefficients A..D / Horner's t / forward differences", {interp::coef_fmt, interp::t_fmt, interp::fd_fmt}},
        {"sample stage: k_d·I, diffuse, ambient + diffuse",
         {pipeline::kdi_fmt, pipeline::diffuse_fmt, pipeline::ad_fmt}},
    };
    const auto rows = readme_rows();
    ASSERT_FALSE(rows.empty()) << "no table under '## Number formats' in README.md";
    for (const auto& [bus, formats] : expected) {
        const auto it = rows.find(bus);
        ASSERT_NE(it, rows.end()) << "README.md's format table has no row '" << bus << "'";
        const auto got = split_formats(it->second);
        ASSERT_EQ(got.size(), formats.size()) << bus << ": '" << it->second << "'";
        for (std::size_t i = 0; i < formats.size(); ++i) EXPECT_EQ(got[i], written(formats[i])) << bus;
    }
    // Every row of the table is checked: a row added to the README needs its constants here.
    for (const auto& [bus, cell] : rows) {
        if (bus != "bus") {
            EXPECT_TRUE(expected.count(bus)) << "README.md row '" << bus << "' is not checked";
        }
    }
}

// The parser itself, on hand-written cells.
TEST(FormatTable, WrittenFormsByHand) {
    EXPECT_EQ(written(qfmt{16, false, 15}), "Q1.15");
    EXPECT_EQ(written(qfmt{32, true, 30}), "signed Q2.30");
    EXPECT_EQ(written(qfmt{10, false, 0}), "10-bit integer");
    EXPECT_EQ(split_formats("Q11.7 / Q10.6 / Q0.12"), (std::vector<std::string>{"Q11.7", "Q10.6", "Q0.12"}));
    EXPECT_EQ(split_formats("Q8.8, Q9.8, Q10.8"), (std::vector<std::string>{"Q8.8", "Q9.8", "Q10.8"}));
}

}  // namespace test_format_table
