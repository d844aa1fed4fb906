// The cells (src/golden_pipeline/cells.h) rendered in SystemC: the planned cells through the cell
// unit (modules/pipeline/cell_unit.h), the intervals and the cells' points through the shading
// pipeline (forward differences, any m per interval), the frame composed and held code for code to
// the golden model's. Prints what the scheme sent, the clocks of both units, the interpolation NMSE
// against per-pixel shading through the device and the largest error, and the long operations a
// pixel counted as cell_study counts them (the points' geometry stepped in the order read, a colour
// at each) against the scan-line Phong. Exit 0 when the SystemC frame is the golden one, 1 if not.
//   build/bin/render_cells                       (the head at 512, T = 0.89; about 4 s)
//   build/bin/render_cells --walk-edges
//   build/bin/render_cells --size 96 --scene torus --tol 2
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <vector>

#include "cell_unit_bench.h"
#include "golden_pipeline/frame_setup.h"
#include "testbenches/common/exit_status.h"
#include "testbenches/common/report_log.h"
#include "testbenches/options/tool_options.h"

using namespace shading;
using namespace shading::pipeline;

int sc_main(int argc, char* argv[]) {
    tb::render_cells_options o;
    if (auto rc = tb::parse_render_cells(argc, argv, o)) return *rc;
    tb::report_log::install();
    try {
        const frame_setup sf(o.scene, o.data_dir, o.size, o.device, o.walk_edges, o.light, o.n);
        if (sf.pixels == 0) {
            std::fprintf(stderr, "render_cells: the scene covers no pixel at %ux%u\n", o.size, o.size);
            return tb::exit_failure;
        }
        plan_config c;
        c.eval = evaluator::fd;
        c.length = length_policy::adaptive;  // the pipeline's fd channel built for any m per interval
        cell_config t;
        t.tol = o.tol;
        const cell_plan p = make_cell_plan(sf.r, sf.k, sf.dev, c, t);
        const tb::cells_run run = tb::simulate_cells(sf.r, p, sf.k, sf.dev, c);
        const error_stats e = compare(to_image(run.f), to_image(sf.per_pixel));
        const cell_counts n = cell_ops(sf.r, p, sf.dev, sf.k.n, o.walk_edges);
        const double px = double(sf.pixels), ops = n.long_ops() / px;
        const bool exact = run.finished && run.differ == 0 && run.stray == 0 && run.unit_mismatches == 0 &&
                           run.pipeline_mismatches == 0 && tb::report_log::get().unexpected() == 0;

        std::printf("# The cells in SystemC: %s %ux%u, device %s, n = %u, T = %g, edges %s\n\n", o.scene.c_str(), o.size,
                    o.size, o.device.c_str(), sf.k.n, o.tol, o.walk_edges ? "walked" : "not walked");
        std::printf("Sent: %zu cells (", p.cells.size());
        for (std::size_t s = 0; s < p.sent.size(); ++s) std::printf("%s%zu of %u", s ? ", " : "", p.sent[s], t.s_min << s);
        std::printf("), %zu smallest as row quadratics and %zu exact; %zu pixels by cells, %zu down columns, %zu "
                    "along rows; %.4f points a pixel.\n",
                    p.fallback_rows, p.fallback_exact, p.pixels_cells, p.pixels_columns, p.pixels_rows,
                    double(p.points.size()) / px);
        std::printf("SystemC: the cell unit %llu clocks, the shading pipeline %llu clocks (%zu jobs); the frame %s the "
                    "golden model's (%zu pixels differ, %zu stray; the benches' checkers %zu and %zu).\n",
                    static_cast<unsigned long long>(run.unit_clocks), static_cast<unsigned long long>(run.pipeline_clocks),
                    pipeline_plan(p).jobs.size(), exact ? "is" : "is NOT", run.differ, run.stray, run.unit_mismatches,
                    run.pipeline_mismatches);
        std::printf("Against per-pixel shading through the device: NMSE %.3e, largest error %.1f levels, %zu pixels "
                    "beyond 4 levels.\n",
                    e.nmse, e.max_abs, e.pixels_over[0]);
        std::printf("Long operations a pixel: %.2f (geometry %.2f, colours %.2f): %.2fx the scan-line Phong's %.2f, "
                    "%.2fx the from-scratch Phong's %.2f.\n",
                    ops, double(n.geometry.long_ops()) / px, double(n.colours.long_ops()) / px, sf.scanline / ops,
                    sf.scanline, sf.phong / ops, sf.phong);
        if (o.walk_edges) {
            std::vector<std::array<unsigned, 2>> every;  // the scan-line Phong's points, in raster order
            for (unsigned y = 0; y < sf.r.height; ++y)
                for (unsigned x = 0; x < sf.r.width; ++x)
                    if (sf.r.covered(x, y)) every.push_back({x, y});
            std::printf("The edge walker holds at most %zu triangles' stepped values at once in the order read (the "
                        "scan-line Phong's %zu).\n",
                        walker_live_triangles(sf.r, p.points), walker_live_triangles(sf.r, every));
        }
        return exact ? tb::exit_success : tb::exit_failure;
    } catch (const std::exception& ex) {
        std::fprintf(stderr, "render_cells: %s\n", ex.what());
        return tb::exit_failure;
    }
}
