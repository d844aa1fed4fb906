// UA 60553 testbench program: replays Fig. 3 (load n and k_s*I for R, G, B through their strobes,
// then stream cos values on ctl17), checks every validated output against the golden model and
// measures the device against cos^n. The generator of a is the patent's (device_ua60553) or a
// tuned one (device_ua60553_tuned). Options common to every bench: common/common_options.h.
//
//   ua60553_tb                       scene line for n = 10 and 100, VCD in traces/ua60553.vcd
//   ua60553_tb --sweep --no-vcd      every cos code 0..1.0 for n = 1, 10, 100, 512, 1000
//   ua60553_tb --random 100000 --seed 7 --generator minimax --mode wrap
//   ua60553_tb --random 1000000 --abstraction fast      the fast pin-level model (specular_fast.h)
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "testbenches/common/bench_runner.h"
#include "testbenches/options/bench_options.h"
#include "arith/ua60553_tuned_arith.h"
#include "scene/scene.h"
#include "testbenches/specular/specular_tb.h"
#include "tuned/ua60553_tuned.h"
#include "ua60553/ua60553.h"

using namespace shading;
using namespace shading::tb;

namespace {

using options = ua60553_options;

const std::map<std::string, const ua60553::tuned_generator*> tuned{{"minimax", &ua60553::minimax},
                                                                  {"rom_matched", &ua60553::rom_matched}};

// The stimulus: one surface per n, white light (k_s*I = 255) on R so the relative error is read
// at full scale; G and B at other levels to exercise all three multipliers. Or the random stream.
item_source<surface> stimulus(const bench_runner& run, options& o) {
    if (run.random()) return random_surfaces(run.random_count(), run.seed());
    if (o.ns.empty()) o.ns = o.sweep ? std::vector<unsigned>{1, 10, 100, 512, 1000} : std::vector<unsigned>{10, 100};
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

template <typename Device, typename... DeviceArgs>
int run_device(bench_runner& run, options& o, const std::string& name, specular_checker::golden_fn golden,
               DeviceArgs&&... device_args) {
    strobe_timing t;
    t.t_low = sc_core::sc_time(o.t_low_ns, sc_core::SC_NS);
    t.t_high = sc_core::sc_time(o.t_high_ns, sc_core::SC_NS);
    t.cos_lead = t.t_high / 2;
    block_delays delays;
    if (o.zero_delays)
        delays.reg = delays.inverter = delays.adder = delays.multiplier = delays.rom = delays.gate = sc_core::SC_ZERO_TIME;
    specular_bench<Device> bench("tb", stimulus(run, o), t, std::move(golden), run.mode(),
                                 std::forward<DeviceArgs>(device_args)..., delays);
    bench.checker.inject_mismatch(run.inject(), run.inject_count());
    bench.checker.measure_accuracy(!run.random());
    const auto limit = run.random() ? sc_core::sc_max_time()
                                    : bench.stim.duration() * 1.01 + sc_core::sc_time(1, sc_core::SC_US);
    run.simulate(bench, limit);

    std::printf("%s (%s mode, %s model%s), strobe %.1f ns low / %.1f ns high, critical path %s\n", name.c_str(),
                run.mode_name().c_str(), o.abstraction.c_str(), o.zero_delays ? ", zero block delays" : "", o.t_low_ns,
                o.t_high_ns, bench.dut.rg2_to_outputs().to_string().c_str());
    if (run.random()) {
        run.report_random("random_" + o.generator + "_" + run.mode_name() + (o.abstraction == "fast" ? "_fast" : ""),
                          bench.checker.samples(), bench.checker.mismatches());
    } else {
        std::printf("%6s %9s %11s %26s\n", "n", "samples", "mismatches", "max rel err (cos^n>=0.56)");
        for (const auto& [n, st] : bench.checker.stats()) {
            std::printf("%6llu %9zu %11zu %25.3f%%\n", static_cast<unsigned long long>(n), st.samples,
                        st.mismatches, 100.0 * st.max_rel_err_056);
            const std::string gen = o.generator == "patent" ? "" : o.generator + "_";
            run.summary({run.bench(), gen + (o.sweep ? "sweep" : "scene") + "_n" + std::to_string(n) + "_" + run.mode_name(),
                         st.samples, st.mismatches, fmt_percent(st.max_rel_err_056, 2), "1 strobe",
                         std::string("max rel err vs cos^n where cos^n>=0.56; ") +
                             (o.sweep ? "every cos code 0..1.0" : "sphere raster line")});
        }
    }
    return run.finish(bench.checker.samples(), bench.checker.mismatches());
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    options o;
    if (auto rc = parse_ua60553(argc, argv, o)) return *rc;
    bench_runner run("ua60553", o.bench);
    if (auto rc = run.start(argc, argv)) return *rc;
    if (o.generator != "patent" || o.abstraction != "block")
        run.default_vcd("traces/ua60553" + (o.generator != "patent" ? "_" + o.generator : std::string()) +
                        (o.abstraction != "block" ? "_" + o.abstraction : std::string()));

    const overflow_mode mode = run.mode();
    const bool fast = o.abstraction == "fast";
    if (o.generator == "patent") {
        const auto golden = [mode](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
            return golden_ua60553(n, c, k, mode);
        };
        return fast ? run_device<device_ua60553_fast>(run, o, "UA 60553", golden, ua60553::patent)
                    : run_device<device_ua60553>(run, o, "UA 60553", golden, ua60553::patent);
    }
    const ua60553::tuned_generator& g = *tuned.at(o.generator);
    const auto golden = [mode, &g](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        return golden_ua60553_tuned(n, c, k, mode, g);
    };
    const std::string name = "UA 60553 tuned (" + o.generator + ")";
    return fast ? run_device<device_ua60553_tuned_fast>(run, o, name, golden, g)
                : run_device<device_ua60553_tuned>(run, o, name, golden, g);
}
