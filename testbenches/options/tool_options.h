// The command lines of the studies and tools that are not testbenches (interp_study, soak_pipeline,
// render_reference, bench_specular_tlm, accuracy_study, generator_search, head_study,
// sqmul_study, components_study) as plain
// structs, and one parse function per program, as in bench_options.h: the struct filled, an exit
// status returned when the program must stop (0 after --help, 2 for bad usage), nothing when it
// runs. No side effect beyond printing help or the usage error (program_options.cpp, CLI11).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace shading::tb {

// The source tree (for data/head/): the default --data-dir, fixed when the options library is built.
const char* default_data_dir();

// The names --device takes (render_reference, bench_specular_tlm, render_pipeline).
inline const std::vector<std::string>& device_names() {
    static const std::vector<std::string> names{"patent", "minimax", "rom_matched", "ua22802", "squared", "sqmul"};
    return names;
}

struct interp_study_options {
    std::string csv = "out/interp_nmse.csv";
    unsigned width = 200;       // 8..100000
    std::string grouping_csv;   // empty on the command line: interp_div3_grouping.csv beside --csv
};

struct soak_options {
    unsigned renders = 1000;  // 2..100000
    unsigned size = 128;      // 8..1024
};

struct render_reference_options {
    std::string scene = "head", out = "out/scene", device = "minimax", mode = "saturate";
    std::string data_dir = default_data_dir();
    unsigned size = 256;             // 1..8192
    unsigned n = 0;                  // 0: the material's own; else 1..1000
    double error_scale = 8.0;        // > 0
    double depth_step = 0.02;        // > 0
    std::vector<std::string> compare;  // device names
};

struct bench_specular_tlm_options {
    std::string device = "patent";
    std::size_t lt_pixels = 100'000'000, pin_pixels = 200'000;  // each 1..10^12
    unsigned burst = 1024;  // pixels per COS_BLOCK write and RESULT_BLOCK read, 1..1024
};

struct bench_line_tlm_options {
    std::size_t lt_pixels = 200'000'000, pin_pixels = 200'000;  // each 1..10^12
    unsigned burst = 256;  // 32-pixel intervals per INTERVAL_BLOCK write and PIXEL_BLOCK read, 1..256
};

struct accuracy_study_options {
    std::string out = "out", data_dir = default_data_dir();
    unsigned fig2_n = 10;   // 1..1000, then at most n_max
    unsigned size = 512;    // 16..4096
    unsigned n_max = 1000;  // 1..1000
};

struct generator_search_options {
    std::string csv = "out/generator_search.csv";
    double keep = 0.06;
};

struct head_study_options {
    std::string out = "out", data_dir = default_data_dir();
    unsigned size = 512;       // 16..4096
    std::vector<unsigned> ns{2, 5, 10, 20, 50, 100, 200, 500, 1000};  // each 1..1000
    unsigned scan_max = 1000;  // 0..1000
};

struct sqmul_study_options {
    std::string out = "out", data_dir = default_data_dir();
    unsigned size = 512;                                                  // 16..4096
    std::vector<unsigned> ns{2, 5, 10, 20, 50, 100, 200, 500, 1000};  // each 1..1000: the head renders
    unsigned n_max = 1000;                                                // 1..1000: the relative errors
};

// components_study: the built-in scene (head, sphere, torus), the tolerances tried per design (8-bit
// levels, each > 0 and <= 64), the longest interval per design (interp::m_min..m_max: 2..6).
struct components_study_options {
    std::string scene = "head", data_dir = default_data_dir(), device = "squared";
    unsigned size = 512;  // 16..4096
    double nmse = 1e-5;   // (0, 1]
    std::vector<double> tol_sum{1.5, 1.7, 1.9, 2.1};
    std::vector<double> tol_diffuse{1.0, 1.2, 1.4, 1.6, 1.9};
    std::vector<double> tol_specular{1.0, 1.3, 1.6, 1.9, 2.2, 2.5};
    unsigned m_max_sum = 5, m_max_diffuse = 5, m_max_specular = 6;
};

// edge_study: the built-in scene (head, sphere, torus), the sample spacings (pixels, powers of two
// 1..64, at least one).
struct edge_study_options {
    std::string scene = "head", data_dir = default_data_dir(), device = "squared";
    unsigned size = 512;  // 16..4096
    std::vector<unsigned> spacings{2, 4, 8, 16};
};

// two_line_study: the built-in scene, the NMSE limit, the tolerances (levels) of one line at a time
// and of the two-line scheme's even and odd lines (and of the middle lines with every fourth line
// first), the longest interval 2^m_max, the line-above limit K (-1: none), edge walking, perfect
// decisions.
struct two_line_study_options {
    std::string scene = "head", data_dir = default_data_dir(), device = "squared";
    unsigned size = 512;  // 16..4096
    double nmse = 1e-5;   // (0, 1]
    std::vector<double> tol_one{1.6, 1.8, 1.9, 2.0};
    std::vector<double> tol_even{1.6, 1.8, 1.9};
    std::vector<double> tol_odd{1.0, 1.5, 2.0, 3.0};
    std::vector<double> tol_mid;  // every fourth line first: the middle lines' tolerances (empty: not run)
    unsigned m_max = 5;
    int above_slack = 2;  // -1..m_max
    bool walk_edges = false;  // the geometry side and the scan-line Phong walk edges (render_pipeline's)
    bool perfect_decisions = false;  // a yardstick: decisions on the true error (studies/yardsticks)
};

// cell_study: the built-in scene, its light (azimuth, elevation in degrees; empty: the scene's) and
// exponent (0: the scene's), the NMSE limit, the cells' tolerances (levels) and their decision
// factors, the fallback's and the lines' tolerances, the largest cell, the lines' longest interval
// 2^m_max, edge walking, perfect decisions, the bit-accurate model instead of the emulation.
struct cell_study_options {
    std::string scene = "head", data_dir = default_data_dir(), device = "squared";
    unsigned size = 512;  // 16..4096
    std::vector<double> light;  // two values, -360..360 and -90..90
    unsigned n = 0;             // 0 or 1..1000
    double nmse = 1e-5;   // (0, 1]
    std::vector<double> tol{0.7, 0.8, 0.85, 0.9, 0.95, 1.0};
    double d2_factor = 8.0, d3_factor = 1.0;  // 0.01..1000
    double fallback_tol = 1.0, line_tol = 1.5;  // levels, 0.001..64
    unsigned cell_max = 32;  // 4..256, a power of two
    unsigned m_max = 4;      // the lines': at 5 an interval beside a silhouette misses a lit streak
    bool walk_edges = false;
    bool perfect_decisions = false;
    bool golden = false;     // the bit-accurate cells (src/golden_pipeline/cells.h), not the emulation
};

// render_cells: the built-in scene, its light and exponent as cell_study's, the cells' tolerance (levels)
// with cell_study's other defaults, edge walking (the counts only).
struct render_cells_options {
    std::string scene = "head", data_dir = default_data_dir(), device = "squared";
    unsigned size = 512;        // 16..1024
    std::vector<double> light;  // two values, -360..360 and -90..90
    unsigned n = 0;             // 0 or 1..1000
    double tol = 0.89;          // 0.001..64: the head at 512's cheapest within interpolation NMSE 1e-5
    bool walk_edges = false;
};

// render_race: a built-in scene or an OBJ file, its size, exponent and light, the device; where the
// table and the sheet go; settings other than the frozen configuration's, each shown as an extra row.
struct render_race_options {
    std::string scene = "head", data_dir = default_data_dir(), device = "sqmul", out = "out/race";
    unsigned size = 512;        // 16..2048
    std::vector<double> light;  // two values, -360..360 and -90..90
    unsigned n = 20;            // 1..1000
    double error_scale = 8.0;   // levels at white on the error maps, > 0
    bool sim = true;            // the cells' SystemC frame against their golden model
    double cells_tol = -1.0, line_tol = -1.0, fast_phong_budget = -1.0;  // < 0: the frozen one only
};

std::optional<int> parse_interp_study(int argc, char** argv, interp_study_options& o);
std::optional<int> parse_soak(int argc, char** argv, soak_options& o);
std::optional<int> parse_render_reference(int argc, char** argv, render_reference_options& o);
std::optional<int> parse_bench_specular_tlm(int argc, char** argv, bench_specular_tlm_options& o);
std::optional<int> parse_bench_line_tlm(int argc, char** argv, bench_line_tlm_options& o);
std::optional<int> parse_accuracy_study(int argc, char** argv, accuracy_study_options& o);
std::optional<int> parse_generator_search(int argc, char** argv, generator_search_options& o);
std::optional<int> parse_head_study(int argc, char** argv, head_study_options& o);
std::optional<int> parse_sqmul_study(int argc, char** argv, sqmul_study_options& o);
std::optional<int> parse_components_study(int argc, char** argv, components_study_options& o);
std::optional<int> parse_edge_study(int argc, char** argv, edge_study_options& o);
std::optional<int> parse_two_line_study(int argc, char** argv, two_line_study_options& o);
std::optional<int> parse_cell_study(int argc, char** argv, cell_study_options& o);
std::optional<int> parse_render_cells(int argc, char** argv, render_cells_options& o);
std::optional<int> parse_render_race(int argc, char** argv, render_race_options& o);

}  // namespace shading::tb
