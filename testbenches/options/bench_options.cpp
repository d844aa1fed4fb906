// The testbench programs' command lines (bench_options.h) parsed with CLI11: the options common
// to every bench, then each program's own, with the same names, checks and help texts the programs
// had when each built its own CLI11 App.
#include "bench_options.h"

#include <cstdlib>
#include <map>

#include "cli_parse.h"

namespace shading::tb {

namespace {

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

std::optional<int> parse_squared(int argc, char** argv, squared_options& o) {
    CLI::App app("Squared-quadratic specular device: Fig. 3 with its clock, against the golden model");
    add_bench_options(app, o.bench, "traces/squared", true);
    app.add_flag("--sweep", o.sweep, "stream every cos code 0..0x8000 instead of a scene line");
    app.add_option("--n", o.ns, "specular exponents (default: 10 100 1000 for the scene, 1 3 10 100 512 1000 "
                                "for --sweep)")
        ->check(CLI::Range(0u, 1023u));
    app.add_option("--scene-pixels", o.scene_pixels, "pixels of the sphere's raster line")->check(CLI::Range(2u, 100000u));
    app.add_option("--clk-ns", o.clk_ns, "the squaring stage's clock period (strobe 17: 12 clocks low, 1 high)")
        ->check(CLI::Range(1.0, 1000.0))->check(not_nan());
    app.add_option("--abstraction", o.abstraction,
                   "device model: block (every block, per-block waveform) or fast (one process at the pins, "
                   "the same pin timing; squared/squared_fast.h)")
        ->check(abstractions);
    return parse_bench(app, argc, argv, o.bench);
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

}  // namespace shading::tb
