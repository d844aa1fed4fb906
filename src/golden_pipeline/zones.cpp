// The zone map of the head (the interpolation paper, Fig. 5). The figure is not in the paper's text, and the text
// names no zone: it says only that the face is cut into characteristic zones and that zones 2, 4 and
// 7 are interpolated by a quadratic, the others by a cubic. The names and boxes below are OUR reading:
// we number the zones so that 2, 4 and 7 are the flat ones (forehead, cheeks, chin), which is what a
// quadratic suits, and calibrate the boxes on the head scan (Lee Perry-Smith's, data/head/) by eye on
// a zone map drawn over the shaded head (test_pipeline_plan writes it: build/out/pipeline/zones_head.png).
// The zone policy takes an interval's degree from the zone of its first pixel; intervals are not cut
// at zone borders (plan.cpp; docs/shading-system.md, "Zone borders: not cut").
#include <algorithm>
#include <cmath>

#include "golden_pipeline/pipeline.h"

namespace shading::pipeline {

namespace {
// The head's frame, from its mesh alone: the axis-aligned bounds, and the nose tip (the vertex
// farthest along +z: the scan looks along +z with +y up). Computed once per mesh and thread.
struct head_frame {
    const glm::dvec3* data = nullptr;  // the mesh's positions, as the cache's key
    std::size_t size = 0;
    glm::dvec3 first{0.0}, last{0.0};
    scene::bounds b{};
    glm::dvec3 tip{0.0};
};

const head_frame& frame_of(const scene::mesh& m) {
    // A cache of one entry per thread (the frame is a pure function of the mesh): keyed by the
    // positions' storage, count and end vertices, so another mesh never reads a stale frame.
    thread_local head_frame cache;
    const bool hit = cache.data == m.positions.data() && cache.size == m.positions.size() && cache.size > 0 &&
                     cache.first == m.positions.front() && cache.last == m.positions.back();
    if (!hit) {
        head_frame f;
        f.data = m.positions.data();
        f.size = m.positions.size();
        if (f.size > 0) {
            f.first = m.positions.front();
            f.last = m.positions.back();
            f.b = scene::mesh_bounds(m);
            f.tip = m.positions.front();
            for (const auto& p : m.positions)
                if (p.z > f.tip.z) f.tip = p;
        }
        cache = f;
    }
    return cache;
}
}  // namespace

const char* zone_name(unsigned zone) {
    switch (zone) {
        case 0: return "other";
        case 1: return "brows";
        case 2: return "forehead";
        case 3: return "eyes";
        case 4: return "cheeks";
        case 5: return "nose";
        case 6: return "mouth";
        case 7: return "chin";
        default: return "?";
    }
}

// The interpolation paper: zones 2, 4 and 7 quadratic. With our numbering these are forehead, cheeks and chin,
// the zones where the adaptive degree policy accepts the quadratic most often (test_pipeline_plan
// prints the acceptance per zone).
bool zone_is_quadratic(unsigned zone) { return zone == 2 || zone == 4 || zone == 7; }

unsigned head_zone(const scene::rasterised& r, const scene::pixel_geometry& g) {
    if (!r.src || g.object >= r.src->objects.size()) return 0;
    const head_frame& f = frame_of(r.src->objects[g.object].geometry);
    if (f.size == 0) return 0;
    // geometry_at fills the position only when a perspective camera or a point light needs it:
    // an orthographic, directionally lit scene has no position here, so no zone.
    bool has_p = !r.src->cam.orthographic();
    for (const auto& l : r.src->lights) has_p = has_p || l.type == scene::light::kind::point;
    if (!has_p) return 0;
    const glm::dvec3 p{g.p.x.value(), g.p.y.value(), g.p.z.value()};
    // Head units: h = the height from the nose tip to the top of the head (about 0.15 world units
    // on the scan), centred on the tip across (x) and in height (y), depth from the tip backwards.
    const double h = f.b.hi.y - f.tip.y;
    if (!(h > 0.0)) return 0;
    const double x = (p.x - f.tip.x) / h, y = (p.y - f.tip.y) / h, d = (f.tip.z - p.z) / h;
    const double ax = std::abs(x);
    // Landmarks on the scan in these units (profiles of the mesh, and contour lines of x and y drawn
    // over the render): eyebrows y = 0.3 .. 0.38, the closed eyes' line 0.2, nose bridge 0.27, below
    // the nose -0.1, the lips -0.17 .. -0.38 (their line -0.3), chin -0.4 .. -0.65; the eyes' corners
    // |x| = 0.1 .. 0.33, the nose's wings 0.15, the mouth's corners 0.2.
    // The face is the front of the head: within 0.55 h of the tip in depth, 0.62 h either side.
    if (d > 0.55 || ax > 0.62 || y < -0.72) return 0;
    if (y > 0.44) return d < 0.42 ? 2 : 0;                       // forehead; the skull above it
    if (y > 0.28) return 1;                                      // brows (and the glabella between)
    if (y > 0.08) return ax < 0.09 ? 5 : (ax < 0.42 ? 3 : 4);    // nose bridge, eyes, temples
    if (y > -0.1) return ax < 0.2 ? 5 : 4;                       // nose, cheeks
    if (y > -0.38) return ax < 0.3 ? 6 : 4;                      // mouth, cheeks
    return ax < 0.42 ? 7 : 0;                                    // chin; the jaw beyond it
}

}  // namespace shading::pipeline
