// A raster line's segments (line_geometry.h): the spans cut at the discontinuities and folds.
#include "golden_pipeline/line_geometry.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace shading::pipeline {

// The visible surface jumps to another part of the mesh between two neighbouring pixels when their
// triangles share no vertex (a fold: eyelid, ear, nostril, lips, in front of a surface at nearly
// the same depth). Integer compares on the rasteriser's triangle indices, counted as decisions.
bool surface_break(const scene::rasterised& r, std::size_t a, std::size_t b, scene::op_counts* decision) {
    const int32_t ta = r.tri[a], tb = r.tri[b];
    if (ta == tb) return false;
    const scene::triangle_setup& sa = r.setups[static_cast<std::size_t>(ta)];
    const scene::triangle_setup& sb = r.setups[static_cast<std::size_t>(tb)];
    if (sa.object != sb.object) return true;
    const scene::mesh& m = r.src->objects[sa.object].geometry;
    const auto& va = m.triangles[sa.triangle];
    const auto& vb = m.triangles[sb.triangle];
    for (uint32_t i : va)
        for (uint32_t j : vb) {
            if (decision) ++decision->cmp;
            if (i == j) return false;
        }
    return true;
}

std::vector<std::array<unsigned, 2>> line_segments(const scene::rasterised& r, unsigned y, const plan_config& c,
                                                   scene::op_counts* decision) {
    // Segment boundaries: every discontinuity (coverage edges bound the spans; object changes and
    // depth steps cut them), so no interval's pixels or samples straddle one.
    std::vector<unsigned> cuts;
    for (const auto& d : scene::line_discontinuities(r, y, c.depth_step)) cuts.push_back(d.x);
    if (c.surface_breaks) {
        for (unsigned x = 1; x < r.width; ++x)
            if (r.covered(x - 1, y) && r.covered(x, y) && surface_break(r, r.index(x - 1, y), r.index(x, y), decision))
                cuts.push_back(x);
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    }
    std::vector<std::array<unsigned, 2>> out;
    for (const scene::span& sp : scene::line_spans(r, y)) {
        unsigned xa = sp.x_begin;
        for (unsigned x : cuts)
            if (x > sp.x_begin && x < sp.x_end) {
                out.push_back({xa, x - 1});
                xa = x;
            }
        out.push_back({xa, sp.x_end - 1});
    }
    return out;
}

namespace {
// The counts below take covered pixels only: anything else is the caller's error.
void require_covered(const scene::rasterised& r, const std::array<unsigned, 2>& pt, const char* who) {
    if (pt[0] >= r.width || pt[1] >= r.height || !r.covered(pt[0], pt[1]))
        throw std::invalid_argument(std::string(who) + ": (" + std::to_string(pt[0]) + ", " + std::to_string(pt[1]) +
                                    ") is not a covered pixel");
}
}  // namespace

stepped_count stepped_geometry(const scene::rasterised& r, const std::vector<std::array<unsigned, 2>>& points,
                               bool walk_edges, const std::vector<uint8_t>& down) {
    if (!down.empty() && down.size() != points.size())
        throw std::invalid_argument("stepped_geometry: " + std::to_string(down.size()) + " column flags for " +
                                    std::to_string(points.size()) + " points");
    scene::span_stepper stepper(r, walk_edges);
    stepped_count out;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto& pt = points[i];
        require_covered(r, pt, "stepped_geometry");
        line_geometry::charge_dots(stepper.at(pt[0], pt[1], &out.ops, !down.empty() && down[i] != 0), &out.ops);
    }
    out.stats = stepper.stats();
    return out;
}

std::size_t walker_live_triangles(const scene::rasterised& r, const std::vector<std::array<unsigned, 2>>& points) {
    std::vector<std::size_t> last(r.setups.size(), 0);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto& pt = points[i];
        require_covered(r, pt, "walker_live_triangles");
        last[static_cast<std::size_t>(r.tri[r.index(pt[0], pt[1])])] = i;
    }
    std::vector<uint8_t> open(r.setups.size(), 0);
    std::size_t live = 0, most = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const std::size_t t = static_cast<std::size_t>(r.tri[r.index(points[i][0], points[i][1])]);
        if (!open[t]) {
            open[t] = 1;
            most = std::max(most, ++live);
        }
        if (last[t] == i) {
            open[t] = 0;
            --live;
        }
    }
    return most;
}

}  // namespace shading::pipeline
