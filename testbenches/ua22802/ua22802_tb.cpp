// UA 22802 testbench program: streams surfaces (n, k_s*I) and pixels (cos) through the ROM
// prototype as in UA 60553, Fig. 3, compares every output with the golden model and with cos^n,
// writes a VCD (open with traces/ua22802.gtkw) and appends one summary row per n to the summary.
// Options common to every bench: common/common_options.h.
//
//   ua22802_tb                         8 exponents x 48 pixels, VCD in traces/ua22802.vcd
//   ua22802_tb --random 100000 --seed 7 --mode wrap
//   ua22802_tb --random 100000 --abstraction fast    the fast pin-level model (specular_fast.h)
#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

#include "testbenches/common/bench_runner.h"
#include "testbenches/options/bench_options.h"
#include "arith/ua22802_arith.h"
#include "testbenches/specular/specular_tb.h"
#include "ua22802/ua22802.h"

using namespace shading;
using namespace shading::tb;

namespace {

// Per n: half the pixels over cos in [0, 1], half where cos^n >= 0.56 (the paper's error bound).
std::vector<surface> surfaces_for(const std::vector<unsigned>& ns, unsigned pixels) {
    std::vector<surface> surfaces;
    for (unsigned n : ns) {
        surface s{n, {255, 160, 48}, {}};
        const unsigned half = pixels / 2;
        const double lo = std::pow(0.56, 1.0 / std::max(1u, n));
        for (unsigned i = 0; i < half; ++i)
            s.cos_codes.push_back(static_cast<uint32_t>(std::lround(spec::cos_one * double(i) / (half - 1 + (half == 1)))));
        for (unsigned i = half; i < pixels; ++i) {
            const double c = lo + (1.0 - lo) * double(i - half) / std::max(1u, pixels - half - 1);
            s.cos_codes.push_back(static_cast<uint32_t>(std::lround(c * spec::cos_one)));
        }
        surfaces.push_back(std::move(s));
    }
    return surfaces;
}

template <typename Device>
constexpr bool is_fast = std::is_same_v<Device, device_ua22802_fast>;

template <typename Device>
int run_device(bench_runner& run, const std::vector<unsigned>& ns, unsigned pixels) {
    const overflow_mode mode = run.mode();
    specular_bench<Device> bench(
        "tb", run.random() ? random_surfaces(run.random_count(), run.seed()) : surfaces_for(ns, pixels),
        strobe_timing{},
        [mode](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) { return golden_ua22802(n, c, k, mode); },
        mode);
    bench.checker.inject_mismatch(run.inject(), run.inject_count());
    bench.checker.measure_accuracy(!run.random());
    using rom_t = shading::rom<ua22802::addr_fmt.width, ua22802::a_fmt.width>;
    std::printf("UA 22802 ROM: %llu words x %d bits (Q%d.%d unsigned) = %llu bits = %llu bytes\n",
                static_cast<unsigned long long>(rom_t::words), static_cast<int>(ua22802::a_fmt.width),
                ua22802::a_fmt.int_bits(), ua22802::a_fmt.frac, static_cast<unsigned long long>(rom_t::bits),
                static_cast<unsigned long long>(rom_t::bits / 8));
    run.simulate(bench, run.random() ? sc_core::sc_max_time() : sc_core::sc_time(1, sc_core::SC_SEC));

    if (run.random()) {
        run.report_random("random_" + run.mode_name() + (is_fast<Device> ? "_fast" : ""), bench.checker.samples(),
                          bench.checker.mismatches());
    } else {
        std::printf("%6s %8s %10s %14s\n", "n", "samples", "mismatches", "max_rel_err");
        for (const auto& [n, st] : bench.checker.stats()) {
            std::printf("%6llu %8zu %10zu %14.6f\n", static_cast<unsigned long long>(n), st.samples, st.mismatches,
                        st.max_rel_err_056);
            run.summary({run.bench(), "n=" + std::to_string(n) + (mode == overflow_mode::wrap ? "_wrap" : ""),
                         st.samples, st.mismatches, fmt_percent(st.max_rel_err_056, 2), "1 strobe",
                         "max rel err vs cos^n where cos^n >= 0.56; ROM " + std::to_string(rom_t::bits) +
                             " bits"});
        }
    }
    return run.finish(bench.checker.samples(), bench.checker.mismatches());
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    ua22802_options o;
    if (auto rc = parse_ua22802(argc, argv, o)) return *rc;
    bench_runner run("ua22802", o.bench);
    if (auto rc = run.start(argc, argv)) return *rc;
    const auto& ns = o.ns;
    const unsigned pixels = o.pixels;
    const std::string& abstraction = o.abstraction;
    if (abstraction == "fast") run.default_vcd("traces/ua22802_fast");
    report_log::get().expect(msg::input);  // n = 0 or n > 1000 on the command line: documented

    return abstraction == "fast" ? run_device<device_ua22802_fast>(run, ns, pixels)
                                 : run_device<device_ua22802>(run, ns, pixels);
}

