// UA 60553 testbench program: replays Fig. 3 (load n and k_s*I for R, G, B through their strobes,
// then stream cos values on ctl17), checks every validated output against the golden model and
// measures the device against cos^n. Returns mismatches + unexpected SystemC reports.
//
//   ua60553_tb                       scene line for n = 10 and 100, VCD in traces/ua60553.vcd
//   ua60553_tb --sweep --no-vcd      every cos code 0..1.0 for n = 1, 10, 100, 512, 1000
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>

#include "common/report_log.h"
#include "scene/scene.h"
#include "specular/specular_tb.h"
#include "core/trace.h"
#include "ua60553/ua60553.h"

using namespace shading;
using namespace shading::tb;

int sc_main(int argc, char* argv[]) {
    CLI::App app{"UA 60553 specular-colour device: Fig. 3 replay against the golden model"};
    std::string vcd_path = "traces/ua60553", mode_name = "saturate";
    std::string summary_path = std::getenv("SHADING_SUMMARY") ? std::getenv("SHADING_SUMMARY") : "";
    bool no_vcd = false, sweep = false;
    std::vector<unsigned> ns;
    unsigned scene_pixels = 96;
    double t_low_ns = 15, t_high_ns = 5;
    app.add_option("--vcd", vcd_path, "VCD path without the .vcd extension");
    app.add_flag("--no-vcd", no_vcd, "do not write a VCD");
    app.add_option("--mode", mode_name, "ADD11 overflow: saturate (default) or wrap (patent-faithful)")
        ->check(CLI::IsMember({"saturate", "wrap"}));
    app.add_flag("--sweep", sweep, "stream every cos code 0..0x8000 instead of a scene line");
    app.add_option("--n", ns, "specular exponents (default: 10 100 for the scene, 1 10 100 512 1000 for --sweep)");
    app.add_option("--scene-pixels", scene_pixels, "pixels of the sphere's raster line")->check(CLI::Range(2u, 100000u));
    app.add_option("--t-low-ns", t_low_ns, "ctl17 low phase = settling time T (Fig. 3)")->check(CLI::PositiveNumber);
    app.add_option("--t-high-ns", t_high_ns, "ctl17 high phase")->check(CLI::PositiveNumber);
    app.add_option("--summary", summary_path, "append TSV summary rows here (default: $SHADING_SUMMARY)");
    CLI11_PARSE(app, argc, argv);

    report_log::install();
    const overflow_mode mode = mode_name == "wrap" ? overflow_mode::wrap : overflow_mode::saturate;
    if (ns.empty()) ns = sweep ? std::vector<unsigned>{1, 10, 100, 512, 1000} : std::vector<unsigned>{10, 100};

    // Stimulus: one surface per n, white light (k_s*I = 255) on R so the relative error is read
    // at full scale; G and B at other levels to exercise all three multipliers.
    std::vector<surface> surfaces;
    std::vector<uint32_t> stream;
    if (sweep) {
        for (uint32_t c = 0; c <= spec::cos_one; ++c) stream.push_back(c);
    } else {
        for (double c : scene::sphere_line_cos(0.2, scene_pixels, 0.3, 0.4, 1.0)) stream.push_back(scene::cos_code(c));
    }
    for (unsigned n : ns) surfaces.push_back({n, {255, 180, 60}, stream});

    strobe_timing t;
    t.t_low = sc_core::sc_time(t_low_ns, sc_core::SC_NS);
    t.t_high = sc_core::sc_time(t_high_ns, sc_core::SC_NS);
    t.cos_lead = t.t_high / 2;
    auto golden = [mode](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        return golden_ua60553(n, c, k, mode);
    };
    specular_bench<device_ua60553> bench("tb", surfaces, t, golden, mode);

    std::unique_ptr<vcd_file> vcd;
    if (!no_vcd) {
        vcd = std::make_unique<vcd_file>(vcd_path);
        vcd->trace(bench);
    }
    sc_core::sc_start(bench.stim.duration() * 1.01 + sc_core::sc_time(1, sc_core::SC_US));
    vcd.reset();

    const bool finished = bench.finished();
    std::printf("UA 60553 (%s mode), strobe %.1f ns low / %.1f ns high, critical path %s\n", mode_name.c_str(),
                t_low_ns, t_high_ns, bench.dut.rg2_to_outputs().to_string().c_str());
    std::printf("%6s %9s %11s %26s\n", "n", "samples", "mismatches", "max rel err (cos^n>=0.56)");
    std::ofstream summary;
    if (!summary_path.empty()) summary.open(summary_path, std::ios::app);
    for (const auto& [n, st] : bench.checker.stats()) {
        std::printf("%6llu %9zu %11zu %25.3f%%\n", static_cast<unsigned long long>(n), st.samples, st.mismatches,
                    100.0 * st.max_rel_err_056);
        if (summary)
            summary << "ua60553\t" << (sweep ? "sweep" : "scene") << "_n" << n << "_" << mode_name << "\t"
                    << st.samples << "\t" << st.mismatches << "\t" << std::fixed << std::setprecision(2)
                    << 100.0 * st.max_rel_err_056 << "%\t1 strobe\tmax rel err vs cos^n where cos^n>=0.56; "
                    << (sweep ? "every cos code 0..1.0" : "sphere raster line") << "\n";
    }
    if (!no_vcd) std::printf("VCD: %s.vcd (open with: gtkwave %s.vcd traces/ua60553.gtkw)\n", vcd_path.c_str(), vcd_path.c_str());
    if (!finished) std::printf("ERROR: the stimulus did not finish\n");
    const auto failures = bench.checker.mismatches() + report_log::get().unexpected() + (finished ? 0 : 1);
    std::printf("%zu samples, %zu mismatches, %u unexpected reports\n", bench.checker.samples(),
                bench.checker.mismatches(), report_log::get().unexpected());
    return static_cast<int>(std::min<std::size_t>(failures, 255));
}
