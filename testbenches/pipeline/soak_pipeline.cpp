// Soak of the SystemC pipeline at the fast abstraction (scripts/soak.sh, docs/fuzzing.md): the head
// rendered R times in one process. SystemC elaborates once per process, so the R renders are one
// simulation of the head's plan repeated R times (simulate_frame, every pixel checked against
// golden_interval as in render_pipeline --sim). Resident memory is read after the first render's
// last pixel and after the last one. The checker keeps no log of the writes (keep_write_order off:
// the tests' 8 bytes per pixel would grow with the renders), so nothing is taken off the figures.
//   soak_pipeline [--renders R] [--size S]     exit 0: no mismatch and the resident memory after the
//                                                 last render within 5 % of the first render's
#include <cstdio>
#include <fstream>
#include <string>
#include <systemc>  // declares sc_main extern "C", as libsystemc needs it

#include "testbenches/options/tool_options.h"
#include "golden_pipeline/pipeline.h"
#include "pipeline_sim.h"
#include "scene/raster.h"
#include "scene/world.h"

namespace {
double rss_mb() {
    std::ifstream f("/proc/self/statm");
    long pages = 0, resident = 0;
    f >> pages >> resident;
    return static_cast<double>(resident) * 4096.0 / (1024.0 * 1024.0);
}
}  // namespace

int sc_main(int, char*[]) { return 2; }  // not used: main() below drives simulate_frame

int main(int argc, char* argv[]) {
    using namespace shading;
    tb::soak_options opt;
    if (auto rc = tb::parse_soak(argc, argv, opt)) return *rc;  // help 0, bad usage 2
    const unsigned renders = opt.renders, size = opt.size;

    const scene::world s = scene::builtin_scene("head", SHADING_SOURCE_DIR, size, size);
    const pipeline::plan_config cfg;
    const scene::device_config dev;
    const pipeline::frame_constants k = pipeline::frame_constants_of(s);
    const scene::rasterised r = scene::rasterise(s);
    const pipeline::plan one = pipeline::make_plan(r, k, dev, cfg);
    pipeline::plan all = one;
    all.jobs.clear();
    all.jobs.reserve(one.jobs.size() * renders);
    for (unsigned i = 0; i < renders; ++i) all.jobs.insert(all.jobs.end(), one.jobs.begin(), one.jobs.end());
    const std::size_t per_render = one.pixels;

    double rss_first = 0.0, rss_last = 0.0;
    pipeline::sim_options o;
    o.level = abstraction::fast;
    o.keep_write_order = false;
    // Called every 4096 pixels and at the last: the first call at or past one render's pixels.
    o.progress = [&](std::size_t done, std::size_t total) {
        if (rss_first == 0.0 && done >= per_render) rss_first = rss_mb();
        if (done == total) rss_last = rss_mb();
    };
    const pipeline::sim_result res = pipeline::simulate_frame(all, k, dev, cfg, o);
    const double growth = (rss_last - rss_first) / rss_first;
    std::printf("soak_pipeline: head %ux%u, %u renders of %zu pixels at the fast abstraction: %zu mismatches, "
                "%.1f s wall, %.1f s CPU (%.3g pixels per CPU s)\n",
                size, size, renders, per_render, res.mismatches, res.seconds, res.cpu_seconds,
                static_cast<double>(per_render) * renders / res.cpu_seconds);
    std::printf("resident memory: after the first render %.1f MB, after the last %.1f MB (%+.2f %%)\n", rss_first,
                rss_last, 100.0 * growth);
    return res.mismatches == 0 && growth <= 0.05 ? 0 : 1;
}
