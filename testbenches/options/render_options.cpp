// render_pipeline's command line (render_options.h) parsed with CLI11, with the same names, checks
// and help texts the program had when it built its own CLI11 App, in groups.
#include "render_options.h"

#include "cli_parse.h"

namespace shading::render_program {

using tb::not_nan;

void add_scene_options(CLI::App& app, options& o) {
    const std::string g = "Scene";
    app.add_option("--scene", o.scene, "built-in scene (sphere, torus, head) or a path to an OBJ file")->group(g);
    app.add_option("--size", o.size, "image width and height in pixels (1.." + std::to_string(max_size) + ")")
        ->check(CLI::Range(1u, max_size))->group(g);
    app.add_option("--data-dir", o.data_dir, "repository root holding data/head/ (for the built-in head)")->group(g);
    app.add_option("--light", o.light, "one directional light from azimuth,elevation (degrees; azimuth towards +x "
                                       "from +z); default: the scene's light")->group(g);
    app.add_option("--n", o.n, "the material's exponent n (1..1000); default: the scene's")
        ->check(CLI::Range(1, 1000))->group(g);
    app.add_option("--kd", o.kd, "k_d: one value or r,g,b in [0, 1]")->group(g);
    app.add_option("--ks", o.ks, "k_s: one value or r,g,b in [0, 1]")->group(g);
    app.add_option("--ambient", o.ambient, "ambient: one value or r,g,b in [0, 1]")->group(g);
}

void add_device_options(CLI::App& app, options& o) {
    const std::string g = "Device";
    app.add_option("--device", o.device, "specular device: patent, minimax, rom_matched, ua22802, squared, sqmul (default sqmul; --sweep: default all of the grid's)")
        ->check(CLI::IsMember({"patent", "minimax", "rom_matched", "ua22802", "squared", "sqmul", "all"}))->group(g);
    app.add_option("--mode", o.mode, "overflow mode of the device's ADD11")
        ->check(CLI::IsMember({"saturate", "wrap"}))->group(g);
    app.add_option("--eval", o.eval, "evaluator: the Fig. 4 Horner unit or our forward differences")
        ->check(CLI::IsMember({"horner", "fd"}))->group(g);
    app.add_option("--set", o.set, "cubic sample points: case1 (0, 1/4, 1/2, 1) or case2 (0, 1/2, 3/4, 1)")
        ->check(CLI::IsMember({"case1", "case2"}))->group(g);
    app.add_option("--div3", o.div3, "division by 3 in the coefficient unit")
        ->check(CLI::IsMember({"shift_add", "exact"}))->group(g);
    app.add_flag("--carry-samples,!--no-carry-samples", o.pc.carry_samples,
                 "the sample stage takes a job's first colour from its last-sample registers where the codes "
                 "are the last sample's (default off)")->group(g);
    app.add_option("--unit", o.unit,
                   "the geometry side's unit: stepped (along the line, as a scan-line renderer; default) or scratch "
                   "(every point from scratch); only the operation counts differ")
        ->check(CLI::IsMember({"stepped", "scratch"}))->group(g);
    app.add_flag("--walk-edges,!--no-walk-edges", o.pc.walk_edges,
                 "the stepped geometry side and the scan-line Phong walk each triangle's values from line to line "
                 "(only a triangle's first run start is evaluated; default off)")->group(g);
}

void add_plan_options(CLI::App& app, options& o, bool length) {
    const std::string g = "Plan";
    if (length)
        app.add_option("--length", o.length,
                       "interval length policy: fixed, adaptive (exact colours at a check point: host only) or "
                       "geometry (N.H and N.L only: a hardware geometry side can run it)")
            ->check(CLI::IsMember({"fixed", "adaptive", "geometry"}))->group(g);
    app.add_option("--m", o.pc.m, "fixed length: intervals of 2^m pixels")->group(g);
    app.add_option("--m-min", o.pc.m_min, "adaptive length: shortest interval 2^m_min")->group(g);
    app.add_option("--m-max", o.pc.m_max, "adaptive length: longest interval 2^m_max")->group(g);
    app.add_option("--length-tol", o.pc.length_tol, "adaptive length: largest accepted error estimate (8-bit levels)")
        ->check(not_nan())->group(g);
    app.add_flag("--exact-fallback,!--no-exact-fallback", o.pc.exact_fallback,
                 "adaptive length: exact pixels where even 2^m_min misses the tolerance (default on)")->group(g);
    app.add_flag("--split-at-check,!--no-split-at-check", o.pc.split_at_check,
                 "adaptive and geometry length: send each accepted cubic above 2^m_min as two quadratics "
                 "through its samples and its check point (default off)")->group(g);
    app.add_option("--above-slack", o.pc.above_slack,
                   "adaptive and geometry length: an interval at most K levels longer than the shortest the line "
                   "above has over its pixels (negative: no limit; default -1)")
        ->check(CLI::Range(-1, static_cast<int>(interp::m_max)))->group(g);
    app.add_flag("--lit-guard,!--no-lit-guard", o.pc.lit_guard,
                 "adaptive and geometry length: reject an interval whose samples and check point are all unlit "
                 "but which covers a triangle with a vertex normal facing the light (default off)")->group(g);
    app.add_option("--lobe-tol", o.pc.lobe_tol, "geometry length: N.H spread allowed in a highlight, x the derived bound")
        ->check(CLI::PositiveNumber)->check(not_nan())->group(g);
    app.add_option("--degree", o.degree, "degree policy")
        ->check(CLI::IsMember({"cubic", "quadratic", "zones", "adaptive", "geometry"}))->group(g);
    app.add_option("--degree-tol", o.pc.degree_tol, "adaptive degree: largest accepted quadratic error estimate")
        ->check(not_nan())->group(g);
    app.add_option("--depth-step", o.pc.depth_step, "depth jump (world units) that ends a segment of a raster line")
        ->check(CLI::PositiveNumber)->check(not_nan())->group(g);
    app.add_flag("--surface-breaks,!--no-surface-breaks", o.pc.surface_breaks,
                 "also end segments at folds (neighbouring pixels' triangles share no vertex; default on)")->group(g);
}

void add_simulation_options(CLI::App& app, options& o) {
    const std::string g = "Simulation";
    app.add_flag("--sim,!--no-sim", o.sim, "run the SystemC pipeline and require its frame to equal the golden one "
                                           "(default on)")->group(g);
    app.add_option("--abstraction", o.abstraction,
                   "with --sim: the SystemC pipeline's level: block (every block of the figures, default) or fast "
                   "(the same pins and timing at them, one process)")
        ->check(CLI::IsMember({"block", "fast"}))->group(g);
    app.add_option("--vcd", o.vcd, "with --sim: VCD file of the SystemC pipeline")->group(g);
    app.add_flag("--sim-available", o.sim_available, "exit 0 if this build has the SystemC pipeline (--sim), 1 if not")
        ->group(g);
    app.add_flag("--inject-mismatch", o.inject_mismatch, "")->group("");
}

void add_output_options(CLI::App& app, options& o) {
    const std::string g = "Output";
    app.add_option("--out", o.out, "output folder")->group(g);
    app.add_flag("--images,!--no-images", o.images, "write the PNGs (default on)")->group(g);
    app.add_option("--json", o.json_name, "report file name in --out (empty: none)")->group(g);
    app.add_option("--md", o.md_name, "Markdown report file name in --out (empty: none)")->group(g);
    app.add_option("--error-scale", o.error_scale, "error vs per-pixel shown white in error_interp.png (8-bit levels)")
        ->check(CLI::PositiveNumber)->check(not_nan())->group(g);
    app.add_option("--error-scale-total", o.error_scale_total, "error vs Phong shown white in error_total.png")
        ->check(CLI::PositiveNumber)->check(not_nan())->group(g);
}

void add_sweep_options(CLI::App& app, options& o) {
    const std::string g = "Sweep";
    app.add_flag("--sweep", o.sweep, "run the grid of configurations on the golden model, one CSV (--csv)")->group(g);
    app.add_option("--jobs", o.jobs, "--sweep: parallel processes (default: the hardware's cores)")->group(g);
    app.add_option("--grid", o.grid, "--sweep: small, full, exponents (every device x n = 2..500, this command's plan settings) or claims (--scenes x --lights x --ns x --sizes x devices x sixteen policies)")
        ->check(CLI::IsMember({"small", "full", "exponents", "claims"}))->group(g);
    app.add_option("--csv", o.csv, "--sweep: CSV path (default: <out>/sweep.csv)")->group(g);
    app.add_option("--shard", o.shard, "--sweep: run only shard I of N (configurations i with i % N = I - 1)")->group(g);
    app.add_flag("--emit-jobs", o.emit_jobs,
                 "--sweep: print one command line per configuration (a shard of one, its own CSV) and exit, for GNU "
                 "parallel or a job array; merge the CSVs with studies/scripts/pipeline_claims.py")->group(g);
    app.add_option("--scenes", o.claims_scenes, "--grid claims: scenes (built-in names or OBJ paths; default head sphere torus)")
        ->group(g);
    app.add_option("--lights", o.claims_lights, "--grid claims: light directions az,el (default -40,25 35,20 10,60)")
        ->group(g);
    app.add_option("--ns", o.claims_ns, "--grid claims: exponents n (default 5 20 100 500)")->group(g);
    app.add_option("--sizes", o.claims_sizes, "--grid claims: image sizes (default 512 1024)")->group(g);
}

void record_command_line(const CLI::App& app, int argc, char** argv, options& o) {
    o.argv.assign(argv, argv + argc);
    o.device_given = app.count("--device") > 0;
}

std::optional<int> parse_render_pipeline(int argc, char** argv, options& o) {
    CLI::App app{"The interpolation paper's shading system: a scene through the planned, interpolating pipeline (golden model and "
                 "SystemC), against per-pixel and Phong references; PNGs and a report. --sweep: a grid of "
                 "configurations in parallel processes, one CSV."};
    add_scene_options(app, o);
    add_device_options(app, o);
    add_plan_options(app, o);
    add_simulation_options(app, o);
    add_output_options(app, o);
    add_sweep_options(app, o);
    SHADING_CLI_PARSE(app, argc, argv);  // help 0, a bad option 2 (common/exit_status.h)
    record_command_line(app, argc, argv, o);
    return std::nullopt;
}

std::optional<int> parse_render_pipeline_rtl(int argc, char** argv, rtl_frame_options& o) {
    CLI::App app{"A scene's planned frame through the shading pipeline's Verilog twin beside the SystemC model, "
                 "every pin compared at every edge and both frames against the golden model"};
    add_scene_options(app, o.scene);
    app.add_option("--variant", o.variant,
                   "the verilated variant and its plan: horner (case 1, shift-add, carry, saturate), fd_any (forward "
                   "differences, any m, case 2, exact, wrap) or fd_m4 (forward differences, m = 4, case 1, exact, "
                   "carry, wrap); default fd_any")
        ->check(CLI::IsMember({"horner", "fd_any", "fd_m4"}));
    app.add_option("--degree", o.degree, "the plan's degree: cubic or quadratic along every segment; default cubic")
        ->check(CLI::IsMember({"cubic", "quadratic"}));
    SHADING_CLI_PARSE(app, argc, argv);  // help 0, a bad option 2 (common/exit_status.h)
    return std::nullopt;
}

}  // namespace shading::render_program
