// Where a polynomial through a raster line's samples misses: inside one triangle, or across a
// triangle's edge, where the Phong normal's slope (and the colour's) jumps (edge_split.h). Per-pixel
// shading through the device (the interpolation NMSE's reference) on one scene, its segments as the
// planner cuts them, samples every h pixels, three reconstructions through the same samples. Prints
// a Markdown table: per spacing and rule the NMSE, the points per pixel, the share of the
// interpolated pixels in gaps on one triangle and their share of the squared error, the NMSE of each
// part.
//   build/bin/edge_study                                  (the head at 512, about 0.1 s)
//   build/bin/edge_study --scene sphere --spacing 4,8,16
#include <algorithm>
#include <cstdio>
#include <exception>
#include <vector>

#include "edge_split.h"
#include "line_kinks.h"
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
        const pipeline::plan_config cfg;  // the planner's segments: depth step, folds

        // Every segment's reference colours (levels) and triangles, and its runs on one triangle.
        struct segment {
            std::vector<rgb_levels> v;
            std::vector<int32_t> tri;
            segment_kinks kinks;
        };
        std::vector<segment> segs;
        std::size_t pixels = 0, runs = 0, edges = 0, vertices = 0;
        for (unsigned y = 0; y < r.height; ++y)
            for (const auto& s : pipeline::line_segments(r, y, cfg, nullptr)) {
                segment g;
                for (unsigned x = s[0]; x <= s[1]; ++x) {
                    const auto& c = pp.px[r.index(x, y)];
                    g.v.push_back({c[0] * pipeline::pixel_fmt.lsb(), c[1] * pipeline::pixel_fmt.lsb(),
                                   c[2] * pipeline::pixel_fmt.lsb()});
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
    } catch (const std::exception& e) {
        std::fprintf(stderr, "edge_study: %s\n", e.what());
        return tb::exit_failure;
    }
    return tb::exit_success;
}
