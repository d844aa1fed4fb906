// The race (src/golden_pipeline/race.h) on one frame: every scheme at the frozen configuration,
// one table (long operations a pixel in both conventions, state in bits, total error against exact
// Phong on the frame buffer and the 8-bit image) and one sheet (every scheme's image, and below it
// its error map at one scale). The cells' frame also runs in SystemC (the cell unit and the shading
// pipeline) and is held code for code to their golden model. Exit 0 when it is (or with --no-sim),
// 1 if not or on a failure, 2 for bad usage.
//   build/bin/render_race                                  (the head at 512, n = 20, sqmul)
//   build/bin/render_race --scene path/to/model.obj --n 100
//   build/bin/render_race --cells-tol 1.5                  (an extra row, marked not frozen)
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
        scene::save_png(sheet(rows, scene::render_phong(sf.r), o.error_scale), (dir / "race_sheet.png").string());
        std::printf("Wrote %s/race.md, race.csv and race_sheet.png (error maps white at %g levels).\n", o.out.c_str(),
                    o.error_scale);
        return exact ? tb::exit_success : tb::exit_failure;
    } catch (const std::exception& ex) {
        std::fprintf(stderr, "render_race: %s\n", ex.what());
        return tb::exit_failure;
    }
}
