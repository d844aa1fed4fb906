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
#include <cstdio>
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

namespace {

options g_options;  // handed from main() to sc_main() when the SystemC pipeline runs

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
