#include "scene/gouraud.h"

#include <chrono>
#include <optional>
#include <vector>

#include "scene/plane_steps.h"

namespace shading::scene {

namespace {
// The colour of vertex `v` of object `o`: its geometry charged to `geo`, its shading to `shade`.
rgb vertex_colour(const rasterised& r, uint32_t o, uint32_t v, const device_config& dev, op_counts* geo,
                  op_counts* shade) {
    const world& s = *r.src;
    const mesh& m = s.objects[o].geometry;
    auto cv = [](const glm::dvec3& a, op_counts* ops) { return cvec3{cnum(a.x, ops), cnum(a.y, ops), cnum(a.z, ops)}; };
    pixel_geometry g;
    g.object = o;
    g.p = cv(m.positions[v], geo);
    add_view_and_lights(r, g, geo);  // V, L, H at the vertex, as the per-pixel geometry derives them
    // The same values, now charging the shading counts (as shade.cpp's render splits them).
    auto rebind = [shade](cvec3& a) { a = {cnum(a.x.value(), shade), cnum(a.y.value(), shade), cnum(a.z.value(), shade)}; };
    g.n = cv(m.normals[v], shade);  // the mesh's unit vertex normal
    rebind(g.v);
    for (auto& a : g.l) rebind(a);
    for (auto& a : g.h) rebind(a);
    return shade_device(g, s.objects[o].mat, s.lights, dev);
}
}  // namespace

shaded_image render_gouraud(const rasterised& r, const device_config& dev, render_stats* stats, scheme_state* state) {
    const auto t0 = std::chrono::steady_clock::now();
    const world& s = *r.src;
    shaded_image img;
    img.width = r.width;
    img.height = r.height;
    img.value.assign(static_cast<std::size_t>(r.width) * r.height, rgb(0.0));
    img.covered.assign(img.value.size(), 0);
    render_stats st;
    // Each distinct vertex's colour, computed on the first triangle that needs it.
    std::vector<std::vector<std::optional<rgb>>> colours(s.objects.size());
    for (std::size_t o = 0; o < s.objects.size(); ++o) colours[o].resize(s.objects[o].geometry.positions.size());
    // Per triangle: the colour planes, channel by channel (set up on the triangle's first pixel).
    std::vector<std::vector<glm::dvec3>> planes(r.setups.size());
    plane_steps steps;
    for (unsigned y = 0; y < r.height; ++y)
        for (const span& sp : line_spans(r, y))
            for (unsigned x = sp.x_begin; x < sp.x_end; ++x) {
                const int32_t t = r.tri[r.index(x, y)];
                std::vector<glm::dvec3>& pl = planes[static_cast<std::size_t>(t)];
                if (pl.empty()) {
                    const triangle_setup& ts = r.setups[static_cast<std::size_t>(t)];
                    const auto& tri = s.objects[ts.object].geometry.triangles[ts.triangle];
                    std::array<rgb, 3> c;
                    for (int i = 0; i < 3; ++i) {
                        std::optional<rgb>& slot = colours[ts.object][tri[i]];
                        if (!slot) slot = vertex_colour(r, ts.object, tri[i], dev, &st.geometry, &st.shading);
                        c[i] = *slot;
                    }
                    const auto lambda = screen_barycentric_planes(r, ts);
                    for (int ch = 0; ch < 3; ++ch) pl.push_back(plane_of(lambda, {c[0][ch], c[1][ch], c[2][ch]}, &st.geometry));
                }
                steps.at(t, pl, x, y, &st.geometry);
                const std::size_t i = r.index(x, y);
                img.value[i] = glm::clamp(rgb(steps.value(0), steps.value(1), steps.value(2)), rgb(0.0), rgb(255.0));
                img.covered[i] = 1;
                ++st.pixels;
            }
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (stats) *stats = st;
    if (state) *state = scheme_state{12, {}};
    return img;
}

}  // namespace shading::scene
