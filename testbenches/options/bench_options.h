// The command lines of the testbench programs (ua60553_tb, ua22802_tb, squared_tb, interp_*_tb) as
// plain structs, and one parse function per program: argv in, the struct filled, an exit status out
// when the program must stop (0 after --help, 2 for bad usage, common/exit_status.h), nothing when
// it runs. The parse functions live in the options library (program_options.cpp, one of the two
// sources that compile CLI11); they have no side effect beyond printing help or the usage error,
// so the fuzz target fuzz_options calls them directly. The options common to every bench, and what
// each does, are common/common_options.h's bench_options.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "testbenches/common/common_options.h"
#include "formats/interp_formats.h"

namespace shading::tb {

struct ua60553_options {
    bench_options bench;
    std::string generator = "patent";  // patent, minimax, rom_matched
    bool sweep = false;
    std::vector<unsigned> ns;          // empty: the defaults of the scene or the sweep
    unsigned scene_pixels = 96;        // 2..100000
    double t_low_ns = 15, t_high_ns = 5;  // > 0
    std::string abstraction = "block";    // block, fast
    bool zero_delays = false;
};

struct ua22802_options {
    bench_options bench;
    unsigned pixels = 48;  // 2..100000
    std::vector<unsigned> ns{1, 2, 3, 8, 32, 128, 512, 1000};  // each 0..1023
    std::string abstraction = "block";
};

struct squared_options {
    bench_options bench;
    bool sweep = false;
    std::vector<unsigned> ns;     // each 0..1023; empty: the defaults of the scene or the sweep
    unsigned scene_pixels = 48;   // 2..100000
    double clk_ns = 20;           // 1..1000
    std::string abstraction = "block";
};

// The square-and-multiply device's bench (sqmul_tb) takes the squared-quadratic device's options.
using sqmul_options = squared_options;

struct interp_coef_options {
    bench_options bench;
    std::string csv_path;
    unsigned width = 200, m = 5, n_extra = 200;  // 1..100000, m_min..8, 0..1000000
};

struct interp_fd_options {
    bench_options bench;
    std::string csv_path;
    unsigned width = 200, m = 5;  // 1..100000, m_min..m_max
};

struct interp_horner_options {
    bench_options bench;
    std::string csv_path;
    unsigned width = 200, m = 5, gap = 0;  // 1..100000, m_min..8, 0..100
    std::string abstraction = "block";
};

struct interp_line_options {
    bench_options bench;
    unsigned width = 200;        // 1..100000
    unsigned m = 5;              // m_min..m_max
    unsigned sample_case = 1;    // 1 or 2
    interp::div3_mode div3 = interp::div3_mode::shift_add;
};

std::optional<int> parse_ua60553(int argc, char** argv, ua60553_options& o);
std::optional<int> parse_ua22802(int argc, char** argv, ua22802_options& o);
std::optional<int> parse_squared(int argc, char** argv, squared_options& o);
std::optional<int> parse_sqmul(int argc, char** argv, sqmul_options& o);
std::optional<int> parse_interp_coef(int argc, char** argv, interp_coef_options& o);
std::optional<int> parse_interp_fd(int argc, char** argv, interp_fd_options& o);
std::optional<int> parse_interp_horner(int argc, char** argv, interp_horner_options& o);
std::optional<int> parse_interp_line(int argc, char** argv, interp_line_options& o);

}  // namespace shading::tb
