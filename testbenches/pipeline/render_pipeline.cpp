// The interpolation paper's shading system end to end: a scene is rasterised, the geometry side plans every raster
// line into intervals (src/golden_pipeline/plan.cpp), the bit-accurate golden pipeline shades the frame
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
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <cstdlib>
#include <string>

#include "testbenches/common/exit_status.h"
#include "render_program.h"

#ifndef SHADING_PIPELINE_SIM
#define SHADING_PIPELINE_SIM 0
#endif
#if SHADING_PIPELINE_SIM
#include <systemc>

#include "testbenches/common/report_log.h"
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
    if (auto rc = parse_render_pipeline(argc, argv, o)) return *rc;  // help 0, a bad option 2
    if (o.sim_available) return SHADING_PIPELINE_SIM ? 0 : 1;
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
