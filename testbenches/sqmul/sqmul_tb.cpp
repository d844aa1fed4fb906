// Square-and-multiply device testbench program: replays Fig. 3 with the stage's clock (load n and
// k_s*I through their strobes, then stream cos values on strobe 17, 24 clocks per pixel),
// checks every output validated by output 29 against the golden model and measures the device
// against cos^n. Options common to every bench: common/common_options.h.
//
//   sqmul_tb                         a sphere's raster line at n = 10, 100 and 1000, VCD in traces/sqmul.vcd
//   sqmul_tb --sweep --no-vcd        every cos code 0..1.0 for n = 1, 3, 10, 100, 512, 1000
//   sqmul_tb --random 100000 --seed 7 --mode wrap
//   sqmul_tb --random 1000000 --abstraction fast        the fast pin-level model (sqmul_fast.h)
#include <cstdio>
#include <string>
#include <vector>

#include "testbenches/common/bench_runner.h"
#include "testbenches/options/bench_options.h"
#include "arith/sqmul_arith.h"
#include "scene/scene.h"
#include "testbenches/specular/specular_tb.h"
#include "sqmul/sqmul.h"

using namespace shading;
using namespace shading::tb;

namespace {

using options = sqmul_options;

// One surface per n, white light (k_s*I = 255) on R so the relative error is read at full scale;
// G and B at other levels to exercise all three multipliers. Or the random stream.
item_source<surface> stimulus(const bench_runner& run, options& o) {
    if (run.random()) return random_surfaces(run.random_count(), run.seed());
    if (o.ns.empty()) o.ns = o.sweep ? std::vector<unsigned>{1, 3, 10, 100, 512, 1000} : std::vector<unsigned>{10, 100, 1000};
    std::vector<uint32_t> stream;
    if (o.sweep) {
        for (uint32_t c = 0; c <= spec::cos_one; ++c) stream.push_back(c);
    } else {
        for (double c : scene::sphere_line_cos(0.2, o.scene_pixels, 0.3, 0.4, 1.0)) stream.push_back(scene::cos_code(c));
    }
    std::vector<surface> surfaces;
    for (unsigned n : o.ns) surfaces.push_back({n, {255, 180, 60}, stream});
    return surfaces;
}

template <typename Device>
int run_device(bench_runner& run, options& o) {
    const overflow_mode mode = run.mode();
    const strobe_timing t = sqmul_timing(sc_core::sc_time(o.clk_ns, sc_core::SC_NS));
    specular_bench<Device> bench(
        "tb", stimulus(run, o), t,
        [mode](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
            datapath_nets r{};
            r.out = golden_sqmul(n, c, k, mode).out;
            return r;
        },
        mode);
    bench.checker.inject_mismatch(run.inject(), run.inject_count());
    bench.checker.measure_accuracy(!run.random());
    const auto limit = run.random() ? sc_core::sc_max_time()
                                    : bench.stim.duration() * 1.01 + sc_core::sc_time(1, sc_core::SC_US);
    run.simulate(bench, limit);

    std::printf("square-and-multiply device (%s mode, %s model), clock %.1f ns, strobe 17 %.0f ns low / %.0f ns high\n",
                run.mode_name().c_str(), o.abstraction.c_str(), o.clk_ns, t.t_low.to_seconds() * 1e9,
                t.t_high.to_seconds() * 1e9);
    if (run.random()) {
        run.report_random(std::string("random_") + run.mode_name() + (o.abstraction == "fast" ? "_fast" : ""),
                          bench.checker.samples(), bench.checker.mismatches());
    } else {
        std::printf("%6s %9s %11s %26s %18s\n", "n", "samples", "mismatches", "max rel err (cos^n>=0.56)",
                    "clocks per sample");
        for (const auto& [n, st] : bench.checker.stats()) {
            // sync17's edges, the taking edge, one per square and per multiplication (golden_sqmul's
            // counts), the done edge.
            const auto g = golden_sqmul(n, 0, {0, 0, 0}, mode);
            const unsigned clocks = g.squares + g.multiplies + sqmul::sync_stages + 2;
            std::printf("%6llu %9zu %11zu %25.3f%% %18u\n", static_cast<unsigned long long>(n), st.samples,
                        st.mismatches, 100.0 * st.max_rel_err_056, clocks);
            run.summary({run.bench(), std::string(o.sweep ? "sweep" : "scene") + "_n" + std::to_string(n) + "_" +
                                          run.mode_name() + (o.abstraction == "fast" ? "_fast" : ""),
                         st.samples, st.mismatches, fmt_percent(st.max_rel_err_056, 2),
                         std::to_string(clocks) + " clocks",
                         std::string("max rel err vs cos^n where cos^n>=0.56; ") +
                             (o.sweep ? "every cos code 0..1.0" : "sphere raster line") +
                             "; clocks from strobe to output 29 at the latest"});
        }
    }
    return run.finish(bench.checker.samples(), bench.checker.mismatches());
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    options o;
    if (auto rc = parse_sqmul(argc, argv, o)) return *rc;
    bench_runner run("sqmul", o.bench);
    if (auto rc = run.start(argc, argv)) return *rc;
    if (o.abstraction != "block") run.default_vcd("traces/sqmul_" + o.abstraction);
    report_log::get().expect(msg::input);  // n = 0 or n > 1000 on the command line: documented

    return o.abstraction == "fast" ? run_device<device_sqmul_fast>(run, o) : run_device<device_sqmul>(run, o);
}
