// The interpolation paper's shading system end to end: a scene is rasterised, the geometry side plans every raster
// line into intervals (src/pipeline/plan.cpp), the bit-accurate golden pipeline shades the frame
// (golden_frame), and with --sim the SystemC pipeline shades it again and must agree bit for bit.
// The hardware image is measured against per-pixel shading through the same device (the
// interpolation's error), exact Phong (the total) and the two references against each other (the
// device BRDF's own error), whole image and per zone of the head; operations per pixel are counted
// for Phong and the hardware path. Writes PNGs and report.md / report.json into --out.
//   build/bin/render_pipeline --scene head --size 512 --out out/pipeline/head
// --sweep runs a grid of configurations on the golden model, one child process of this program per
// configuration (--jobs in parallel), and merges their reports into one CSV (scripts/plot_pipeline.py
// draws it).
//   build/bin/render_pipeline --sweep --scene head --size 256 --out out/pipeline/sweep
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <cstdlib>
#include <string>

#include "common/exit_status.h"
#include "render_program.h"

#ifndef SHADING_PIPELINE_SIM
#define SHADING_PIPELINE_SIM 0
#endif
#if SHADING_PIPELINE_SIM
#include <systemc>

#include "common/report_log.h"
#endif

using namespace shading;
using namespace shading::render_program;

namespace shading::render_program {
bool progress_open = false;
}  // namespace shading::render_program

namespace {

namespace fs = std::filesystem;

options g_options;  // handed from main() to sc_main() when the SystemC pipeline runs

// Bad usage found from the command line alone, before any work (exit 2, common/exit_status.h): an
// unknown built-in scene, a light or colour that does not parse, a plan the units cannot run. Empty
// when none. A missing or malformed OBJ file is found later, and is a failure (exit 1).
std::string usage_problem(const options& o) {
    if (!o.sweep && o.device == "all") return "--device all is for --sweep";
    const bool looks_like_obj = o.scene.size() > 4 && o.scene.substr(o.scene.size() - 4) == ".obj";
    if (!looks_like_obj && !fs::is_regular_file(o.scene)) {
        const auto names = scene::builtin_scene_names();
        if (std::find(names.begin(), names.end(), o.scene) == names.end())
            return "--scene '" + o.scene + "' is neither a file nor a built-in scene (sphere, torus, head)";
    }
    try {
        if (!o.light.empty()) parse_light(o.light);
        if (!o.kd.empty()) parse_colour("--kd", o.kd);
        if (!o.ks.empty()) parse_colour("--ks", o.ks);
        if (!o.ambient.empty()) parse_colour("--ambient", o.ambient);
        if (!o.shard.empty()) parse_shard(o.shard);
        validate(plan_config_of(o));
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

int run(const options& o) {
    try {
        return o.sweep ? run_sweep(o) : render(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%srender_pipeline: %s\n", progress_open ? "\n" : "", e.what());
        return 1;
    }
}

}  // namespace

#if SHADING_PIPELINE_SIM
// SystemC's reports through the testbenches' log: info (the kernel's "stopped by user") silent,
// warnings and errors shown with their ids and counted.
int sc_main(int, char*[]) {
    shading::tb::report_log::install();
    return run(g_options);
}
#endif

int main(int argc, char* argv[]) {
    options& o = g_options;
    CLI::App app{"The interpolation paper's shading system: a scene through the planned, interpolating pipeline (golden model and "
                 "SystemC), against per-pixel and Phong references; PNGs and a report. --sweep: a grid of "
                 "configurations in parallel processes, one CSV."};
    app.add_option("--scene", o.scene, "built-in scene (sphere, torus, head) or a path to an OBJ file");
    app.add_option("--size", o.size, "image width and height in pixels (1.." + std::to_string(max_size) + ")")
        ->check(CLI::Range(1u, max_size));
    app.add_option("--data-dir", o.data_dir, "repository root holding data/head/ (for the built-in head)");
    app.add_option("--light", o.light, "one directional light from azimuth,elevation (degrees; azimuth towards +x "
                                       "from +z); default: the scene's light");
    app.add_option("--n", o.n, "the material's exponent n (1..1000); default: the scene's")->check(CLI::Range(1, 1000));
    app.add_option("--kd", o.kd, "k_d: one value or r,g,b in [0, 1]");
    app.add_option("--ks", o.ks, "k_s: one value or r,g,b in [0, 1]");
    app.add_option("--ambient", o.ambient, "ambient: one value or r,g,b in [0, 1]");
    app.add_option("--length", o.length,
                   "interval length policy: fixed, adaptive (exact colours at a check point: host only) or geometry "
                   "(N.H and N.L only: a hardware geometry side can run it)")
        ->check(CLI::IsMember({"fixed", "adaptive", "geometry"}));
    app.add_option("--lobe-tol", o.pc.lobe_tol, "geometry length: N.H spread allowed in a highlight, x the derived bound")
        ->check(CLI::PositiveNumber);
    app.add_option("--m", o.pc.m, "fixed length: intervals of 2^m pixels");
    app.add_option("--m-min", o.pc.m_min, "adaptive length: shortest interval 2^m_min");
    app.add_option("--m-max", o.pc.m_max, "adaptive length: longest interval 2^m_max");
    app.add_option("--length-tol", o.pc.length_tol, "adaptive length: largest accepted error estimate (8-bit levels)");
    app.add_flag("--exact-fallback,!--no-exact-fallback", o.pc.exact_fallback,
                 "adaptive length: exact pixels where even 2^m_min misses the tolerance (default on)");
    app.add_flag("--surface-breaks,!--no-surface-breaks", o.pc.surface_breaks,
                 "also end segments at folds (neighbouring pixels' triangles share no vertex; default on)");
    app.add_option("--degree", o.degree, "degree policy")
        ->check(CLI::IsMember({"cubic", "quadratic", "zones", "adaptive", "geometry"}));
    app.add_option("--degree-tol", o.pc.degree_tol, "adaptive degree: largest accepted quadratic error estimate");
    app.add_option("--eval", o.eval, "evaluator: the Fig. 4 Horner unit or our forward differences")
        ->check(CLI::IsMember({"horner", "fd"}));
    app.add_option("--set", o.set, "cubic sample points: case1 (0, 1/4, 1/2, 1) or case2 (0, 1/2, 3/4, 1)")
        ->check(CLI::IsMember({"case1", "case2"}));
    app.add_option("--div3", o.div3, "division by 3 in the coefficient unit")->check(CLI::IsMember({"shift_add", "exact"}));
    app.add_option("--device", o.device, "specular device: patent, minimax, rom_matched, ua22802, squared (--sweep: default all of the grid's)")
        ->check(CLI::IsMember({"patent", "minimax", "rom_matched", "ua22802", "squared", "all"}));
    app.add_option("--mode", o.mode, "overflow mode of the device's ADD11")->check(CLI::IsMember({"saturate", "wrap"}));
    app.add_option("--unit", o.unit,
                   "the geometry side's unit: stepped (along the line, as a scan-line renderer; default) or scratch "
                   "(every point from scratch); only the operation counts differ")
        ->check(CLI::IsMember({"stepped", "scratch"}));
    app.add_option("--depth-step", o.pc.depth_step, "depth jump (world units) that ends a segment of a raster line")
        ->check(CLI::PositiveNumber);
    app.add_option("--out", o.out, "output folder");
    app.add_flag("--sim,!--no-sim", o.sim, "run the SystemC pipeline and require its frame to equal the golden one "
                                           "(default on)");
    app.add_flag("--images,!--no-images", o.images, "write the PNGs (default on)");
    app.add_option("--vcd", o.vcd, "with --sim: VCD file of the SystemC pipeline");
    app.add_option("--abstraction", o.abstraction,
                   "with --sim: the SystemC pipeline's level: block (every block of the figures, default) or fast "
                   "(the same pins and timing at them, one process)")
        ->check(CLI::IsMember({"block", "fast"}));
    app.add_option("--json", o.json_name, "report file name in --out (empty: none)");
    app.add_option("--md", o.md_name, "Markdown report file name in --out (empty: none)");
    app.add_option("--error-scale", o.error_scale, "error vs per-pixel shown white in error_interp.png (8-bit levels)")
        ->check(CLI::PositiveNumber);
    app.add_option("--error-scale-total", o.error_scale_total, "error vs Phong shown white in error_total.png")
        ->check(CLI::PositiveNumber);
    app.add_flag("--sweep", o.sweep, "run the grid of configurations on the golden model, one CSV (--csv)");
    app.add_option("--jobs", o.jobs, "--sweep: parallel processes (default: the hardware's cores)");
    app.add_option("--grid", o.grid, "--sweep: small, full, exponents (every device x n = 2..500, this command's plan settings) or claims (--scenes x --lights x --ns x --sizes x devices x twelve policies)")
        ->check(CLI::IsMember({"small", "full", "exponents", "claims"}));
    app.add_option("--csv", o.csv, "--sweep: CSV path (default: <out>/sweep.csv)");
    app.add_option("--shard", o.shard, "--sweep: run only shard I of N (configurations i with i % N = I - 1)");
    app.add_flag("--emit-jobs", o.emit_jobs,
                 "--sweep: print one command line per configuration (a shard of one, its own CSV) and exit, for GNU "
                 "parallel or a job array; merge the CSVs with scripts/pipeline_claims.py");
    app.add_option("--scenes", o.claims_scenes, "--grid claims: scenes (built-in names or OBJ paths; default head sphere torus)");
    app.add_option("--lights", o.claims_lights, "--grid claims: light directions az,el (default -40,25 35,20 10,60)");
    app.add_option("--ns", o.claims_ns, "--grid claims: exponents n (default 5 20 100 500)");
    app.add_option("--sizes", o.claims_sizes, "--grid claims: image sizes (default 512 1024)");
    app.add_flag("--inject-mismatch", o.inject_mismatch, "")->group("");
    bool sim_available = false;
    app.add_flag("--sim-available", sim_available, "exit 0 if this build has the SystemC pipeline (--sim), 1 if not");
    SHADING_CLI_PARSE(app, argc, argv);  // help 0, a bad option 2 (common/exit_status.h)
    if (sim_available) return SHADING_PIPELINE_SIM ? 0 : 1;
    o.argv.assign(argv, argv + argc);
    o.device_given = app.count("--device") > 0;
    if (const std::string why = usage_problem(o); !why.empty()) {
        std::fprintf(stderr, "render_pipeline: %s\n", why.c_str());
        return tb::exit_usage;
    }
#if SHADING_PIPELINE_SIM
    if (o.sim && !o.sweep) {
        ::setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
        return sc_core::sc_elab_and_sim(argc, argv);
    }
#endif
    return run(o);
}
