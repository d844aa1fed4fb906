// The race (src/golden_pipeline/race.h) on one frame: every scheme at the frozen configuration,
// one table (long operations a pixel in both conventions, state in bits, total error against exact
// Phong on the frame buffer and the 8-bit image) and one sheet (every scheme's image, and below it
// its error map at one scale), and the counts by unit (race_ops.csv: a cost model's input,
// scripts/phong_estimate.py). The cells' frame also runs in SystemC (the cell unit and the shading
// pipeline) and is held code for code to their golden model. Exit 0 when it is (or with --no-sim),
// 1 if not or on a failure, 2 for bad usage.
//   build/bin/render_race                                  (the head at 512, n = 20, sqmul)
//   build/bin/render_race --scene path/to/model.obj --n 100
//   build/bin/render_race --cells-tol 1.5                  (an extra row, marked not frozen)
#include <array>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cell_unit_bench.h"
#include "golden_pipeline/frame_setup.h"
#include "golden_pipeline/race.h"
#include "scene/image.h"
#include "scene/shade.h"
#include "testbenches/common/exit_status.h"
#include "testbenches/common/report_log.h"
#include "testbenches/options/tool_options.h"

using namespace shading;
using namespace shading::pipeline;

namespace {

std::string fmt(const char* f, double v) {
    char b[64];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

// The table, as Markdown (csv = false) or CSV.
std::string table(const std::vector<race_row>& rows, double phong_ops, bool csv) {
    const char* head_md = "| scheme | long ops / px | with 1/sqrt | adds / px | x Phong 1975 | state (bits) | NMSE frame "
                          "buffer | NMSE 8-bit | largest error (levels) | pixels > 4 levels |\n"
                          "|---|---|---|---|---|---|---|---|---|---|\n";
    const char* head_csv = "scheme,frozen,long_ops,long_ops_rsqrt,adds,times_phong1975,state_bits,nmse_frame_buffer,"
                           "nmse_8bit,max_error_levels,pixels_over_4,state,what\n";
    std::string t = csv ? head_csv : head_md;
    for (const race_row& r : rows) {
        const std::string name = r.scheme + (r.frozen ? "" : " (not frozen)");
        const std::vector<std::string> cells{
            fmt("%.2f", r.long_ops), fmt("%.2f", r.long_ops_rsqrt), fmt("%.1f", r.adds),
            fmt("%.2f", r.long_ops > 0 ? phong_ops / r.long_ops : 0.0), std::to_string(r.state_bits),
            fmt("%.3e", r.frame_buffer.nmse), fmt("%.3e", r.image8.nmse), fmt("%.2f", r.frame_buffer.max_abs),
            std::to_string(r.frame_buffer.pixels_over[0])};
        if (csv) {
            t += r.scheme + "," + (r.frozen ? "1" : "0");
            for (const auto& c : cells) t += "," + c;
            t += ",\"" + r.state + "\",\"" + r.what + "\"\n";
        } else {
            t += "| " + name;
            for (const auto& c : cells) t += " | " + c;
            t += " |\n";
        }
    }
    return t;
}

// One race_ops.csv row: a part's operations over the frame (scripts/phong_estimate.py prices each kind).
std::string ops_line(const std::string& scheme, const std::string& part, std::size_t pixels, uint64_t samples,
                     const scene::op_counts& c) {
    std::string t = scheme + "," + part + "," + std::to_string(pixels) + "," + std::to_string(samples);
    for (uint64_t v : {c.mul, c.div, c.sqrt, c.add, c.cmp, c.rsqrt}) t += "," + std::to_string(v);
    return t + "\n";
}

// The counts a cost model needs by kind and by the unit that performs them (race_ops.csv): Phong 1975
// with the device, the device's own operations apart (its samples counted as they are made); the
// lines' geometry side, sample stage and interpolation. Each scheme's sum is held to its race row.
std::string ops_table(const frame_setup& sf, const race_config& c, const std::vector<race_row>& rows) {
    scene::op_counts dev_ops;
    uint64_t samples = 0;
    const scene::specular_fn unit = [&](unsigned n, uint32_t code, const std::array<uint64_t, 3>& ksi) {
        dev_ops += scene::device_sample_ops(sf.dev, n);
        ++samples;
        return scene::device_specular(sf.dev, n, code, ksi);
    };
    scene::render_stats st;
    scene::render_specular_scanline(sf.r, unit, &st, c.walk_edges);
    const plan p = make_plan(sf.r, sf.k, sf.dev, c.lines);
    const hardware_counts h = hardware_ops(p, c.lines, sf.dev, sf.k.n);
    scene::op_counts phong = st.total(), lines = h.total();
    phong += dev_ops;
    for (const race_row& r : rows) {
        const double got = double(r.scheme == "lines" ? lines.long_ops() : phong.long_ops()) / double(sf.pixels);
        if ((r.scheme == "lines" || r.scheme == "phong1975_device") && r.frozen && got != r.long_ops)
            throw scene::scene_error("render_race: the counts by unit of " + r.scheme + " miss its race row");
    }
    return "scheme,part,pixels,samples,mul,div,sqrt,add,cmp,rsqrt\n" +
           ops_line("phong1975_device", "shader", sf.pixels, 0, st.total()) +
           ops_line("phong1975_device", "device", sf.pixels, samples, dev_ops) +
           ops_line("lines", "geometry", sf.pixels, p.check_samples, h.geometry) +
           ops_line("lines", "sample_stage", sf.pixels, h.samples, h.sample_stage) +
           ops_line("lines", "interpolation", sf.pixels, h.intervals, h.interpolation);
}

void write_file(const std::filesystem::path& p, const std::string& text) {
    std::ofstream f(p);
    f << text;
    if (!f) throw scene::image_error("render_race: cannot write " + p.string());
}

// Every scheme's image on the top row (exact Phong first), its error map below (the key first).
scene::rgb_image sheet(const std::vector<race_row>& rows, const scene::shaded_image& phong, double scale) {
    std::vector<scene::rgb_image> top{scene::to_rgb8(phong)}, bottom;
    std::vector<std::string> top_labels{"exact Phong"}, bottom_labels{""};
    bottom.push_back(scene::heat_map_legend(phong.width, phong.height, scale, "levels off exact Phong"));
    for (const race_row& r : rows) {
        top.push_back(scene::to_rgb8(r.image));
        top_labels.push_back(r.scheme + (r.frozen ? "" : " *"));
        bottom.push_back(scene::heat_map(scene::abs_error(r.image, phong), phong.width, phong.height, scale, &phong.covered));
        bottom_labels.push_back("");
    }
    return scene::stacked({scene::side_by_side(top, top_labels), scene::side_by_side(bottom, bottom_labels)});
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    tb::render_race_options o;
    if (auto rc = tb::parse_render_race(argc, argv, o)) return *rc;
    tb::report_log::install();
    try {
        const frame_setup sf(o.scene, o.data_dir, o.size, o.device, true, o.light, o.n);
        if (sf.pixels == 0) {
            std::fprintf(stderr, "render_race: the scene covers no pixel at %ux%u\n", o.size, o.size);
            return tb::exit_failure;
        }
        const race_config frozen = frozen_race_config();
        std::vector<race_row> rows = run_race(sf.r, sf.dev, frozen);
        // Settings other than the frozen ones: extra rows, marked.
        race_config tuned = frozen;
        std::vector<std::string> extra;
        if (o.cells_tol > 0) tuned.cells.tol = o.cells_tol, extra.push_back("cells");
        if (o.line_tol > 0) tuned.lines.length_tol = o.line_tol, extra.push_back("lines");
        if (o.fast_phong_budget > 0) tuned.fast_phong_budget = o.fast_phong_budget, extra.push_back("fast_phong_split");
        if (!extra.empty())
            for (race_row& r : run_race(sf.r, sf.dev, tuned, extra)) {
                r.frozen = false;
                rows.push_back(std::move(r));
            }
        double phong_ops = 0.0;
        for (const race_row& r : rows)
            if (r.scheme == "phong1975") phong_ops = r.long_ops;

        bool exact = true;
        std::string sim_line = "SystemC: not run (--no-sim).";
        if (o.sim) {
            const cell_plan p = make_cell_plan(sf.r, sf.k, sf.dev, frozen.cell_lines, frozen.cells);
            const tb::cells_run run = tb::simulate_cells(sf.r, p, sf.k, sf.dev, frozen.cell_lines);
            exact = run.finished && run.differ == 0 && run.stray == 0 && run.unit_mismatches == 0 &&
                    run.pipeline_mismatches == 0 && tb::report_log::get().unexpected() == 0;
            sim_line = "SystemC: the cells' frame (cell unit " + std::to_string(run.unit_clocks) + " clocks, shading pipeline " +
                       std::to_string(run.pipeline_clocks) + " clocks) " + (exact ? "is" : "is NOT") +
                       " the golden model's (" + std::to_string(run.differ) + " pixels differ, " +
                       std::to_string(run.stray) + " stray).";
        }
        const std::string title = "# The race: " + o.scene + " " + std::to_string(o.size) + "x" + std::to_string(o.size) +
                                  ", n = " + std::to_string(sf.k.n) + ", device " + o.device + ", " +
                                  std::to_string(sf.pixels) + " pixels\n\n";
        const std::string md = title + table(rows, phong_ops, false) + "\n" + sim_line + "\n";
        std::fputs(md.c_str(), stdout);
        std::filesystem::create_directories(o.out);
        const std::filesystem::path dir(o.out);
        write_file(dir / "race.md", md);
        write_file(dir / "race.csv", table(rows, phong_ops, true));
        write_file(dir / "race_ops.csv", ops_table(sf, frozen, rows));
        scene::save_png(sheet(rows, scene::render_phong(sf.r), o.error_scale), (dir / "race_sheet.png").string());
        std::printf("Wrote %s/race.md, race.csv, race_ops.csv and race_sheet.png (error maps white at %g levels).\n", o.out.c_str(),
                    o.error_scale);
        return exact ? tb::exit_success : tb::exit_failure;
    } catch (const std::exception& ex) {
        std::fprintf(stderr, "render_race: %s\n", ex.what());
        return tb::exit_failure;
    }
}
