// Every program's command line but render_pipeline's (bench_options.h, tool_options.h) parsed with
// CLI11, with the same names, checks and help texts the programs had when each built its own CLI11
// App. One source for all of them: each source that includes CLI11 pays its inline classes and
// global validators again (render_options.cpp is the only other one).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "bench_options.h"
#include "cli_parse.h"
#include "formats/interp_formats.h"
#include "tool_options.h"

namespace shading::tb {

namespace {

// The built-in scene a study renders (components_study, edge_study): its name, size, where the head
// scan lies and the specular device.
void add_study_scene(CLI::App& app, std::string& scene, unsigned& size, std::string& data_dir, std::string& device) {
    app.add_option("--scene", scene, "built-in scene")->check(CLI::IsMember({"head", "sphere", "torus"}));
    app.add_option("--size", size, "image width and height")->check(CLI::Range(16u, 4096u));
    app.add_option("--data-dir", data_dir, "repository root holding data/head/");
    app.add_option("--device", device, "specular device")->check(CLI::IsMember(device_names()));
}

// The common options, added before the program's own (their order in --help).
void add_bench_options(CLI::App& app, bench_options& b, const std::string& default_vcd, bool with_mode) {
    b.vcd = default_vcd;
    b.with_mode = with_mode;
    if (const char* s = std::getenv("SHADING_SUMMARY")) b.summary = s;
    app.add_option("--vcd", b.vcd, "write <stem>.vcd (default " + default_vcd + "; random mode: only when given)");
    app.add_flag("--no-vcd", b.no_vcd, "write no VCD");
    app.add_option("--summary", b.summary, "append TSV summary rows here (default: $SHADING_SUMMARY)");
    if (with_mode)
        app.add_option("--mode", b.mode, "ADD11 overflow: saturate (default) or wrap (patent-faithful)")
            ->check(CLI::IsMember({"saturate", "wrap"}));
    app.add_option("--seed", b.seed, "seed of the random stimuli (default 1)");
    app.add_option("--random", b.random, "random differential mode: N random stimuli against the golden model")
        ->check(CLI::Range(uint64_t{1}, max_random));
    // Hidden (empty group): the CI proves with it that a mismatch makes the program fail.
    app.add_option("--inject-mismatch", b.inject, "corrupt the golden value of sample K (0-based)")->group("");
    app.add_option("--inject-count", b.inject_count, "corrupt C samples from K on (256 must not exit 0)")->group("");
    app.add_option("--jobs", b.jobs, "random mode: J independent processes (default: one per core from 100000 stimuli)")
        ->check(CLI::Range(1u, max_jobs));
}

// The TLM benches' two run lengths, in pixels rounded up to whole `unit`s (lines or bursts).
void add_pixel_options(CLI::App& app, std::size_t& lt, std::size_t& pin, const std::string& unit) {
    const auto pixels = CLI::Range(std::size_t{1}, std::size_t{1'000'000'000'000});
    app.add_option("--lt-pixels", lt, "pixels shaded loosely timed (whole " + unit + ")")->check(pixels);
    app.add_option("--pin-pixels", pin, "pixels shaded pin-accurate (whole " + unit + ")")->check(pixels);
}

// Parses, then derives what depends on which options were given.
std::optional<int> parse_bench(CLI::App& app, int argc, char** argv, bench_options& b) {
    SHADING_CLI_PARSE(app, argc, argv);
    b.vcd_given = app.count("--vcd") > 0;
    if (app.count("--jobs") == 0) b.jobs = 0;
    if (b.random > 0 && !b.vcd_given) b.no_vcd = true;  // 10^7 stimuli make a huge VCD
    if (const auto* o = app.get_option_no_throw("--csv"); o != nullptr && o->count() > 0)
        b.csv = o->as<std::string>();
    return std::nullopt;
}

const CLI::IsMember abstractions({"block", "fast"});

}  // namespace

std::optional<int> parse_ua60553(int argc, char** argv, ua60553_options& o) {
    CLI::App app("UA 60553 specular-colour device: Fig. 3 replay against the golden model");
    add_bench_options(app, o.bench, "traces/ua60553", true);
    app.add_option("--generator", o.generator,
                   "generator of a: patent (MUL6 + ADD15 with the patent's constants), minimax or rom_matched "
                   "(the tuned device)")
        ->check(CLI::IsMember({"patent", "minimax", "rom_matched"}));
    app.add_flag("--sweep", o.sweep, "stream every cos code 0..0x8000 instead of a scene line");
    app.add_option("--n", o.ns, "specular exponents (default: 10 100 for the scene, 1 10 100 512 1000 for --sweep)");
    app.add_option("--scene-pixels", o.scene_pixels, "pixels of the sphere's raster line")->check(CLI::Range(2u, 100000u));
    app.add_option("--t-low-ns", o.t_low_ns, "ctl17 low phase = settling time T (Fig. 3)")->check(CLI::PositiveNumber)->check(not_nan());
    app.add_option("--t-high-ns", o.t_high_ns, "ctl17 high phase")->check(CLI::PositiveNumber)->check(not_nan());
    app.add_option("--abstraction", o.abstraction,
                   "device model: block (every block of Fig. 1, per-block waveform) or fast (one process at the "
                   "pins, the same pin timing; specular/specular_fast.h)")
        ->check(abstractions);
    app.add_flag("--zero-delays", o.zero_delays, "every block delay 0: the network settles in delta time");
    return parse_bench(app, argc, argv, o.bench);
}

std::optional<int> parse_ua22802(int argc, char** argv, ua22802_options& o) {
    CLI::App app("UA 22802 (ROM prototype): Fig. 3 replay against the golden model");
    add_bench_options(app, o.bench, "traces/ua22802", true);
    app.add_option("--pixels", o.pixels, "pixels per surface (half over [0,1], half where cos^n >= 0.56)")
        ->check(CLI::Range(2u, 100000u));
    app.add_option("--n", o.ns, "specular exponents, one surface each")->check(CLI::Range(0u, 1023u));
    app.add_option("--abstraction", o.abstraction,
                   "device model: block (every block of Fig. 1) or fast (one process at the pins; "
                   "specular/specular_fast.h)")
        ->check(abstractions);
    return parse_bench(app, argc, argv, o.bench);
}

namespace {
// The clocked devices' benches (squared_tb, sqmul_tb): their options are the same.
std::optional<int> parse_clocked(int argc, char** argv, squared_options& o, const char* what, const char* trace,
                                 const char* clk_help, const char* fast_help) {
    CLI::App app(what);
    add_bench_options(app, o.bench, trace, true);
    app.add_flag("--sweep", o.sweep, "stream every cos code 0..0x8000 instead of a scene line");
    app.add_option("--n", o.ns, "specular exponents (default: 10 100 1000 for the scene, 1 3 10 100 512 1000 "
                                "for --sweep)")
        ->check(CLI::Range(0u, 1023u));
    app.add_option("--scene-pixels", o.scene_pixels, "pixels of the sphere's raster line")->check(CLI::Range(2u, 100000u));
    app.add_option("--clk-ns", o.clk_ns, clk_help)->check(CLI::Range(1.0, 1000.0))->check(not_nan());
    app.add_option("--abstraction", o.abstraction, fast_help)->check(abstractions);
    return parse_bench(app, argc, argv, o.bench);
}
}  // namespace

std::optional<int> parse_squared(int argc, char** argv, squared_options& o) {
    return parse_clocked(argc, argv, o, "Squared-quadratic specular device: Fig. 3 with its clock, against the golden model",
                         "traces/squared", "the squaring stage's clock period (strobe 17: 12 clocks low, 1 high)",
                         "device model: block (every block, per-block waveform) or fast (one process at the pins, "
                         "the same pin timing; squared/squared_fast.h)");
}

std::optional<int> parse_sqmul(int argc, char** argv, sqmul_options& o) {
    return parse_clocked(argc, argv, o, "Square-and-multiply specular device: Fig. 3 with its clock, against the golden model",
                         "traces/sqmul", "the stage's clock period (strobe 17: 21 clocks low, 1 high)",
                         "device model: block (every block, per-block waveform) or fast (one process at the pins, "
                         "the same pin timing; sqmul/sqmul_fast.h)");
}

std::optional<int> parse_interp_coef(int argc, char** argv, interp_coef_options& o) {
    CLI::App app("The interpolation paper's coefficient units: raster-line samples against the golden models");
    add_bench_options(app, o.bench, "traces/interp_coef", false);
    app.add_option("--csv", o.csv_path, "write per-interval A and C (real, shift-and-add, exact) here");
    app.add_option("--width", o.width, "pixels of the raster line")->check(CLI::Range(1u, 100000u));
    app.add_option("--m", o.m, "interval of 2^m pixels")->check(CLI::Range(interp::m_min, 8u));
    app.add_option("--extra-sets", o.n_extra, "random sample sets streamed after the line (fixed seed 2024)")
        ->check(CLI::Range(0u, 1000000u));
    return parse_bench(app, argc, argv, o.bench);
}

std::optional<int> parse_interp_fd(int argc, char** argv, interp_fd_options& o) {
    CLI::App app("Forward-difference evaluator: one raster line, every variant, against the golden models");
    add_bench_options(app, o.bench, "traces/interp_fd", false);
    app.add_option("--csv", o.csv_path, "per-pixel CSV: unit,variant,pixel,t,exact,value,error");
    app.add_option("--width", o.width, "pixels of the raster line")->check(CLI::Range(1u, 100000u));
    app.add_option("--m", o.m, "interval of 2^m pixels")->check(CLI::Range(interp::m_min, interp::m_max));
    return parse_bench(app, argc, argv, o.bench);
}

std::optional<int> parse_interp_horner(int argc, char** argv, interp_horner_options& o) {
    CLI::App app("The interpolation paper's iterative Horner unit: one raster line, every variant, against the golden model");
    add_bench_options(app, o.bench, "traces/interp_horner", false);
    app.add_option("--csv", o.csv_path, "per-pixel CSV: unit,variant,pixel,t,exact,value,error");
    app.add_option("--width", o.width, "pixels of the raster line")->check(CLI::Range(1u, 100000u));
    app.add_option("--m", o.m, "interval of 2^m pixels, t = k/2^m")->check(CLI::Range(interp::m_min, 8u));
    app.add_option("--gap", o.gap, "idle clocks after each result (default 0: back to back)")
        ->check(CLI::Range(0u, 100u));
    app.add_option("--abstraction", o.abstraction, "block (Fig. 4's blocks, default) or fast (the same pins, one process)")
        ->check(abstractions);
    return parse_bench(app, argc, argv, o.bench);
}

std::optional<int> parse_interp_line(int argc, char** argv, interp_line_options& o) {
    CLI::App app("Raster-line interpolator (coefficient unit + forward differences) against the golden chain");
    add_bench_options(app, o.bench, "traces/interp_line", false);
    const std::map<std::string, interp::div3_mode> div3_names{{"shift-add", interp::div3_mode::shift_add},
                                                              {"exact", interp::div3_mode::exact}};
    app.add_option("--width", o.width, "pixels of the raster line")->check(CLI::Range(1u, 100000u));
    app.add_option("--m", o.m, "interval of 2^m pixels")->check(CLI::Range(interp::m_min, interp::m_max));
    app.add_option("--case", o.sample_case, "sample set: 1 (t = 0, 1/4, 1/2, 1) or 2 (t = 0, 1/2, 3/4, 1)")
        ->check(CLI::Range(1u, 2u));
    app.add_option("--div3", o.div3, "division by 3: shift-add (the interpolation paper, Fig. 2) or exact")
        ->transform(CLI::CheckedTransformer(div3_names, CLI::ignore_case));
    return parse_bench(app, argc, argv, o.bench);
}

// The studies and tools.

const char* default_data_dir() { return SHADING_SOURCE_DIR; }

std::optional<int> parse_interp_study(int argc, char** argv, interp_study_options& o) {
    CLI::App app{"NMSE of the interpolation paper's interpolation against the exact intensity, per interval length"};
    app.add_option("--csv", o.csv, "output CSV");
    app.add_option("--width", o.width, "pixels of the raster line")->check(CLI::Range(8u, 100000u));
    app.add_option("--grouping-csv", o.grouping_csv,
                   "CSV of the /3 grouping study (default: interp_div3_grouping.csv beside --csv)");
    SHADING_CLI_PARSE(app, argc, argv);
    if (o.grouping_csv.empty())
        o.grouping_csv = (std::filesystem::path(o.csv).parent_path() / "interp_div3_grouping.csv").string();
    return std::nullopt;
}

std::optional<int> parse_soak(int argc, char** argv, soak_options& o) {
    CLI::App app{"The head rendered R times in one process by the fast SystemC pipeline; resident memory"};
    app.add_option("--renders", o.renders, "renders of the head")->check(CLI::Range(2u, 100000u));
    app.add_option("--size", o.size, "image width and height")->check(CLI::Range(8u, 1024u));
    SHADING_CLI_PARSE(app, argc, argv);
    return std::nullopt;
}

std::optional<int> parse_render_reference(int argc, char** argv, render_reference_options& o) {
    CLI::App app{"Per-pixel reference renders (Phong, and shading through a specular device's golden model) to PNG"};
    app.add_option("--scene", o.scene, "built-in scene (sphere, torus, head) or a path to an OBJ file");
    app.add_option("--size", o.size, "image width and height in pixels")->check(CLI::Range(1u, 8192u));
    // Names, ranges and numbers are checked by the parser: any bad one is bad usage (exit 2).
    const auto devices = CLI::IsMember(device_names());
    app.add_option("--device", o.device, "specular device: patent, minimax, rom_matched, ua22802, squared, sqmul")
        ->check(devices);
    app.add_option("--compare", o.compare,
                   "devices (comma-separated) for compare.png: Phong and their images above their error maps")
        ->delimiter(',')
        ->check(devices);
    app.add_option("--mode", o.mode, "overflow mode of the device's ADD11: saturate or wrap")
        ->check(CLI::IsMember({"saturate", "wrap"}));
    app.add_option("--n", o.n, "override the material's exponent n (1..1000)")->check(CLI::Range(1u, 1000u));
    app.add_option("--error-scale", o.error_scale, "8-bit error shown as white in the heat map")->check(CLI::PositiveNumber)->check(not_nan());
    app.add_option("--depth-step", o.depth_step, "depth jump (world units) that splits a raster line")
        ->check(CLI::PositiveNumber)->check(not_nan());
    app.add_option("--out", o.out, "output folder");
    app.add_option("--data-dir", o.data_dir, "repository root holding data/head/ (for the built-in head)");
    SHADING_CLI_PARSE(app, argc, argv);
    return std::nullopt;
}

std::optional<int> parse_bench_specular_tlm(int argc, char** argv, bench_specular_tlm_options& o) {
    CLI::App app{"Throughput of the specular TLM-2.0 wrapper, loosely timed and pin-accurate"};
    app.add_option("--device", o.device, "specular device: patent, minimax, rom_matched, ua22802, squared, sqmul")
        ->check(CLI::IsMember(device_names()));
    add_pixel_options(app, o.lt_pixels, o.pin_pixels, "lines");
    app.add_option("--burst", o.burst, "pixels per access (1: one transaction per write and per read)")
        ->check(CLI::Range(1u, 1024u));
    SHADING_CLI_PARSE(app, argc, argv);
    return std::nullopt;
}

std::optional<int> parse_bench_line_tlm(int argc, char** argv, bench_line_tlm_options& o) {
    CLI::App app{"Throughput of the raster-line unit's TLM-2.0 wrapper, loosely timed and pin-accurate"};
    add_pixel_options(app, o.lt_pixels, o.pin_pixels, "bursts");
    app.add_option("--burst", o.burst, "32-pixel intervals per access (1: one transaction per interval and direction)")
        ->check(CLI::Range(1u, 256u));
    SHADING_CLI_PARSE(app, argc, argv);
    return std::nullopt;
}

std::optional<int> parse_accuracy_study(int argc, char** argv, accuracy_study_options& o) {
    CLI::App app{"accuracy study of the quadratic BRDF, the UA 22802 / UA 60553 devices and the squared-quadratic law"};
    app.add_option("--out", o.out, "output directory");
    app.add_option("--fig2-n", o.fig2_n, "n of the Fig. 2 curve")->check(CLI::Range(1u, 1000u));
    app.add_option("--n-max", o.n_max, "study n in [1, n-max] (a short run for the tests)")->check(CLI::Range(1u, 1000u));
    app.add_option("--size", o.size, "the head's image size for the cos distribution")->check(CLI::Range(16u, 4096u));
    app.add_option("--data-dir", o.data_dir, "repository root holding data/head/");
    SHADING_CLI_PARSE(app, argc, argv);
    o.fig2_n = std::min(o.fig2_n, o.n_max);
    return std::nullopt;
}

std::optional<int> parse_generator_search(int argc, char** argv, generator_search_options& o) {
    CLI::App app{"search for the ROM-free a(n) generator with the smallest worst-case error"};
    app.add_option("--csv", o.csv, "output CSV");
    app.add_option("--keep", o.keep, "keep candidates whose worst max rel error is below this")
        ->check(not_nan());
    SHADING_CLI_PARSE(app, argc, argv);
    return std::nullopt;
}

std::optional<int> parse_head_study(int argc, char** argv, head_study_options& o) {
    CLI::App app{"the head per device and n, and the squared-quadratic device's fit"};
    app.add_option("--out", o.out, "output directory");
    app.add_option("--size", o.size, "the head's image size")->check(CLI::Range(16u, 4096u));
    app.add_option("--n", o.ns, "exponents to render (comma-separated, 1..1000)")->delimiter(',')->check(CLI::Range(1u, 1000u));
    app.add_option("--data-dir", o.data_dir, "repository root holding data/head/");
    app.add_option("--scan-max", o.scan_max,
                   "the baseline and every bend variant (the device is s2) against Phong for every n in [1, scan-max] "
                   "(0: none)")
        ->check(CLI::Range(0u, 1000u));
    SHADING_CLI_PARSE(app, argc, argv);  // an n outside 1..1000 is bad usage (exit 2)
    return std::nullopt;
}

std::optional<int> parse_sqmul_study(int argc, char** argv, sqmul_study_options& o) {
    CLI::App app{"the square-and-multiply designs, left to right and right to left, at P words Q1.15..Q1.20"};
    app.add_option("--out", o.out, "output directory");
    app.add_option("--size", o.size, "the head's image size")->check(CLI::Range(16u, 4096u));
    app.add_option("--n", o.ns, "exponents to render (comma-separated, 1..1000)")->delimiter(',')->check(CLI::Range(1u, 1000u));
    app.add_option("--n-max", o.n_max, "relative errors over n in [1, n-max]")->check(CLI::Range(1u, 1000u));
    app.add_option("--data-dir", o.data_dir, "repository root holding data/head/");
    SHADING_CLI_PARSE(app, argc, argv);
    return std::nullopt;
}

std::optional<int> parse_components_study(int argc, char** argv, components_study_options& o) {
    CLI::App app{"the shading components interpolated apart (as the interpolation paper does) against their sum"};
    add_study_scene(app, o.scene, o.size, o.data_dir, o.device);
    app.add_option("--nmse", o.nmse, "the interpolation NMSE allowed (0..1]")->check(CLI::Range(1e-12, 1.0));
    const auto tol = CLI::Range(1e-3, 64.0);
    app.add_option("--tol-sum", o.tol_sum, "the sum's tolerances (8-bit levels, comma-separated)")->delimiter(',')->check(tol);
    app.add_option("--tol-diffuse", o.tol_diffuse, "ambient + diffuse tolerances")->delimiter(',')->check(tol);
    app.add_option("--tol-specular", o.tol_specular, "specular tolerances")->delimiter(',')->check(tol);
    const auto m = CLI::Range(interp::m_min, interp::m_max);
    app.add_option("--m-max-sum", o.m_max_sum, "the sum's longest interval 2^m")->check(m);
    app.add_option("--m-max-diffuse", o.m_max_diffuse, "ambient + diffuse longest interval 2^m")->check(m);
    app.add_option("--m-max-specular", o.m_max_specular, "specular longest interval 2^m")->check(m);
    SHADING_CLI_PARSE(app, argc, argv);
    return std::nullopt;
}

std::optional<int> parse_edge_study(int argc, char** argv, edge_study_options& o) {
    CLI::App app{"where a polynomial through a raster line's samples misses: inside one triangle or across an edge"};
    add_study_scene(app, o.scene, o.size, o.data_dir, o.device);
    app.add_option("--spacing", o.spacings, "sample spacings in pixels (powers of two 1..64, comma-separated)")
        ->delimiter(',')
        ->check(CLI::IsMember({1u, 2u, 4u, 8u, 16u, 32u, 64u}));
    SHADING_CLI_PARSE(app, argc, argv);
    if (o.spacings.empty()) {
        std::fprintf(stderr, "edge_study: --spacing needs at least one value\n");
        return 2;
    }
    // CLI11 reads an empty value ("--spacing ''") as 0 without asking the check above.
    for (unsigned h : o.spacings)
        if (h < 1 || h > 64 || (h & (h - 1)) != 0) {
            std::fprintf(stderr, "edge_study: --spacing: %u is not a power of two 1..64\n", h);
            return 2;
        }
    return std::nullopt;
}

std::optional<int> parse_two_line_study(int argc, char** argv, two_line_study_options& o) {
    CLI::App app{"every other line predicted from the lines either side, the adaptive policy on the residual"};
    add_study_scene(app, o.scene, o.size, o.data_dir, o.device);
    app.add_option("--nmse", o.nmse, "the interpolation NMSE allowed (0..1]")->check(CLI::Range(1e-12, 1.0));
    const auto tol = CLI::Range(1e-3, 64.0);
    app.add_option("--tol-one", o.tol_one, "one line at a time: tolerances (8-bit levels, comma-separated)")
        ->delimiter(',')
        ->check(tol);
    app.add_option("--tol-even", o.tol_even, "two lines: the even lines' tolerances (with --tol-mid also every fourth line's)")
        ->delimiter(',')
        ->check(tol);
    app.add_option("--tol-odd", o.tol_odd, "two lines: the odd lines' tolerances (on the residual)")
        ->delimiter(',')
        ->check(tol);
    app.add_option("--tol-mid", o.tol_mid,
                   "every fourth line first (not run without): the tolerances of the lines between them two apart "
                   "(on the residual)")
        ->delimiter(',')
        ->check(tol);
    app.add_option("--m-max", o.m_max, "the longest interval 2^m")->check(CLI::Range(interp::m_min, interp::m_max));
    app.add_option("--above-slack", o.above_slack, "the line-above limit K (render_pipeline's; -1: none)")
        ->check(CLI::Range(-1, int(interp::m_max)));
    app.add_flag("--walk-edges", o.walk_edges,
                 "the geometry side and the scan-line Phong walk each triangle's values from line to line "
                 "(render_pipeline's)");
    app.add_flag("--perfect-decisions", o.perfect_decisions,
                 "a yardstick: every decision, the planner's and the emulation's, taken on the true RMS error of what "
                 "the interval sends (render_pipeline's), every check point still paid");
    SHADING_CLI_PARSE(app, argc, argv);
    // CLI11 converts an empty list value without asking the check (edge_study's --spacing '').
    for (const auto* list : {&o.tol_one, &o.tol_even, &o.tol_odd, &o.tol_mid}) {
        if (list->empty() && list != &o.tol_mid) {  // --tol-mid may be empty: no four-line table
            std::fprintf(stderr, "two_line_study: every tolerance list needs at least one value\n");
            return 2;
        }
        for (double t : *list)
            if (!(t >= 1e-3 && t <= 64.0)) {
                std::fprintf(stderr, "two_line_study: a tolerance of %g is outside 0.001..64\n", t);
                return 2;
            }
    }
    return std::nullopt;
}

std::optional<int> parse_render_cells(int argc, char** argv, render_cells_options& o) {
    CLI::App app{"the cells rendered in SystemC: the cell unit and the shading pipeline against the golden frame"};
    app.add_option("--scene", o.scene, "built-in scene")->check(CLI::IsMember({"head", "sphere", "torus"}));
    app.add_option("--size", o.size, "image width and height")->check(CLI::Range(16u, 1024u));
    app.add_option("--data-dir", o.data_dir, "repository root holding data/head/");
    app.add_option("--device", o.device, "specular device")->check(CLI::IsMember(device_names()));
    app.add_option("--light", o.light, "one directional light instead of the scene's: azimuth,elevation in degrees")
        ->delimiter(',')
        ->expected(2)
        ->check(CLI::Range(-360.0, 360.0))
        ->check(not_nan());
    app.add_option("--n", o.n, "the specular exponent instead of the scene's (1..1000)")->check(CLI::Range(1u, 1000u));
    app.add_option("--tol", o.tol, "the cells' tolerance (8-bit levels)")->check(CLI::Range(1e-3, 64.0))->check(not_nan());
    app.add_flag("--walk-edges", o.walk_edges,
                 "count the geometry side and the scan-line Phong walking each triangle's values from line to line");
    SHADING_CLI_PARSE(app, argc, argv);
    if (!o.light.empty() && (o.light.size() != 2 || !(std::abs(o.light[1]) <= 90.0))) {
        std::fprintf(stderr, "render_cells: --light needs azimuth,elevation with the elevation in -90..90\n");
        return 2;
    }
    return std::nullopt;
}

std::optional<int> parse_render_race(int argc, char** argv, render_race_options& o) {
    CLI::App app{"the race: Phong 1975, Gouraud, Bishop-Weimer, Lyon, the interpolation paper's lines and the cells on "
                 "one frame, against exact Phong"};
    app.add_option("--scene", o.scene, "built-in scene (head, sphere, torus) or an OBJ file (a path ending in .obj)");
    app.add_option("--size", o.size, "image width and height")->check(CLI::Range(16u, 2048u));
    app.add_option("--data-dir", o.data_dir, "repository root holding data/head/");
    app.add_option("--device", o.device, "specular device")->check(CLI::IsMember(device_names()));
    app.add_option("--light", o.light, "one directional light instead of the scene's: azimuth,elevation in degrees")
        ->delimiter(',')
        ->expected(2)
        ->check(CLI::Range(-360.0, 360.0))
        ->check(not_nan());
    app.add_option("--n", o.n, "the specular exponent (1..1000)")->check(CLI::Range(1u, 1000u));
    app.add_option("--out", o.out, "folder for race.md, race.csv and race_sheet.png");
    app.add_option("--error-scale", o.error_scale, "levels at white on the error maps")
        ->check(CLI::PositiveNumber)
        ->check(not_nan());
    app.add_flag("!--no-sim", o.sim, "skip the cells' SystemC run");
    auto* tuned = app.add_option_group("not frozen", "a setting other than the frozen one: an extra row, marked");
    tuned->add_option("--cells-tol", o.cells_tol, "the cells' tolerance (levels)")->check(CLI::Range(1e-3, 64.0));
    tuned->add_option("--line-tol", o.line_tol, "the lines' length tolerance (levels)")->check(CLI::Range(1e-3, 64.0));
    tuned->add_option("--fast-phong-budget", o.fast_phong_budget, "the split fast Phong's budget (levels)")
        ->check(CLI::Range(1e-3, 64.0));
    SHADING_CLI_PARSE(app, argc, argv);
    if (!o.light.empty() && (o.light.size() != 2 || !(std::abs(o.light[1]) <= 90.0))) {
        std::fprintf(stderr, "render_race: --light needs azimuth,elevation with the elevation in -90..90\n");
        return 2;
    }
    return std::nullopt;
}

std::optional<int> parse_cell_study(int argc, char** argv, cell_study_options& o) {
    CLI::App app{"a quadtree of biquadratic cells decided from its lattices' differences, the lines for the rest"};
    add_study_scene(app, o.scene, o.size, o.data_dir, o.device);
    app.add_option("--light", o.light, "one directional light instead of the scene's: azimuth,elevation in degrees "
                                       "(render_pipeline's)")
        ->delimiter(',')
        ->expected(2)
        ->check(CLI::Range(-360.0, 360.0))
        ->check(not_nan());
    app.add_option("--n", o.n, "the specular exponent instead of the scene's (1..1000)")->check(CLI::Range(1u, 1000u));
    app.add_option("--nmse", o.nmse, "the interpolation NMSE allowed (0..1]")->check(CLI::Range(1e-12, 1.0))->check(not_nan());
    const auto tol = CLI::Range(1e-3, 64.0);
    app.add_option("--tol", o.tol, "the cells' tolerances (8-bit levels, comma-separated)")->delimiter(',')->check(tol);
    const auto factor = CLI::Range(1e-2, 1e3);
    app.add_option("--d2-factor", o.d2_factor, "a cell's lattice second differences allowed, x the tolerance")->check(factor)->check(not_nan());
    app.add_option("--d3-factor", o.d3_factor, "its family's third differences (x k3) allowed, x the tolerance")->check(factor)->check(not_nan());
    app.add_option("--fallback-tol", o.fallback_tol, "the smallest cells' row quadratics: their check points' miss allowed (levels)")
        ->check(tol)
        ->check(not_nan());
    app.add_option("--line-tol", o.line_tol, "the rest, by the adaptive policy along columns and rows: its tolerance (levels)")
        ->check(tol)
        ->check(not_nan());
    app.add_option("--cell-max", o.cell_max, "the tiles' size, a power of two 4..256")
        ->check(CLI::IsMember({4u, 8u, 16u, 32u, 64u, 128u, 256u}));
    app.add_option("--m-max", o.m_max, "the lines' longest interval 2^m")->check(CLI::Range(interp::m_min, interp::m_max));
    app.add_flag("--walk-edges", o.walk_edges,
                 "the geometry side and the scan-line Phong walk each triangle's values from line to line "
                 "(render_pipeline's)");
    app.add_flag("--perfect-decisions", o.perfect_decisions,
                 "a yardstick: every cell and run decided on the true RMS error of what it sends, every point still read");
    app.add_flag("--golden", o.golden,
                 "the bit-accurate cells (the sample stage's codes, forward differences, the rest by the planner down "
                 "columns and along rows) instead of the real-valued emulation");
    SHADING_CLI_PARSE(app, argc, argv);
    if (o.golden && (o.perfect_decisions || o.cell_max > (1u << interp::m_max))) {
        std::fprintf(stderr, "cell_study: --golden takes no --perfect-decisions and cells of at most %u pixels\n",
                     1u << interp::m_max);
        return 2;
    }
    if (!o.light.empty() && (o.light.size() != 2 || !(std::abs(o.light[1]) <= 90.0))) {
        std::fprintf(stderr, "cell_study: --light needs azimuth,elevation with the elevation in -90..90\n");
        return 2;
    }
    if (o.tol.empty()) {  // CLI11 converts an empty list value without asking the check
        std::fprintf(stderr, "cell_study: --tol needs at least one value\n");
        return 2;
    }
    for (double t : o.tol)
        if (!(t >= 1e-3 && t <= 64.0)) {
            std::fprintf(stderr, "cell_study: a tolerance of %g is outside 0.001..64\n", t);
            return 2;
        }
    return std::nullopt;
}

}  // namespace shading::tb
