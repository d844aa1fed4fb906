// Where a polynomial through a raster line's samples misses: inside one triangle, or across a
// triangle's edge, where the Phong normal's slope (and the colour's) jumps, or past a mesh vertex
// (edge_split.h, line_kinks.h). Per-pixel shading through the device (the interpolation NMSE's
// reference) on one scene, its segments as the planner cuts them, samples every h pixels, three
// reconstructions through the same samples. Prints Markdown tables: per spacing and rule the NMSE,
// the points per pixel, the share of the interpolated pixels in gaps on one triangle and past a
// vertex and their shares of the squared error; the NMSE with every shared edge's exact slope jump
// taken out first; the gaps past a vertex in fifths by how far the passed vertex's normal stands
// out from its neighbours' (normal_laplacian), each fifth's share of the error; every other line
// rebuilt from the lines above and below against every other column from its neighbours; every
// other line predicted from the lines either side and corrected by its own samples.
//   build/bin/edge_study                                  (the head at 512, about 0.2 s)
//   build/bin/edge_study --scene sphere --spacing 4,8,16
#include <algorithm>
#include <cstdio>
#include <exception>
#include <vector>

#include "edge_split.h"
#include "line_kinks.h"
#include "study_frame.h"
#include "golden_pipeline/pipeline.h"
#include "scene/raster.h"
#include "testbenches/common/exit_status.h"
#include "testbenches/options/tool_options.h"

using namespace shading;
using namespace shading::study;

int main(int argc, char* argv[]) {
    tb::edge_study_options o;
    if (auto rc = tb::parse_edge_study(argc, argv, o)) return *rc;
    try {
        const scene::world w = scene::builtin_scene(o.scene, o.data_dir, o.size, o.size);
        const scene::rasterised r = scene::rasterise(w);
        const pipeline::frame_constants k = pipeline::frame_constants_of(w);
        scene::device_config dev;
        dev.device = scene::parse_device(o.device);
        const pipeline::frame pp = pipeline::per_pixel_frame(r, k, dev);
        const std::vector<rgb_levels> colour = levels_of(pp);  // the reference, levels
        const pipeline::plan_config cfg;  // the planner's segments: depth step, folds

        // Every segment's reference colours (levels) and triangles, and its runs on one triangle.
        struct segment {
            std::vector<rgb_levels> v;
            std::vector<int32_t> tri;
            segment_kinks kinks;
            uint32_t object;
        };
        std::vector<segment> segs;
        std::size_t pixels = 0, runs = 0, edges = 0, vertices = 0;
        for (unsigned y = 0; y < r.height; ++y)
            for (const auto& s : pipeline::line_segments(r, y, cfg, nullptr)) {
                segment g;
                g.object = static_cast<uint32_t>(r.object_at(s[0], y));
                for (unsigned x = s[0]; x <= s[1]; ++x) {
                    g.v.push_back(colour[r.index(x, y)]);
                    g.tri.push_back(r.tri[r.index(x, y)]);
                    if (x == s[0] || g.tri[g.tri.size() - 2] != g.tri.back()) ++runs;
                }
                g.kinks = kinks_of(r, y, s[0], s[1]);
                edges += g.kinks.edges;
                vertices += g.kinks.vertices;
                pixels += g.v.size();
                segs.push_back(std::move(g));
            }

        if (pixels == 0 || !(segs.size() > 0)) {
            std::fprintf(stderr, "edge_study: the scene covers no pixel at %ux%u\n", o.size, o.size);
            return tb::exit_failure;
        }
        std::printf("# Interpolation error inside one triangle and across edges: %s %ux%u, device %s, n = %u\n\n",
                    o.scene.c_str(), o.size, o.size, o.device.c_str(), k.n);
        std::printf("%zu pixels in %zu segments; %zu runs on one triangle (%.2f pixels a run); between them %zu "
                    "shared edges crossed and %zu vertices passed.\n\n",
                    pixels, segs.size(), runs, double(pixels) / double(runs), edges, vertices);
        std::printf("| h | rule | points / px | NMSE | interpolated pixels in one-triangle gaps | their share of the "
                    "squared error | NMSE there | NMSE across edges | interpolated pixels in gaps past a vertex | their share "
                    "of the squared error |\n|---|---|---|---|---|---|---|---|---|---|\n");
        for (unsigned h : o.spacings)
            for (reconstruction rule : {reconstruction::linear, reconstruction::quadratic, reconstruction::cubic}) {
                edge_split all;
                for (const segment& g : segs) all += split_errors(g.v, g.tri, h, rule, g.kinks.vertex_pass);
                const double se = all.se_within + all.se_crossing;
                const double interpolated = double(std::max<std::size_t>(1, all.interpolated()));
                std::printf("| %u | %s | %.4f | %.3e | %.3f | %.4f | %.2e | %.2e | %.3f | %.3f |\n", h,
                            reconstruction_name(rule), double(all.points) / double(all.pixels()), se / all.ref2,
                            double(all.pixels_within) / interpolated, se > 0.0 ? all.se_within / se : 0.0,
                            all.se_within / all.ref2, all.se_crossing / all.ref2,
                            double(all.pixels_past_vertex) / interpolated, se > 0.0 ? all.se_past_vertex / se : 0.0);
            }

        // The kinks taken out: every shared edge's exact slope jump (line_kinks.h) removed before the
        // samples are interpolated and added back after. Passes by a vertex keep theirs.
        std::printf("\nWith the slope jump at every shared edge known exactly (exact Phong's) and taken out first:\n\n"
                    "| h | rule | NMSE | with the jumps taken out | its share past a vertex |\n|---|---|---|---|---|\n");
        for (unsigned h : o.spacings)
            for (reconstruction rule : {reconstruction::linear, reconstruction::cubic}) {
                edge_split plain, ramped;
                for (const segment& g : segs) {
                    plain += split_errors(g.v, g.tri, h, rule, g.kinks.vertex_pass);
                    ramped += split_errors(g.v, g.tri, h, rule, g.kinks.vertex_pass, &g.kinks.jumps);
                }
                const double se = ramped.se_within + ramped.se_crossing;
                std::printf("| %u | %s | %.3e | %.3e | %.3f |\n", h, reconstruction_name(rule),
                            (plain.se_within + plain.se_crossing) / plain.ref2, se / ramped.ref2,
                            se > 0.0 ? ramped.se_past_vertex / se : 0.0);
            }

        // The gaps past a vertex by how far the passed vertex's normal stands out from its
        // neighbours' (normal_laplacian; a gap passing several: the largest), in fifths of those gaps.
        std::vector<std::vector<double>> lap;
        std::vector<double> every;
        for (const scene::object& obj : w.objects) {
            lap.push_back(normal_laplacian(obj.geometry));
            every.insert(every.end(), lap.back().begin(), lap.back().end());
        }
        std::sort(every.begin(), every.end());
        std::printf("\nThe gaps past a vertex, the cubic, in fifths by the passed vertex's |N_v - mean N_u| (u its "
                    "neighbours; over the scene's vertices: median %.4f, 90th percentile %.4f):\n\n"
                    "| h | fifth | the vertices' range | gaps | their share of the squared error | squared error a gap |\n"
                    "|---|---|---|---|---|---|\n",
                    every[every.size() / 2], every[every.size() * 9 / 10]);
        for (unsigned h : o.spacings) {
            std::vector<std::pair<double, double>> gaps;  // (the passed vertex's value, the gap's squared error)
            double se_all = 0.0;
            for (const segment& g : segs) {
                const std::vector<rgb_levels> rec = reconstruct(g.v, h, reconstruction::cubic, nullptr);
                for (std::size_t gap = 0; gap < (g.v.size() - 1) / h; ++gap) {
                    double se = 0.0, key = -1.0;
                    for (std::size_t i = gap * h; i < gap * h + h; ++i)
                        for (int ch = 0; ch < 3; ++ch) se += (rec[i][ch] - g.v[i][ch]) * (rec[i][ch] - g.v[i][ch]);
                    for (std::size_t i = gap * h + 1; i <= gap * h + h; ++i)
                        if (g.kinks.vertex_pass[i]) key = std::max(key, lap[g.object][g.kinks.passed[i]]);
                    se_all += se;
                    if (key >= 0.0) gaps.push_back({key, se});
                }
            }
            std::sort(gaps.begin(), gaps.end());
            for (std::size_t f = 0; f < 5 && gaps.size() >= 5; ++f) {
                const std::size_t a = gaps.size() * f / 5, b = gaps.size() * (f + 1) / 5;
                double se = 0.0;
                for (std::size_t i = a; i < b; ++i) se += gaps[i].second;
                std::printf("| %u | %zu | %.4f..%.4f | %zu | %.3f | %.3g |\n", h, f + 1, gaps[a].first, gaps[b - 1].first,
                            b - a, se_all > 0.0 ? se / se_all : 0.0, se / double(b - a));
            }
        }

        // Would the lines either side stand in for a line's own samples? Every other line rebuilt as
        // the mean of its neighbours above and below, against every other column as the mean of its
        // neighbours along the line: the same linear rule at the same spacing, the same pixels' triangles
        // required to be one patch of the mesh (midpoint_errors).
        const auto patch = [&r](int32_t a, int32_t b) { return one_patch(r, a, b); };
        std::printf("\nEvery other line (or column) as the mean of the two beside it, where the three pixels lie on one "
                    "patch of the mesh (the rest exact):\n\n| rebuilt | pixels rebuilt | NMSE of the image |\n|---|---|---|\n");
        for (bool across : {true, false}) {
            const midpoint_error m = midpoint_errors(colour, r.tri, r.width, r.height, across, patch);
            std::printf("| %s | %zu | %.3e |\n", across ? "odd lines, from the lines above and below" :
                        "odd columns, from the pixels left and right", m.pixels, m.ref2 > 0.0 ? m.se / m.ref2 : 0.0);
        }
        std::printf("\nEvery other line predicted from the exact lines either side, its own samples every h pixels "
                    "correcting the prediction (the residual rebuilt), against the same samples rebuilding the colour "
                    "(odd_lines_predicted; the NMSE is the odd lines' part of the image's):\n\n"
                    "| h | rule | pixels | points / px | NMSE rebuilt directly | NMSE predicted and corrected | "
                    "ratio |\n|---|---|---|---|---|---|---|\n");
        for (unsigned h : o.spacings)
            for (reconstruction rule : {reconstruction::linear, reconstruction::cubic}) {
                const predicted_lines q = odd_lines_predicted(colour, r.tri, r.width, r.height, h, rule, patch);
                std::printf("| %u | %s | %zu | %.4f | %.3e | %.3e | %.1f |\n", h, reconstruction_name(rule), q.pixels,
                            double(q.points) / double(std::max<std::size_t>(1, q.pixels)), q.se_direct / q.ref2,
                            q.se_predicted / q.ref2, q.se_predicted > 0.0 ? q.se_direct / q.se_predicted : 0.0);
            }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "edge_study: %s\n", e.what());
        return tb::exit_failure;
    }
    return tb::exit_success;
}
