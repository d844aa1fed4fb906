#include "scene/lyon.h"

#include <array>
#include <chrono>
#include <string>
#include <vector>

#include "reference/brdf_reference.h"
#include "scene/plane_steps.h"

namespace shading::scene {

namespace {
constexpr double full_scale = 255.0;  // 8-bit image units

// The stepped components' planes of triangle t: U_N (3), then U_P (3) where a position is needed,
// then Q where the camera is perspective, counted as scanline.h's set-up.
std::vector<glm::dvec3> lyon_setup(const rasterised& r, const triangle_setup& ts, bool need_p, bool perspective,
                                   op_counts* ops) {
    const mesh& m = r.src->objects[ts.object].geometry;
    const auto& tri = m.triangles[ts.triangle];
    std::vector<glm::dvec3> pl;
    for (int k = 0; k < 3; ++k) pl.push_back(plane_of(ts.plane, {m.normals[tri[0]][k], m.normals[tri[1]][k], m.normals[tri[2]][k]}, ops));
    if (need_p)
        for (int k = 0; k < 3; ++k)
            pl.push_back(plane_of(ts.plane, {m.positions[tri[0]][k], m.positions[tri[1]][k], m.positions[tri[2]][k]}, ops));
    if (perspective) {
        // Q = sum_i g_i: 2 adds per coefficient.
        glm::dvec3 q;
        for (int k = 0; k < 3; ++k)
            q[k] = (cnum(ts.plane[0][k], ops) + cnum(ts.plane[1][k], ops) + cnum(ts.plane[2][k], ops)).value();
        pl.push_back(q);
    }
    return pl;
}

unsigned log2_of(unsigned gamma) {
    unsigned k = 0;
    while ((1u << k) < gamma) ++k;
    return k;
}

// One pixel's colour from its geometry (every vector charging the shading counts).
rgb shade_lyon(const pixel_geometry& g, const material& m, const std::vector<light>& lights, unsigned gamma) {
    op_counts* ops = g.n.x.counts();
    auto c = [ops](double v) { return cnum(v, ops); };
    const cnum zero = c(0.0), one = c(1.0);
    const cnum scale = c(m.n / (2.0 * gamma));  // a material constant
    const unsigned k = log2_of(gamma);
    std::array<cnum, 3> acc{c(full_scale * m.ambient.x), c(full_scale * m.ambient.y), c(full_scale * m.ambient.z)};
    for (std::size_t li = 0; li < lights.size(); ++li) {
        const cnum ndl = dot(g.n, g.l[li]);
        if (!(ndl > zero)) continue;
        const cvec3 d = g.n - g.h[li];  // the chord: N.H = 1 - D.D/2 for unit vectors
        cnum s = max(one - scale * dot(d, d), zero);
        for (unsigned i = 0; i < k; ++i) s = s * s;
        const rgb kdi = full_scale * m.k_d * lights[li].intensity;  // frame constants
        const rgb ksi = full_scale * m.k_s * lights[li].intensity;
        for (int ch = 0; ch < 3; ++ch) acc[ch] = acc[ch] + c(kdi[ch]) * ndl + c(ksi[ch]) * s;
    }
    return {acc[0].value(), acc[1].value(), acc[2].value()};
}
}  // namespace

cvec3 lyon_normalize(const cvec3& n) {
    op_counts* ops = n.x.counts();
    auto c = [ops](double v) { return cnum(v, ops); };
    const cnum u = dot(n, n) - c(1.0);
    const cnum r = c(1.0) + u * (c(0.375) * u - c(0.5));
    return r * n;
}

shaded_image render_lyon(const rasterised& r, render_stats* stats, scheme_state* state, unsigned gamma) {
    if (gamma != 0 && (gamma & (gamma - 1)) != 0)
        throw scene_error("Lyon's gamma must be a power of two (reached by squarings), not " + std::to_string(gamma));
    const auto t0 = std::chrono::steady_clock::now();
    const world& s = *r.src;
    const bool perspective = !s.cam.orthographic();
    bool need_p = perspective;
    for (const auto& l : s.lights) need_p = need_p || l.type == light::kind::point;
    shaded_image img;
    img.width = r.width;
    img.height = r.height;
    img.value.assign(static_cast<std::size_t>(r.width) * r.height, rgb(0.0));
    img.covered.assign(img.value.size(), 0);
    render_stats st;
    std::vector<std::vector<glm::dvec3>> planes(r.setups.size());
    plane_steps steps;
    for (unsigned y = 0; y < r.height; ++y)
        for (const span& sp : line_spans(r, y))
            for (unsigned x = sp.x_begin; x < sp.x_end; ++x) {
                const int32_t t = r.tri[r.index(x, y)];
                const triangle_setup& ts = r.setups[static_cast<std::size_t>(t)];
                std::vector<glm::dvec3>& pl = planes[static_cast<std::size_t>(t)];
                if (pl.empty()) pl = lyon_setup(r, ts, need_p, perspective, &st.geometry);
                steps.at(t, pl, x, y, &st.geometry);
                auto c = [&st](double v) { return cnum(v, &st.geometry); };
                const cvec3 un{c(steps.value(0)), c(steps.value(1)), c(steps.value(2))};
                pixel_geometry g;
                g.object = ts.object;
                if (perspective) {
                    const cnum inv_q = c(1.0) / c(steps.value(6));
                    g.p = inv_q * cvec3{c(steps.value(3)), c(steps.value(4)), c(steps.value(5))};
                    g.n = lyon_normalize(inv_q * un);
                } else {
                    if (need_p) g.p = {c(steps.value(3)), c(steps.value(4)), c(steps.value(5))};
                    g.n = lyon_normalize(un);
                }
                add_view_and_lights(r, g, &st.geometry);
                auto rebind = [&st](cvec3& v) {
                    v = {cnum(v.x.value(), &st.shading), cnum(v.y.value(), &st.shading), cnum(v.z.value(), &st.shading)};
                };
                rebind(g.n);
                rebind(g.v);
                for (auto& v : g.l) rebind(v);
                for (auto& v : g.h) rebind(v);
                const material& m = s.objects[ts.object].mat;
                const unsigned gm = gamma != 0 ? gamma : ref::lyon_gamma(m.n);
                const std::size_t i = r.index(x, y);
                img.value[i] = glm::clamp(shade_lyon(g, m, s.lights, gm), rgb(0.0), rgb(full_scale));
                img.covered[i] = 1;
                ++st.pixels;
            }
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (stats) *stats = st;
    if (state) *state = scheme_state{static_cast<unsigned>(4 * (3 + (need_p ? 3 : 0) + (perspective ? 1 : 0))), {}};
    return img;
}

}  // namespace shading::scene
