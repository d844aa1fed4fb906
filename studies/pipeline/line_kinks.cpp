// A segment's triangle changes and the colour's slope jumps at shared edges (line_kinks.h).
#include "line_kinks.h"

#include <algorithm>

#include "scene/shade.h"

namespace shading::study {

rgb_levels colour_on(const scene::rasterised& r, int32_t t, double xs, double ys) {
    const scene::triangle_setup& ts = r.setups[static_cast<std::size_t>(t)];
    const scene::object& obj = r.src->objects[ts.object];
    const auto& tri = obj.geometry.triangles[ts.triangle];
    glm::dvec3 un(0.0), up(0.0);
    double q = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double g = ts.plane[i].x * xs + ts.plane[i].y * ys + ts.plane[i].z;
        q += g;
        un += g * obj.geometry.normals[tri[i]];
        up += g * obj.geometry.positions[tri[i]];
    }
    const glm::dvec3 n = glm::normalize(un), p = up / q;
    auto c = [](double v) { return scene::cnum(v, nullptr); };
    scene::pixel_geometry g;
    g.object = ts.object;
    g.n = {c(n.x), c(n.y), c(n.z)};
    g.p = {c(p.x), c(p.y), c(p.z)};
    scene::add_view_and_lights(r, g, nullptr);
    const scene::rgb v = scene::shade_phong(g, obj.mat, r.src->lights);
    return {v.x, v.y, v.z};
}

namespace {

// The corners two triangles share: -1 when they belong to different objects; common, the last
// shared vertex; own, the index in A of the last vertex B lacks.
struct corners {
    int shared = -1, own = -1;
    uint32_t common = 0;
};
corners shared_corners(const scene::rasterised& r, int32_t ta, int32_t tb) {
    const scene::triangle_setup& sa = r.setups[static_cast<std::size_t>(ta)];
    const scene::triangle_setup& sb = r.setups[static_cast<std::size_t>(tb)];
    corners c;
    if (sa.object != sb.object) return c;
    const auto& va = r.src->objects[sa.object].geometry.triangles[sa.triangle];
    const auto& vb = r.src->objects[sb.object].geometry.triangles[sb.triangle];
    c.shared = 0;
    for (int i = 0; i < 3; ++i) {
        const bool in_b = std::find(vb.begin(), vb.end(), va[i]) != vb.end();
        c.shared += in_b;
        if (in_b) c.common = va[i];
        if (!in_b) c.own = i;
    }
    return c;
}

}  // namespace

bool one_patch(const scene::rasterised& r, int32_t ta, int32_t tb) {
    return ta == tb || shared_corners(r, ta, tb).shared >= 1;
}

std::vector<double> normal_laplacian(const scene::mesh& m) {
    std::vector<std::vector<uint32_t>> neighbours(m.positions.size());
    for (const auto& t : m.triangles)
        for (uint32_t a : t)
            for (uint32_t b : t)
                if (a != b && std::find(neighbours[a].begin(), neighbours[a].end(), b) == neighbours[a].end())
                    neighbours[a].push_back(b);
    std::vector<double> out(m.positions.size(), 0.0);
    for (std::size_t v = 0; v < neighbours.size(); ++v) {
        if (neighbours[v].empty()) continue;
        glm::dvec3 sum(0.0);
        for (uint32_t u : neighbours[v]) sum += m.normals[u];
        out[v] = glm::length(m.normals[v] - sum / double(neighbours[v].size()));
    }
    return out;
}

segment_kinks kinks_of(const scene::rasterised& r, unsigned y, unsigned x0, unsigned x1) {
    segment_kinks out;
    out.vertex_pass.assign(x1 - x0 + 1, 0);
    out.passed.assign(x1 - x0 + 1, 0);
    const double ys = y + 0.5;
    for (unsigned x = x0 + 1; x <= x1; ++x) {
        const int32_t ta = r.tri[r.index(x - 1, y)], tb = r.tri[r.index(x, y)];
        if (ta == tb) continue;
        const corners c = shared_corners(r, ta, tb);
        if (c.shared == 1) {
            out.vertex_pass[x - x0] = 1;
            out.passed[x - x0] = c.common;
            ++out.vertices;
        }
        if (c.shared != 2) continue;
        ++out.edges;
        // The shared edge: g_own = a x + b y + c = 0 on this line.
        const glm::dvec3& pl = r.setups[static_cast<std::size_t>(ta)].plane[static_cast<std::size_t>(c.own)];
        if (pl.x == 0.0) continue;  // the edge runs along the line: no crossing point
        const double xs = std::clamp(-(pl.y * ys + pl.z) / pl.x, x - 0.5, x + 0.5);
        const double d = 1e-3;
        const rgb_levels a0 = colour_on(r, ta, xs - d, ys), a1 = colour_on(r, ta, xs + d, ys);
        const rgb_levels b0 = colour_on(r, tb, xs - d, ys), b1 = colour_on(r, tb, xs + d, ys);
        slope_jump j{xs - 0.5 - x0, {}};
        for (int ch = 0; ch < 3; ++ch) j.s[ch] = (b1[ch] - b0[ch] - a1[ch] + a0[ch]) / (2.0 * d);
        out.jumps.push_back(j);
    }
    return out;
}

}  // namespace shading::study
