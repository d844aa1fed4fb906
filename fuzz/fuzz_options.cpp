// Fuzz target: every program's command line. The options library (testbenches/options/) parses
// each program's argv into a plain struct with no side effect, so the parse functions are called
// here directly. The first input byte picks the program (modulo the table below: 0 interp_coef_tb,
// 1 ua60553_tb, 2 interp_fd_tb, 3 ua22802_tb, ... - even low numbers a bench without --mode, odd
// ones a bench with it, as the first byte's low bit chose before); the rest is split at NUL bytes
// into up to 24 arguments of at most 64 bytes. For every program the parse must return an exit
// status of 0 (--help) or 2 (bad usage), or accept the line with every value inside the range or
// set the program documents (written out below from the programs' comments and help, not by
// calling the parser's validators); any other outcome (another status, an exception escaping, a
// sanitizer report) is a finding. A --random run's split into processes happens after parsing
// (bench_runner::start), so no line starts a process here.
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "fuzz_check.h"
#include "testbenches/options/bench_options.h"
#include "testbenches/options/tool_options.h"
#if SHADING_FUZZ_RENDER_OPTIONS
#include "testbenches/options/render_options.h"
#endif

namespace {

using namespace shading::tb;
using names = std::set<std::string>;

const names abstractions{"block", "fast"}, modes{"saturate", "wrap"};

bool in(const names& set, const std::string& v) { return set.count(v) > 0; }
bool positive(double v) { return v > 0 && std::isfinite(v); }
template <typename T, typename U>
bool within(T v, U lo, U hi) { return v >= static_cast<T>(lo) && v <= static_cast<T>(hi); }
bool device(const std::string& d) {
    for (const auto& n : device_names())
        if (n == d) return true;
    return false;
}

// bench_options.h's common options, given the program's default VCD stem and whether it has --mode.
void check_bench(const bench_options& b, const char* default_vcd, bool with_mode) {
    FUZZ_CHECK(in(modes, b.mode), "--mode '%s' accepted", b.mode.c_str());
    FUZZ_CHECK(with_mode || b.mode == "saturate", "--mode '%s' accepted by a program without it", b.mode.c_str());
    FUZZ_CHECK(b.random == 0 || within(b.random, uint64_t{1}, uint64_t{1} << 40), "--random %llu accepted",
               static_cast<unsigned long long>(b.random));
    FUZZ_CHECK(b.jobs == 0 || within(b.jobs, 1u, 1024u), "--jobs %u accepted", b.jobs);
    FUZZ_CHECK(b.vcd_given || b.vcd == default_vcd, "the VCD stem '%s' without --vcd", b.vcd.c_str());
    FUZZ_CHECK(b.random == 0 || b.vcd_given || b.no_vcd, "--random without --vcd writes a VCD");
}

void check_ns(const std::vector<unsigned>& ns, unsigned hi) {
    for (unsigned n : ns) FUZZ_CHECK(n <= hi, "--n %u accepted", n);
}

// One program: its parse function and the check of an accepted line.
struct program {
    const char* name;
    std::optional<int> (*fuzz)(int argc, char** argv);
};

std::optional<int> ua60553(int argc, char** argv) {
    ua60553_options o;
    if (auto rc = parse_ua60553(argc, argv, o)) return rc;
    check_bench(o.bench, "traces/ua60553", true);
    FUZZ_CHECK(in({"patent", "minimax", "rom_matched"}, o.generator), "--generator '%s'", o.generator.c_str());
    FUZZ_CHECK(within(o.scene_pixels, 2u, 100000u), "--scene-pixels %u", o.scene_pixels);
    FUZZ_CHECK(positive(o.t_low_ns) && positive(o.t_high_ns), "--t-low-ns %g --t-high-ns %g", o.t_low_ns, o.t_high_ns);
    FUZZ_CHECK(in(abstractions, o.abstraction), "--abstraction '%s'", o.abstraction.c_str());
    return std::nullopt;
}

std::optional<int> ua22802(int argc, char** argv) {
    ua22802_options o;
    if (auto rc = parse_ua22802(argc, argv, o)) return rc;
    check_bench(o.bench, "traces/ua22802", true);
    FUZZ_CHECK(within(o.pixels, 2u, 100000u), "--pixels %u", o.pixels);
    check_ns(o.ns, 1023);
    FUZZ_CHECK(in(abstractions, o.abstraction), "--abstraction '%s'", o.abstraction.c_str());
    return std::nullopt;
}

std::optional<int> squared(int argc, char** argv) {
    squared_options o;
    if (auto rc = parse_squared(argc, argv, o)) return rc;
    check_bench(o.bench, "traces/squared", true);
    check_ns(o.ns, 1023);
    FUZZ_CHECK(within(o.scene_pixels, 2u, 100000u), "--scene-pixels %u", o.scene_pixels);
    FUZZ_CHECK(o.clk_ns >= 1.0 && o.clk_ns <= 1000.0, "--clk-ns %g", o.clk_ns);
    FUZZ_CHECK(in(abstractions, o.abstraction), "--abstraction '%s'", o.abstraction.c_str());
    return std::nullopt;
}

std::optional<int> sqmul(int argc, char** argv) {
    sqmul_options o;
    if (auto rc = parse_sqmul(argc, argv, o)) return rc;
    check_bench(o.bench, "traces/sqmul", true);
    check_ns(o.ns, 1023);
    FUZZ_CHECK(within(o.scene_pixels, 2u, 100000u), "--scene-pixels %u", o.scene_pixels);
    FUZZ_CHECK(o.clk_ns >= 1.0 && o.clk_ns <= 1000.0, "--clk-ns %g", o.clk_ns);
    FUZZ_CHECK(in(abstractions, o.abstraction), "--abstraction '%s'", o.abstraction.c_str());
    return std::nullopt;
}

std::optional<int> interp_coef(int argc, char** argv) {
    interp_coef_options o;
    if (auto rc = parse_interp_coef(argc, argv, o)) return rc;
    check_bench(o.bench, "traces/interp_coef", false);
    FUZZ_CHECK(within(o.width, 1u, 100000u), "--width %u", o.width);
    FUZZ_CHECK(within(o.m, 2u, 8u), "--m %u", o.m);
    FUZZ_CHECK(o.n_extra <= 1000000u, "--extra-sets %u", o.n_extra);
    FUZZ_CHECK(o.bench.csv == o.csv_path, "the split's CSV '%s' is not --csv", o.bench.csv.c_str());
    return std::nullopt;
}

std::optional<int> interp_fd(int argc, char** argv) {
    interp_fd_options o;
    if (auto rc = parse_interp_fd(argc, argv, o)) return rc;
    check_bench(o.bench, "traces/interp_fd", false);
    FUZZ_CHECK(within(o.width, 1u, 100000u), "--width %u", o.width);
    FUZZ_CHECK(within(o.m, 2u, 6u), "--m %u", o.m);
    FUZZ_CHECK(o.bench.csv == o.csv_path, "the split's CSV '%s' is not --csv", o.bench.csv.c_str());
    return std::nullopt;
}

std::optional<int> interp_horner(int argc, char** argv) {
    interp_horner_options o;
    if (auto rc = parse_interp_horner(argc, argv, o)) return rc;
    check_bench(o.bench, "traces/interp_horner", false);
    FUZZ_CHECK(within(o.width, 1u, 100000u), "--width %u", o.width);
    FUZZ_CHECK(within(o.m, 2u, 8u), "--m %u", o.m);
    FUZZ_CHECK(o.gap <= 100u, "--gap %u", o.gap);
    FUZZ_CHECK(in(abstractions, o.abstraction), "--abstraction '%s'", o.abstraction.c_str());
    return std::nullopt;
}

std::optional<int> interp_line(int argc, char** argv) {
    interp_line_options o;
    if (auto rc = parse_interp_line(argc, argv, o)) return rc;
    check_bench(o.bench, "traces/interp_line", false);
    FUZZ_CHECK(within(o.width, 1u, 100000u), "--width %u", o.width);
    FUZZ_CHECK(within(o.m, 2u, 6u), "--m %u", o.m);
    FUZZ_CHECK(o.sample_case == 1 || o.sample_case == 2, "--case %u", o.sample_case);
    FUZZ_CHECK(o.div3 == shading::interp::div3_mode::shift_add || o.div3 == shading::interp::div3_mode::exact,
               "--div3 %d", static_cast<int>(o.div3));
    return std::nullopt;
}

std::optional<int> interp_study(int argc, char** argv) {
    interp_study_options o;
    if (auto rc = parse_interp_study(argc, argv, o)) return rc;
    FUZZ_CHECK(within(o.width, 8u, 100000u), "--width %u", o.width);
    FUZZ_CHECK(!o.grouping_csv.empty(), "no grouping CSV path");
    return std::nullopt;
}

std::optional<int> soak(int argc, char** argv) {
    soak_options o;
    if (auto rc = parse_soak(argc, argv, o)) return rc;
    FUZZ_CHECK(within(o.renders, 2u, 100000u), "--renders %u", o.renders);
    FUZZ_CHECK(within(o.size, 8u, 1024u), "--size %u", o.size);
    return std::nullopt;
}

std::optional<int> render_reference(int argc, char** argv) {
    render_reference_options o;
    if (auto rc = parse_render_reference(argc, argv, o)) return rc;
    FUZZ_CHECK(within(o.size, 1u, 8192u), "--size %u", o.size);
    FUZZ_CHECK(device(o.device), "--device '%s'", o.device.c_str());
    for (const auto& d : o.compare) FUZZ_CHECK(device(d), "--compare '%s'", d.c_str());
    FUZZ_CHECK(in(modes, o.mode), "--mode '%s'", o.mode.c_str());
    FUZZ_CHECK(o.n == 0 || within(o.n, 1u, 1000u), "--n %u", o.n);
    FUZZ_CHECK(positive(o.error_scale), "--error-scale %g", o.error_scale);
    FUZZ_CHECK(positive(o.depth_step), "--depth-step %g", o.depth_step);
    return std::nullopt;
}

std::optional<int> bench_specular_tlm(int argc, char** argv) {
    bench_specular_tlm_options o;
    if (auto rc = parse_bench_specular_tlm(argc, argv, o)) return rc;
    FUZZ_CHECK(device(o.device), "--device '%s'", o.device.c_str());
    const std::size_t most = 1'000'000'000'000;
    FUZZ_CHECK(within(o.lt_pixels, std::size_t{1}, most), "--lt-pixels %zu", o.lt_pixels);
    FUZZ_CHECK(within(o.pin_pixels, std::size_t{1}, most), "--pin-pixels %zu", o.pin_pixels);
    FUZZ_CHECK(within(o.burst, 1u, 1024u), "--burst %u", o.burst);
    return std::nullopt;
}

std::optional<int> bench_line_tlm(int argc, char** argv) {
    bench_line_tlm_options o;
    if (auto rc = parse_bench_line_tlm(argc, argv, o)) return rc;
    const std::size_t most = 1'000'000'000'000;
    FUZZ_CHECK(within(o.lt_pixels, std::size_t{1}, most), "--lt-pixels %zu", o.lt_pixels);
    FUZZ_CHECK(within(o.pin_pixels, std::size_t{1}, most), "--pin-pixels %zu", o.pin_pixels);
    FUZZ_CHECK(within(o.burst, 1u, 256u), "--burst %u", o.burst);
    return std::nullopt;
}

std::optional<int> accuracy_study(int argc, char** argv) {
    accuracy_study_options o;
    if (auto rc = parse_accuracy_study(argc, argv, o)) return rc;
    FUZZ_CHECK(within(o.n_max, 1u, 1000u), "--n-max %u", o.n_max);
    FUZZ_CHECK(within(o.fig2_n, 1u, o.n_max), "--fig2-n %u (n-max %u)", o.fig2_n, o.n_max);
    FUZZ_CHECK(within(o.size, 16u, 4096u), "--size %u", o.size);
    return std::nullopt;
}

std::optional<int> generator_search(int argc, char** argv) {
    generator_search_options o;
    if (auto rc = parse_generator_search(argc, argv, o)) return rc;
    // --keep is any number (a bound on the worst error: none kept below 0); only that it is one.
    FUZZ_CHECK(!std::isnan(o.keep), "--keep nan accepted");
    return std::nullopt;
}

std::optional<int> head_study(int argc, char** argv) {
    head_study_options o;
    if (auto rc = parse_head_study(argc, argv, o)) return rc;
    FUZZ_CHECK(within(o.size, 16u, 4096u), "--size %u", o.size);
    for (unsigned n : o.ns) FUZZ_CHECK(within(n, 1u, 1000u), "--n %u", n);
    FUZZ_CHECK(o.scan_max <= 1000u, "--scan-max %u", o.scan_max);
    return std::nullopt;
}

// The scene options of the studies that render one (components_study, edge_study, two_line_study,
// cell_study, render_cells).
void check_study_scene(const std::string& scene, const std::string& dev, unsigned size) {
    FUZZ_CHECK(in({"head", "sphere", "torus"}, scene), "--scene '%s'", scene.c_str());
    FUZZ_CHECK(device(dev), "--device '%s'", dev.c_str());
    FUZZ_CHECK(within(size, 16u, 4096u), "--size %u", size);
}

std::optional<int> components_study(int argc, char** argv) {
    components_study_options o;
    if (auto rc = parse_components_study(argc, argv, o)) return rc;
    check_study_scene(o.scene, o.device, o.size);
    FUZZ_CHECK(o.nmse > 0.0 && o.nmse <= 1.0, "--nmse %g", o.nmse);
    for (const auto* tols : {&o.tol_sum, &o.tol_diffuse, &o.tol_specular})
        for (double t : *tols) FUZZ_CHECK(t > 0.0 && t <= 64.0, "a tolerance %g", t);
    for (unsigned m : {o.m_max_sum, o.m_max_diffuse, o.m_max_specular})
        FUZZ_CHECK(within(m, shading::interp::m_min, shading::interp::m_max), "an --m-max %u", m);
    return std::nullopt;
}

std::optional<int> edge_study(int argc, char** argv) {
    edge_study_options o;
    if (auto rc = parse_edge_study(argc, argv, o)) return rc;
    check_study_scene(o.scene, o.device, o.size);
    FUZZ_CHECK(!o.spacings.empty(), "no --spacing");
    for (unsigned h : o.spacings)
        FUZZ_CHECK(h >= 1 && h <= 64 && (h & (h - 1)) == 0, "--spacing %u", h);
    return std::nullopt;
}

std::optional<int> two_line_study(int argc, char** argv) {
    two_line_study_options o;
    if (auto rc = parse_two_line_study(argc, argv, o)) return rc;
    check_study_scene(o.scene, o.device, o.size);
    FUZZ_CHECK(o.nmse > 0.0 && o.nmse <= 1.0, "--nmse %g", o.nmse);
    for (const auto* tols : {&o.tol_one, &o.tol_even, &o.tol_odd}) {
        FUZZ_CHECK(!tols->empty(), "an empty tolerance list");
        for (double t : *tols) FUZZ_CHECK(t > 0.0 && t <= 64.0, "a tolerance %g", t);
    }
    for (double t : o.tol_mid) FUZZ_CHECK(t > 0.0 && t <= 64.0, "a middle lines' tolerance %g", t);
    FUZZ_CHECK(within(o.m_max, shading::interp::m_min, shading::interp::m_max), "--m-max %u", o.m_max);
    FUZZ_CHECK(within(o.above_slack, -1, int(shading::interp::m_max)), "--above-slack %d", o.above_slack);
    return std::nullopt;
}

std::optional<int> cell_study(int argc, char** argv) {
    cell_study_options o;
    if (auto rc = parse_cell_study(argc, argv, o)) return rc;
    check_study_scene(o.scene, o.device, o.size);
    FUZZ_CHECK(o.light.empty() || (o.light.size() == 2 && std::abs(o.light[0]) <= 360.0 && std::abs(o.light[1]) <= 90.0),
               "--light of %zu values", o.light.size());
    FUZZ_CHECK(o.n <= 1000u, "--n %u", o.n);
    FUZZ_CHECK(o.nmse > 0.0 && o.nmse <= 1.0, "--nmse %g", o.nmse);
    FUZZ_CHECK(!o.tol.empty(), "an empty --tol");
    for (double t : o.tol) FUZZ_CHECK(t > 0.0 && t <= 64.0, "a tolerance %g", t);
    for (double t : {o.fallback_tol, o.line_tol}) FUZZ_CHECK(t > 0.0 && t <= 64.0, "a tolerance %g", t);
    for (double a : {o.d2_factor, o.d3_factor}) FUZZ_CHECK(a >= 1e-2 && a <= 1e3, "a factor %g", a);
    FUZZ_CHECK(within(o.cell_max, 4u, 256u) && (o.cell_max & (o.cell_max - 1)) == 0, "--cell-max %u", o.cell_max);
    FUZZ_CHECK(within(o.m_max, shading::interp::m_min, shading::interp::m_max), "--m-max %u", o.m_max);
    return std::nullopt;
}

std::optional<int> render_cells(int argc, char** argv) {
    render_cells_options o;
    if (auto rc = parse_render_cells(argc, argv, o)) return rc;
    check_study_scene(o.scene, o.device, o.size);
    FUZZ_CHECK(o.size <= 1024u, "--size %u", o.size);
    FUZZ_CHECK(o.light.empty() || (o.light.size() == 2 && std::abs(o.light[0]) <= 360.0 && std::abs(o.light[1]) <= 90.0),
               "--light of %zu values", o.light.size());
    FUZZ_CHECK(o.n <= 1000u, "--n %u", o.n);
    FUZZ_CHECK(o.tol > 0.0 && o.tol <= 64.0, "--tol %g", o.tol);
    return std::nullopt;
}

std::optional<int> render_race(int argc, char** argv) {
    render_race_options o;
    if (auto rc = parse_render_race(argc, argv, o)) return rc;
    FUZZ_CHECK(device(o.device), "--device '%s'", o.device.c_str());
    FUZZ_CHECK(within(o.size, 16u, 2048u), "--size %u", o.size);
    FUZZ_CHECK(o.light.empty() || (o.light.size() == 2 && std::abs(o.light[0]) <= 360.0 && std::abs(o.light[1]) <= 90.0),
               "--light of %zu values", o.light.size());
    FUZZ_CHECK(within(o.n, 1u, 1000u), "--n %u", o.n);
    FUZZ_CHECK(positive(o.error_scale), "--error-scale %g", o.error_scale);
    for (double t : {o.cells_tol, o.line_tol, o.fast_phong_budget})
        FUZZ_CHECK(t == -1.0 || (t >= 1e-3 && t <= 64.0), "a setting %g", t);
    return std::nullopt;
}

std::optional<int> render_pipeline(int argc, char** argv) {
#if SHADING_FUZZ_RENDER_OPTIONS
    namespace rp = shading::render_program;
    rp::options o;
    if (auto rc = rp::parse_render_pipeline(argc, argv, o)) return rc;
    FUZZ_CHECK(within(o.size, 1u, rp::max_size), "--size %u", o.size);
    FUZZ_CHECK(o.n == -1 || within(o.n, 1, 1000), "--n %d", o.n);
    FUZZ_CHECK(in({"fixed", "adaptive", "geometry"}, o.length), "--length '%s'", o.length.c_str());
    FUZZ_CHECK(in({"cubic", "quadratic", "zones", "adaptive", "geometry"}, o.degree), "--degree '%s'", o.degree.c_str());
    FUZZ_CHECK(in({"horner", "fd"}, o.eval), "--eval '%s'", o.eval.c_str());
    FUZZ_CHECK(in({"case1", "case2"}, o.set), "--set '%s'", o.set.c_str());
    FUZZ_CHECK(in({"shift_add", "exact"}, o.div3), "--div3 '%s'", o.div3.c_str());
    FUZZ_CHECK(device(o.device) || o.device == "all", "--device '%s'", o.device.c_str());
    FUZZ_CHECK(o.device_given || o.device == "sqmul", "--device '%s' without --device", o.device.c_str());
    FUZZ_CHECK(in(modes, o.mode), "--mode '%s'", o.mode.c_str());
    FUZZ_CHECK(in({"stepped", "scratch"}, o.unit), "--unit '%s'", o.unit.c_str());
    FUZZ_CHECK(within(o.pc.above_slack, -1, int(shading::interp::m_max)), "--above-slack %d", o.pc.above_slack);
    FUZZ_CHECK(in(abstractions, o.abstraction), "--abstraction '%s'", o.abstraction.c_str());
    FUZZ_CHECK(in({"small", "full", "exponents", "claims"}, o.grid), "--grid '%s'", o.grid.c_str());
    FUZZ_CHECK(positive(o.pc.lobe_tol) && positive(o.pc.depth_step), "--lobe-tol %g --depth-step %g", o.pc.lobe_tol,
               o.pc.depth_step);
    FUZZ_CHECK(!std::isnan(o.pc.length_tol) && !std::isnan(o.pc.degree_tol), "--length-tol %g --degree-tol %g",
               o.pc.length_tol, o.pc.degree_tol);
    FUZZ_CHECK(positive(o.error_scale) && positive(o.error_scale_total), "--error-scale %g --error-scale-total %g",
               o.error_scale, o.error_scale_total);
    FUZZ_CHECK(o.argv.size() == static_cast<std::size_t>(argc), "argv kept for --emit-jobs: %zu of %d",
               o.argv.size(), argc);
    return std::nullopt;
#else
    (void)argc;
    (void)argv;
    return 0;  // this build has no render_pipeline (no scene library)
#endif
}

// The order keeps the committed seeds' meaning: their first byte was 0 (a bench without --mode)
// or 1 (with it), and a few 2 and 3.
const program programs[] = {
    {"interp_coef_tb", interp_coef}, {"ua60553_tb", ua60553},           {"interp_fd_tb", interp_fd},
    {"ua22802_tb", ua22802},         {"interp_horner_tb", interp_horner}, {"squared_tb", squared},
    {"interp_line_tb", interp_line}, {"interp_study", interp_study},     {"soak_pipeline", soak},
    {"render_reference", render_reference}, {"bench_specular_tlm", bench_specular_tlm},
    {"accuracy_study", accuracy_study},     {"generator_search", generator_search},
    {"head_study", head_study},             {"render_pipeline", render_pipeline},
    {"bench_line_tlm", bench_line_tlm},     {"components_study", components_study},
    {"edge_study", edge_study},             {"two_line_study", two_line_study},
    {"cell_study", cell_study},             {"render_cells", render_cells}, {"render_race", render_race},
    {"sqmul_tb", sqmul},
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    shading::fuzz::input in(data, size);
    const program& p = programs[in.u8() % (sizeof programs / sizeof programs[0])];
    std::vector<std::string> args{p.name};
    std::string cur;
    while (!in.empty() && args.size() < 24) {
        const char c = static_cast<char>(in.u8());
        if (c == '\0') {
            args.push_back(cur);
            cur.clear();
        } else if (cur.size() < 64) {
            cur.push_back(c);
        }
    }
    if (!cur.empty()) args.push_back(cur);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    const auto status = p.fuzz(static_cast<int>(args.size()), argv.data());
    if (status) FUZZ_CHECK(*status == 0 || *status == 2, "%s: parse returned exit status %d", p.name, *status);
    return 0;
}
