#include "scene/raster.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

namespace shading::scene {

namespace {
constexpr double pi = 3.14159265358979323846;
constexpr double inf = std::numeric_limits<double>::infinity();

struct screen_vertex {
    double x, y;  // pixel units, y down
    double q;     // 1 / w
    double d;     // view depth
};

bool finite(const screen_vertex& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.q) && std::isfinite(v.d);
}

// The pixels whose centres lie in [lo, hi): ceil(lo - 0.5) .. ceil(hi - 0.5) - 1, clipped to 0..n-1
// before the conversion to int. A vertex near the camera plane far to the side has screen
// coordinates no int holds (1e14 pixels from an OBJ vertex 1e12 units aside). False if none.
bool pixel_range(double lo, double hi, unsigned n, int& first, int& last) {
    const double f = std::max(0.0, std::ceil(lo - 0.5));
    const double l = std::min(double(n) - 1.0, std::ceil(hi - 0.5) - 1.0);
    if (!(f <= l)) return false;
    first = static_cast<int>(f);
    last = static_cast<int>(l);
    return true;
}
}  // namespace

std::size_t rasterised::covered_pixels() const {
    return static_cast<std::size_t>(std::count_if(tri.begin(), tri.end(), [](int32_t t) { return t >= 0; }));
}

rasterised transposed(const rasterised& r) {
    rasterised t;
    t.src = r.src;
    t.width = r.height;
    t.height = r.width;
    t.eye = r.eye;
    t.view_dir = r.view_dir;
    t.setups = r.setups;
    for (triangle_setup& ts : t.setups)
        for (glm::dvec3& g : ts.plane) std::swap(g.x, g.y);
    t.depth.resize(r.depth.size());
    t.tri.resize(r.tri.size());
    for (unsigned y = 0; y < r.height; ++y)
        for (unsigned x = 0; x < r.width; ++x) {
            t.depth[t.index(y, x)] = r.depth[r.index(x, y)];
            t.tri[t.index(y, x)] = r.tri[r.index(x, y)];
        }
    return t;
}

rasterised rasterise(const world& s) {
    validate(s);
    const camera& cam = s.cam;
    rasterised r;
    r.src = &s;
    r.width = cam.width;
    r.height = cam.height;
    r.depth.assign(static_cast<std::size_t>(r.width) * r.height, inf);
    r.tri.assign(r.depth.size(), -1);
    r.eye = cam.position;
    r.view_dir = glm::normalize(cam.position - cam.target);

    const glm::dmat4 view = glm::lookAt(cam.position, cam.target, cam.up);
    const double aspect = static_cast<double>(cam.width) / cam.height;
    const glm::dmat4 proj =
        cam.orthographic()
            ? glm::ortho(-0.5 * cam.ortho_height * aspect, 0.5 * cam.ortho_height * aspect, -0.5 * cam.ortho_height,
                         0.5 * cam.ortho_height, cam.z_near, cam.z_far)
            : glm::perspective(cam.fov_y_deg * pi / 180.0, aspect, cam.z_near, cam.z_far);
    const double W = cam.width, H = cam.height;

    for (uint32_t oi = 0; oi < s.objects.size(); ++oi) {
        const mesh& m = s.objects[oi].geometry;
        std::vector<screen_vertex> sv(m.positions.size());
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            const glm::dvec4 e = view * glm::dvec4(m.positions[i], 1.0);
            const glm::dvec4 c = proj * e;
            sv[i] = {(c.x / c.w + 1.0) * 0.5 * W, (1.0 - c.y / c.w) * 0.5 * H, 1.0 / c.w, -e.z};
        }
        for (uint32_t ti = 0; ti < m.triangles.size(); ++ti) {
            const auto& t = m.triangles[ti];
            const screen_vertex v[3] = {sv[t[0]], sv[t[1]], sv[t[2]]};
            if (v[0].d < cam.z_near || v[1].d < cam.z_near || v[2].d < cam.z_near) continue;
            if (v[0].d > cam.z_far && v[1].d > cam.z_far && v[2].d > cam.z_far) continue;
            // Not placed on the screen (a projection of a vertex beyond double's range): nothing to draw.
            if (!finite(v[0]) || !finite(v[1]) || !finite(v[2])) continue;
            // Screen-space barycentrics lambda_i = a x + b y + c (edge functions over twice the area).
            triangle_setup ts{oi, ti, {}};
            bool degenerate = false;
            for (int i = 0; i < 3; ++i) {
                const screen_vertex& j = v[(i + 1) % 3];
                const screen_vertex& k = v[(i + 2) % 3];
                const double ex = k.x - j.x, ey = k.y - j.y;
                const double den = ex * (v[i].y - j.y) - ey * (v[i].x - j.x);
                if (std::abs(den) < 1e-12) {
                    degenerate = true;
                    break;
                }
                const glm::dvec3 lam(-ey / den, ex / den, (ey * j.x - ex * j.y) / den);
                ts.plane[i] = lam * v[i].q;  // lambda_i / w_i
            }
            if (degenerate) continue;
            const double ymin = std::min({v[0].y, v[1].y, v[2].y});
            const double ymax = std::max({v[0].y, v[1].y, v[2].y});
            int y0 = 0, y1 = -1;
            if (!pixel_range(ymin, ymax, cam.height, y0, y1)) continue;
            const auto setup_index = static_cast<int32_t>(r.setups.size());
            bool used = false;
            for (int y = y0; y <= y1; ++y) {
                const double yc = y + 0.5;
                // The line's crossings with the edges whose half-open y range [top, bottom) holds yc.
                double xl = inf, xr = -inf;
                for (int e = 0; e < 3; ++e) {
                    // Walk each edge from its upper end, so the two triangles sharing an edge compute
                    // bit-identical crossings and the half-open rule leaves no gap and no overlap.
                    const screen_vertex* a = &v[e];
                    const screen_vertex* b = &v[(e + 1) % 3];
                    if (b->y < a->y || (b->y == a->y && b->x < a->x)) std::swap(a, b);
                    if (!(yc >= a->y && yc < b->y)) continue;
                    const double x = a->x + (yc - a->y) * (b->x - a->x) / (b->y - a->y);
                    xl = std::min(xl, x);
                    xr = std::max(xr, x);
                }
                int x0 = 0, x1 = -1;
                if (!(xl < xr) || !pixel_range(xl, xr, cam.width, x0, x1)) continue;
                for (int x = x0; x <= x1; ++x) {
                    const glm::dvec3 pc(x + 0.5, yc, 1.0);
                    double sq = 0.0, sdq = 0.0;
                    for (int i = 0; i < 3; ++i) {
                        const double g = glm::dot(ts.plane[i], pc);  // lambda_i q_i
                        sq += g;
                        sdq += g * v[i].d;
                    }
                    const double d = sdq / sq;  // perspective-correct view depth
                    const std::size_t p = r.index(static_cast<unsigned>(x), static_cast<unsigned>(y));
                    if (d < r.depth[p] && d >= cam.z_near) {
                        r.depth[p] = d;
                        r.tri[p] = setup_index;
                        used = true;
                    }
                }
            }
            if (used) r.setups.push_back(ts);
        }
    }
    return r;
}

std::vector<span> line_spans(const rasterised& r, unsigned y) {
    std::vector<span> out;
    unsigned x = 0;
    while (x < r.width) {
        while (x < r.width && !r.covered(x, y)) ++x;
        if (x == r.width) break;
        const unsigned b = x;
        while (x < r.width && r.covered(x, y)) ++x;
        out.push_back({b, x});
    }
    return out;
}

std::vector<discontinuity> line_discontinuities(const rasterised& r, unsigned y, double depth_threshold) {
    std::vector<discontinuity> out;
    for (unsigned x = 0; x <= r.width; ++x) {
        const bool prev = x > 0 && r.covered(x - 1, y);
        const bool cur = x < r.width && r.covered(x, y);
        unsigned k = 0;
        if (!prev && cur) k |= coverage_begin;
        if (prev && !cur) k |= coverage_end;
        if (prev && cur) {
            if (r.object_at(x - 1, y) != r.object_at(x, y)) k |= object_change;
            if (std::abs(r.depth[r.index(x, y)] - r.depth[r.index(x - 1, y)]) > depth_threshold) k |= depth_step;
        }
        if (k) out.push_back({x, k});
    }
    return out;
}

pixel_geometry geometry_at(const rasterised& r, unsigned x, unsigned y, op_counts* ops) {
    const triangle_setup& ts = r.setups[static_cast<std::size_t>(r.tri[r.index(x, y)])];
    const world& s = *r.src;
    const mesh& m = s.objects[ts.object].geometry;
    const auto& t = m.triangles[ts.triangle];
    auto c = [ops](double v) { return cnum(v, ops); };
    auto cv = [&c](const glm::dvec3& v) { return cvec3{c(v.x), c(v.y), c(v.z)}; };

    // Perspective-correct barycentrics: g_i = a_i x + b_i y + c_i, b_i = g_i / sum g.
    const cnum px = c(x + 0.5), py = c(y + 0.5);
    std::array<cnum, 3> g;
    for (int i = 0; i < 3; ++i) g[i] = c(ts.plane[i].x) * px + c(ts.plane[i].y) * py + c(ts.plane[i].z);
    const cnum inv = c(1.0) / (g[0] + g[1] + g[2]);
    const std::array<cnum, 3> b{g[0] * inv, g[1] * inv, g[2] * inv};

    pixel_geometry out;
    out.object = ts.object;
    out.n = normalize(b[0] * cv(m.normals[t[0]]) + b[1] * cv(m.normals[t[1]]) + b[2] * cv(m.normals[t[2]]));
    bool need_p = !s.cam.orthographic();
    for (const auto& l : s.lights) need_p = need_p || l.type == light::kind::point;
    if (need_p)
        out.p = b[0] * cv(m.positions[t[0]]) + b[1] * cv(m.positions[t[1]]) + b[2] * cv(m.positions[t[2]]);
    add_view_and_lights(r, out, ops);
    return out;
}

void add_view_and_lights(const rasterised& r, pixel_geometry& g, op_counts* ops) {
    auto c = [ops](double v) { return cnum(v, ops); };
    add_view_and_lights(r, g, ops, [&](const glm::dvec3& e) { return normalize(cvec3{c(e.x), c(e.y), c(e.z)} - g.p); });
}

void add_view_and_lights(const rasterised& r, pixel_geometry& g, op_counts* ops,
                         const std::function<cvec3(const glm::dvec3&)>& towards) {
    const world& s = *r.src;
    auto c = [ops](double v) { return cnum(v, ops); };
    auto cv = [&c](const glm::dvec3& v) { return cvec3{c(v.x), c(v.y), c(v.z)}; };
    // V: towards the eye (perspective), or the constant view direction (orthographic, no work).
    g.v = s.cam.orthographic() ? cv(r.view_dir) : towards(r.eye);
    g.l.clear();
    g.h.clear();
    for (const auto& l : s.lights) {
        // L: a directional light's unit vector is a frame constant (normalised here, uncounted).
        const cvec3 lv = l.type == light::kind::directional ? cv(glm::normalize(l.vector)) : towards(l.vector);
        g.l.push_back(lv);
        g.h.push_back(normalize(lv + g.v));
    }
}

}  // namespace shading::scene
