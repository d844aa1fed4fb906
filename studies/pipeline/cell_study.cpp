// A quadtree of biquadratic cells decided from its lattices' differences (cell_tree.h): is the
// interpolation target (NMSE <= 1e-5 against per-pixel shading, >= 3x fewer long operations than the
// scan-line Phong) in reach of a scheme that pays no check point for its decisions? No SystemC.
// On one scene (default the head at 512, the squared device, n = 20), at each --tol:
//  - the points per pixel, the cells sent by size, the smallest cells sent as row quadratics or exact,
//    the pixels the cells, the columns and the rows delivered;
//  - the NMSE against per-pixel shading through the device, the largest error and the pixels beyond
//    4 and 16 levels;
//  - the long operations counted as the planner counts a plan's (cell_long_ops: the points' geometry
//    stepped in the order the scheme reads them, and in raster order, a colour formed at each),
//    against the scan-line Phong; with --walk-edges both walk edges;
//  - the cheapest meeting --nmse, counted in the scheme's order;
//  - with --perfect-decisions, a yardstick: every decision on the true error of what it sends;
//  - with --golden, the bit-accurate cells (src/golden_pipeline/cells.h) instead of the emulation:
//    the sample stage's codes, forward differences, the rest by the planner down columns and along rows.
//   build/bin/cell_study                  (under 1 s at 512)
//   build/bin/cell_study --size 48 --tol 1,2
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <vector>

#include "testbenches/common/exit_status.h"
#include "testbenches/options/tool_options.h"
#include "cell_tree.h"
#include "line_kinks.h"
#include "golden_pipeline/cells.h"
#include "study_frame.h"

using namespace shading;
using namespace shading::pipeline;
using namespace shading::study;

namespace {

// The bit-accurate cells (src/golden_pipeline/cells.h) in the emulation's terms: their frame in
// levels, their points in the order read (the columns' stepped down their columns).
cell_frame golden_cells(const study_frame& sf, const plan_config& cfg, const cell_tree_config& t) {
    cell_config g;
    g.tol = t.tol;
    g.d2_factor = t.d2_factor;
    g.d3_factor = t.d3_factor;
    g.fallback_tol = t.fallback_tol;
    g.s_max = t.s_max;
    g.s_min = t.s_min;
    g.line_tol = t.line_tol;
    g.line_m_max = t.line_m_max;
    g.column_ratio = t.column_ratio;
    plan_config c = cfg;
    c.eval = evaluator::fd;
    const cell_plan p = make_cell_plan(sf.r, sf.k, sf.dev, c, g);
    const frame fr = golden_cell_frame(p, sf.k, sf.dev, c);
    cell_frame f;
    f.out = levels_of(fr);
    f.point.assign(fr.px.size(), 0);
    for (const auto& q : p.points) f.point[sf.r.index(q[0], q[1])] = 1;
    f.order = p.points;
    f.sent = p.sent;
    f.fallback_rows = p.fallback_rows;
    f.fallback_exact = p.fallback_exact;
    f.pixels = p.pixels;
    f.pixels_cells = p.pixels_cells;
    f.pixels_columns = p.pixels_columns;
    f.pixels_rows = p.pixels_rows;
    f.order_down = p.point_down;
    f.points_lines = p.points_lines;
    for (std::size_t i = 0; i < fr.px.size(); ++i) {
        if (sf.r.tri[i] < 0) continue;
        for (int ch = 0; ch < 3; ++ch) {
            const double d = f.out[i][ch] - sf.colour[i][ch];
            f.se += d * d;
            f.ref2 += sf.colour[i][ch] * sf.colour[i][ch];
        }
    }
    return f;
}

}  // namespace

int main(int argc, char* argv[]) {
    tb::cell_study_options o;
    if (auto rc = tb::parse_cell_study(argc, argv, o)) return *rc;
    try {
        const study_frame sf(o.scene, o.data_dir, o.size, o.device, o.walk_edges, o.light, o.n);
        const scene::rasterised& r = sf.r;
        const std::vector<rgb_levels>& colour = sf.colour;
        if (sf.pixels == 0) {
            std::fprintf(stderr, "cell_study: the scene covers no pixel at %ux%u\n", o.size, o.size);
            return tb::exit_failure;
        }
        const double pixels = double(sf.pixels), scanline = sf.scanline;
        plan_config cfg;  // the planner's segments
        cfg.walk_edges = o.walk_edges;
        cell_tree_config t;
        t.d2_factor = o.d2_factor;
        t.d3_factor = o.d3_factor;
        t.fallback_tol = o.fallback_tol;
        t.line_tol = o.line_tol;
        t.s_max = o.cell_max;  // s_min stays 4, the smallest cell with a lattice between its corners
        t.line_m_max = o.m_max;
        t.perfect = o.perfect_decisions;

        char light[64] = "the scene's";
        if (!o.light.empty()) std::snprintf(light, sizeof light, "%g,%g", o.light[0], o.light[1]);
        std::printf("# Cells: a quadtree of biquadratic cells decided from its lattices' differences. %s %ux%u, device "
                    "%s, light %s, n = %u, cells %u..%u, d2 %.3g T, d3 %.3g T, fallback %.3g, lines T = %.3g m <= %u, edges %s, "
                    "NMSE limit %.3g%s\n\n",
                    o.scene.c_str(), o.size, o.size, o.device.c_str(),
                    light, sf.k.n, t.s_min, t.s_max, t.d2_factor, t.d3_factor,
                    t.fallback_tol, t.line_tol, t.line_m_max, o.walk_edges ? "walked" : "not walked", o.nmse,
                    o.perfect_decisions ? ", perfect decisions (a yardstick)" : "");
        std::printf("Scan-line Phong: %.2f long operations per pixel (%zu pixels); 3x needs %.2f. Phong from scratch: "
                    "%.2f.\n\n",
                    scanline, sf.pixels, scanline / 3.0, sf.phong);
        std::printf("| T | points / px | cells sent (%u, %u, ...) | smallest: rows / exact | pixels: cells / columns / "
                    "rows | points / px: cells' / lines' | NMSE | largest error | beyond 4 / 16 | long ops / px, its order "
                    "(x scan-line) | raster order (x) |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
                    t.s_min, 2 * t.s_min);
        std::optional<double> best;
        double best_T = 0.0, best_points = 0.0, best_nmse = 0.0, best_raster = 0.0;
        for (double tol : o.tol) {
            t.tol = tol;
            const cell_frame f = o.golden ? golden_cells(sf, cfg, t) : emulate_cells(r, colour, cfg, t);
            double worst = 0.0;
            std::size_t over4 = 0, over16 = 0;
            for (std::size_t i = 0; i < colour.size(); ++i) {
                if (r.tri[i] < 0) continue;
                double e = 0.0;
                for (int ch = 0; ch < 3; ++ch) e = std::max(e, std::abs(f.out[i][ch] - colour[i][ch]));
                worst = std::max(worst, e);
                over4 += e > 4.0;
                over16 += e > 16.0;
            }
            const double own = cell_long_ops(r, f, sf.dev, sf.k.n, o.walk_edges, false).long_ops() / pixels;
            const double raster = cell_long_ops(r, f, sf.dev, sf.k.n, o.walk_edges, true).long_ops() / pixels;
            const double pts = double(f.points()) / double(f.pixels);
            std::printf("| %.3g | %.4f | ", tol, pts);
            for (std::size_t s = 0; s < f.sent.size(); ++s) std::printf("%s%zu", s ? ", " : "", f.sent[s]);
            const std::size_t line_pixels = f.pixels_columns + f.pixels_rows;
            std::printf(" | %zu / %zu | %zu / %zu / %zu | %.3f / %.3f | %.3e | %.1f | %zu / %zu | %.2f (%.2fx) | %.2f "
                        "(%.2fx) |\n",
                        f.fallback_rows, f.fallback_exact, f.pixels_cells, f.pixels_columns, f.pixels_rows,
                        double(f.points() - f.points_lines) / double(std::max<std::size_t>(1, f.pixels_cells)),
                        double(f.points_lines) / double(std::max<std::size_t>(1, line_pixels)), f.nmse(),
                        worst, over4, over16, own, scanline / own, raster, scanline / raster);
            if (f.nmse() <= o.nmse && (!best || own < *best)) {
                best = own;
                best_T = tol;
                best_points = pts;
                best_nmse = f.nmse();
                best_raster = raster;
            }
        }
        if (!best)
            std::printf("\nThe cheapest meeting NMSE <= %.3g: none of --tol\n", o.nmse);
        else
            std::printf("\nThe cheapest meeting NMSE <= %.3g: T = %.3g, %.4f points / px (NMSE %.3e), counted %.2f long "
                        "ops / px in its order: %.2fx the scan-line Phong, %.2fx the from-scratch Phong (raster order "
                        "%.2f: %.2fx)\n",
                        o.nmse, best_T, best_points, best_nmse, *best, scanline / *best, sf.phong / *best, best_raster,
                        scanline / best_raster);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cell_study: %s\n", e.what());
        return tb::exit_failure;
    }
    return tb::exit_success;
}
