// A scene's planned frame through the shading pipeline's Verilog twin (rtl/pipeline/shading_pipeline.v
// with the square-and-multiply device, one of the three verilated variants) beside the SystemC block
// model shading_pipeline<sqmul_device, EVAL>, on the same pins and clock (pipeline_pair.h's pair_bench):
// the scene rasterised and planned by make_plan with the variant's configuration (the interpolation
// paper's geometry side), every pin of the two compared at every edge, both frame buffers checked
// pixel by pixel against golden_interval. Exit 0 only with no pin difference, no golden mismatch and
// every planned pixel written once; 1 otherwise; 2 for bad usage (an unknown scene, an OBJ file
// that cannot be read, a size out of range).
//   build/bin/render_pipeline_rtl --scene head --size 128 --variant fd_any [--degree quadratic]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <memory>
#include <string>

#include "testbenches/common/exit_status.h"
#include "testbenches/common/report_log.h"
#include "testbenches/options/render_options.h"
#include "testbenches/pipeline/render_program.h"
#include "testbenches/rtl/rtl_pipeline_variants.h"
#include "core/report_ids.h"
#include "scene/raster.h"

using namespace shading;
using namespace shading::pipeline;
using namespace shading::pipeline::rtl_variants;

namespace {

// What main() prepares before the simulation (a bad scene found there, not half-way through), for sc_main.
struct frame_job {
    render_program::rtl_frame_options o;
    frame_constants k;
    plan p;
};
frame_job g_job;

template <class V>
int run(const frame_job& job) {
    const plan_config c = V::plan_config_of();
    const scene::device_config dev = V::device();
    auto bench = std::make_unique<rtl_pair<V>>("tb", job.p, job.k, dev, c, sqmul_device::default_config(),
                                               std::function<bool(const typename V::rtl&)>{}, "rtl");
    const auto t0 = std::chrono::steady_clock::now();
    sc_core::sc_start(pipeline_period() * static_cast<double>(pair_watchdog_clocks(job.p)));
    const double wall = render_program::seconds_since(t0);
    const bool finished = bench->finished();
    bench->chk_b.finish();
    bench->chk_o.finish();
    const auto clocks = static_cast<unsigned long long>(sc_core::sc_time_stamp() / pipeline_period());
    const std::size_t planned = bench->chk_o.pixels();
    std::printf("%s at %u, variant %s: %zu pixels planned in %zu jobs\n", job.o.scene.scene.c_str(),
                job.o.scene.size, job.o.variant.c_str(), planned, job.p.jobs.size());
    std::printf("  %zu valid edges compared (%zu edges), %zu pin differences\n", bench->cmp.valid_edges(),
                bench->cmp.edges(), bench->cmp.differences());
    std::printf("  pixels written: %zu by the model, %zu by the RTL; golden mismatches: %zu model, %zu RTL\n",
                bench->chk_b.written(), bench->chk_o.written(), bench->chk_b.mismatches(), bench->chk_o.mismatches());
    std::printf("  %llu clocks (%.2f a pixel), %.1f s\n", clocks,
                planned ? static_cast<double>(clocks) / static_cast<double>(planned) : 0.0, wall);
    const bool ok = finished && bench->cmp.differences() == 0 && bench->chk_b.mismatches() == 0 &&
                    bench->chk_o.mismatches() == 0 && bench->chk_o.written() == planned &&
                    bench->chk_b.written() == planned;
    if (ok) {
        std::printf("PASS: the RTL equals the SystemC model at every pin and edge, both frames equal the golden "
                    "model, every planned pixel written once\n");
    } else {
        std::printf("FAIL: %s\n", finished ? "the RTL and the model or the golden frame differ, or a planned pixel "
                                             "was not written once"
                                           : "the run did not finish within its watchdog");
    }
    bench.release();  // elaborated for the process's life
    return ok ? tb::exit_success : tb::exit_failure;
}

}  // namespace

// SystemC's reports through the testbenches' log: warnings and errors shown with their ids.
int sc_main(int, char*[]) {
    tb::report_log::install();
    tb::report_log::get().expect(msg::input);  // N.H codes above 1.0, if any: the device's overflow mode's
    const std::string& v = g_job.o.variant;
    return v == "horner" ? run<horner>(g_job) : v == "fd_m4" ? run<fd_m4>(g_job) : run<fd_any>(g_job);
}

int main(int argc, char* argv[]) {
    render_program::rtl_frame_options& o = g_job.o;
    if (auto rc = render_program::parse_render_pipeline_rtl(argc, argv, o)) return *rc;  // help 0, a bad option 2
    // The scene and its plan before any simulation: bad input is bad usage here, an OBJ file that
    // cannot be read included (the program has nothing else to report).
    try {
        if (const std::string why = render_program::usage_problem(o.scene); !why.empty())
            throw scene::scene_error(why);
        const scene::world w = render_program::load_world(o.scene);
        g_job.k = frame_constants_of(w);
        plan_config base;
        base.degree = o.degree == "quadratic" ? degree_policy::quadratic : degree_policy::cubic;
        const plan_config c = o.variant == "horner" ? horner::plan_config_of(base)
                              : o.variant == "fd_m4" ? fd_m4::plan_config_of(base)
                                                     : fd_any::plan_config_of(base);
        const scene::device_config dev = o.variant == "horner" ? horner::device()
                                         : o.variant == "fd_m4" ? fd_m4::device()
                                                                : fd_any::device();
        g_job.p = make_plan(scene::rasterise(w), g_job.k, dev, c);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "render_pipeline_rtl: %s\n", e.what());
        return tb::exit_usage;
    }
    ::setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
    return sc_core::sc_elab_and_sim(argc, argv);
}
