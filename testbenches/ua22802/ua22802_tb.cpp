// UA 22802 testbench program: streams surfaces (n, k_s*I) and pixels (cos) through the device as
// in UA 60553, Fig. 3, compares every output with the golden model and with cos^n, writes a VCD
// (open with traces/ua22802.gtkw) and appends one summary row per n to $SHADING_SUMMARY.
// Returns mismatches + unexpected SystemC reports.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <systemc>

#include "common/report_log.h"
#include "common/sim_guard.h"
#include "specular/specular_tb.h"
#include "core/trace.h"
#include "ua22802/ua22802.h"
#include "golden/ua22802_golden.h"

using namespace shading;
using namespace shading::tb;

int sc_main(int argc, char* argv[]) {
    CLI::App app{"UA 22802 (ROM prototype) testbench"};
    std::string vcd = "traces/ua22802";
    bool no_vcd = false, wrap = false;
    unsigned pixels = 48;
    std::vector<unsigned> ns{1, 2, 3, 8, 32, 128, 512, 1000};
    app.add_option("--vcd", vcd, "VCD path without the .vcd suffix");
    app.add_flag("--no-vcd", no_vcd, "do not write a VCD");
    app.add_option("--pixels", pixels, "pixels per surface (half over [0,1], half where cos^n >= 0.56)")
        ->check(CLI::Range(2u, 100000u));
    app.add_option("--n", ns, "specular exponents, one surface each")->check(CLI::Range(0u, 1023u));
    app.add_flag("--wrap", wrap, "ADD11 wraps instead of saturating");
    CLI11_PARSE(app, argc, argv);

    report_log::install();
    report_log::get().expect(msg::input);  // n = 0 or n > 1000 on the command line: documented
    const overflow_mode mode = wrap ? overflow_mode::wrap : overflow_mode::saturate;

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

    specular_bench<device_ua22802> bench(
        "tb", surfaces, strobe_timing{},
        [mode](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) { return golden_ua22802(n, c, k, mode); },
        mode);
    std::unique_ptr<vcd_file> tf;
    if (!no_vcd) {
        tf = std::make_unique<vcd_file>(vcd);
        tf->trace(bench);
    }

    std::cout << "UA 22802 ROM: " << bench.dut.rom.words << " words x " << ua22802::a_fmt.width
              << " bits (Q" << ua22802::a_fmt.int_bits() << "." << ua22802::a_fmt.frac
              << " unsigned) = " << bench.dut.rom.bits << " bits = " << bench.dut.rom.bits / 8
              << " bytes\n";
    const bool done = run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_SEC));
    tf.reset();
    if (!done) std::cerr << "ua22802_tb: stimulus did not finish\n";

    const char* sum_path = std::getenv("SHADING_SUMMARY");
    std::ofstream sum;
    if (sum_path != nullptr && *sum_path != '\0') sum.open(sum_path, std::ios::app);
    std::printf("%6s %8s %10s %14s\n", "n", "samples", "mismatches", "max_rel_err");
    for (const auto& [n, st] : bench.checker.stats()) {
        std::printf("%6llu %8zu %10zu %14.6f\n", static_cast<unsigned long long>(n), st.samples,
                    st.mismatches, st.max_rel_err_056);
        if (sum.is_open())
            sum << "ua22802\tn=" << n << '\t' << st.samples << '\t' << st.mismatches << '\t'
                << std::fixed << std::setprecision(2) << 100.0 * st.max_rel_err_056
                << "%\t1 strobe\tmax rel err vs cos^n where cos^n >= 0.56; ROM "
                << bench.dut.rom.bits << " bits\n";
    }
    const std::size_t errors = bench.checker.mismatches() + report_log::get().unexpected() + (done ? 0 : 1);
    std::cout << "ua22802_tb: " << bench.checker.samples() << " samples, " << bench.checker.mismatches()
              << " mismatches, " << report_log::get().unexpected() << " unexpected reports\n";
    return static_cast<int>(errors);
}
