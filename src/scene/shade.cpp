#include "scene/shade.h"

#include <algorithm>
#include <chrono>

#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "scene/scene.h"

namespace shading::scene {

namespace {
constexpr double full_scale = 255.0;  // 8-bit image units

rgb clamp_rgb(const rgb& v) { return glm::clamp(v, rgb(0.0), rgb(full_scale)); }

// The terms both references share; `specular(light index, N.H)` gives S * 255 * k_s * I per channel.
template <class Specular>
rgb shade_common(const pixel_geometry& g, const material& m, const std::vector<light>& lights, Specular specular) {
    op_counts* ops = g.n.x.counts();
    auto c = [ops](double v) { return cnum(v, ops); };
    const cnum zero = c(0.0);
    std::array<cnum, 3> acc{c(full_scale * m.ambient.x), c(full_scale * m.ambient.y), c(full_scale * m.ambient.z)};
    for (std::size_t li = 0; li < lights.size(); ++li) {
        const cnum ndl = dot(g.n, g.l[li]);
        if (!(ndl > zero)) continue;
        const cnum ndh = max(dot(g.n, g.h[li]), zero);
        const std::array<cnum, 3> spec = specular(li, ndh);
        const rgb kdi = full_scale * m.k_d * lights[li].intensity;  // frame constant
        for (int ch = 0; ch < 3; ++ch) acc[ch] = acc[ch] + c(kdi[ch]) * ndl + spec[ch];
    }
    return {acc[0].value(), acc[1].value(), acc[2].value()};
}

// The per-pixel references' geometry: geometry_at, from scratch at every pixel.
auto from_scratch(const rasterised& r) {
    return [&r](unsigned x, unsigned y, op_counts* ops) { return geometry_at(r, x, y, ops); };
}

// `geometry(x, y, ops)`: the pixel's geometry, charged to ops (geometry_at, or a span_stepper's).
template <class Geometry, class Shade>
shaded_image render(const rasterised& r, render_stats* stats, Geometry geometry, Shade shade) {
    const auto t0 = std::chrono::steady_clock::now();
    shaded_image img;
    img.width = r.width;
    img.height = r.height;
    img.value.assign(static_cast<std::size_t>(r.width) * r.height, rgb(0.0));
    img.covered.assign(img.value.size(), 0);
    render_stats st;
    for (unsigned y = 0; y < r.height; ++y)
        for (const span& sp : line_spans(r, y))
            for (unsigned x = sp.x_begin; x < sp.x_end; ++x) {
                const pixel_geometry g = geometry(x, y, &st.geometry);
                pixel_geometry gs = g;  // the same values, now charging the shading counts
                auto rebind = [&st](cvec3& v) {
                    v = {cnum(v.x.value(), &st.shading), cnum(v.y.value(), &st.shading), cnum(v.z.value(), &st.shading)};
                };
                rebind(gs.n);
                rebind(gs.v);
                for (auto& v : gs.l) rebind(v);
                for (auto& v : gs.h) rebind(v);
                const material& m = r.src->objects[g.object].mat;
                const std::size_t i = r.index(x, y);
                img.value[i] = clamp_rgb(shade(gs, m));
                img.covered[i] = 1;
                ++st.pixels;
            }
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (stats) *stats = st;
    return img;
}
}  // namespace

const char* device_name(specular_device d) {
    switch (d) {
        case specular_device::patent: return "patent";
        case specular_device::minimax: return "minimax";
        case specular_device::rom_matched: return "rom_matched";
        case specular_device::ua22802: return "ua22802";
        case specular_device::squared: return "squared";
        case specular_device::sqmul: return "sqmul";
    }
    return "?";
}

std::vector<std::string> device_names() { return {"patent", "minimax", "rom_matched", "ua22802", "squared", "sqmul"}; }

specular_device parse_device(const std::string& name) {
    for (auto d : {specular_device::patent, specular_device::minimax, specular_device::rom_matched,
                   specular_device::ua22802, specular_device::squared, specular_device::sqmul})
        if (name == device_name(d)) return d;
    throw scene_error("unknown specular device '" + name + "' (patent, minimax, rom_matched, ua22802, squared, sqmul)");
}

op_counts device_sample_ops(const device_config& dev, unsigned n) {
    op_counts ops;
    if (dev.device == specular_device::sqmul) {
        // MUL_P once per square and per multiplication, then MUL12..14: no MUL7, MUL10, ADD9, ADD11.
        const auto g = golden_sqmul(n, 0, {0, 0, 0}, dev.mode);
        ops.mul = g.squares + g.multiplies + 3;
        return ops;
    }
    ops.mul = 5;
    ops.add = 2;
    if (dev.device == specular_device::squared) ops.mul += golden_squared_a(n).k;  // MUL_SQ, k times
    return ops;
}

cnum pow_int(cnum x, unsigned n) {
    if (n == 0) return cnum(1.0, x.counts());
    unsigned top = 31;
    while (!(n >> top & 1u)) --top;
    cnum r = x;
    for (int b = static_cast<int>(top) - 1; b >= 0; --b) {
        r = r * r;
        if (n >> b & 1u) r = r * x;
    }
    return r;
}

rgb shade_phong(const pixel_geometry& g, const material& m, const std::vector<light>& lights) {
    op_counts* ops = g.n.x.counts();
    return shade_common(g, m, lights, [&](std::size_t li, cnum ndh) {
        const cnum s = pow_int(ndh, m.n);
        const rgb ksi = full_scale * m.k_s * lights[li].intensity;  // frame constant
        return std::array<cnum, 3>{cnum(ksi.x, ops) * s, cnum(ksi.y, ops) * s, cnum(ksi.z, ops) * s};
    });
}

rgb shade_specular(const pixel_geometry& g, const material& m, const std::vector<light>& lights,
                   const specular_fn& unit) {
    op_counts* ops = g.n.x.counts();
    return shade_common(g, m, lights, [&](std::size_t li, cnum ndh) {
        const rgb ks_i = m.k_s * lights[li].intensity;  // frame constants: the device's 8-bit codes
        const std::array<uint64_t, 3> ksi{ksi_code(ks_i.x), ksi_code(ks_i.y), ksi_code(ks_i.z)};
        const auto out = unit(m.n, cos_code(ndh.value()), ksi);
        return std::array<cnum, 3>{cnum(device_out_value(out[0]), ops), cnum(device_out_value(out[1]), ops),
                                   cnum(device_out_value(out[2]), ops)};
    });
}

rgb shade_device(const pixel_geometry& g, const material& m, const std::vector<light>& lights,
                 const device_config& dev) {
    op_counts* ops = g.n.x.counts();
    return shade_specular(g, m, lights, [&dev, ops](unsigned n, uint32_t code, const std::array<uint64_t, 3>& ksi) {
        if (ops) *ops += device_sample_ops(dev, n);  // the device's multipliers and adders
        return device_specular(dev, n, code, ksi);
    });
}

shaded_image render_phong(const rasterised& r, render_stats* stats) {
    return render(r, stats, from_scratch(r),
                  [&r](const pixel_geometry& g, const material& m) { return shade_phong(g, m, r.src->lights); });
}

shaded_image render_device(const rasterised& r, const device_config& dev, render_stats* stats) {
    return render(r, stats, from_scratch(r),
                  [&r, &dev](const pixel_geometry& g, const material& m) { return shade_device(g, m, r.src->lights, dev); });
}

shaded_image render_specular(const rasterised& r, const specular_fn& unit, render_stats* stats) {
    return render(r, stats, from_scratch(r), [&r, &unit](const pixel_geometry& g, const material& m) {
        return shade_specular(g, m, r.src->lights, unit);
    });
}

shaded_image render_phong_scanline(const rasterised& r, render_stats* stats, stepping_stats* steps,
                                   bool walk_edges) {
    span_stepper st(r, walk_edges);
    shaded_image img = render(
        r, stats, [&st](unsigned x, unsigned y, op_counts* o) { return st.at(x, y, o); },
        [&r](const pixel_geometry& g, const material& m) { return shade_phong(g, m, r.src->lights); });
    if (steps) *steps = st.stats();
    return img;
}

shaded_image render_device_scanline(const rasterised& r, const device_config& dev, render_stats* stats,
                                    bool walk_edges) {
    span_stepper st(r, walk_edges);
    return render(
        r, stats, [&st](unsigned x, unsigned y, op_counts* o) { return st.at(x, y, o); },
        [&r, &dev](const pixel_geometry& g, const material& m) { return shade_device(g, m, r.src->lights, dev); });
}

shaded_image render_specular_scanline(const rasterised& r, const specular_fn& unit, render_stats* stats,
                                      bool walk_edges) {
    span_stepper st(r, walk_edges);
    return render(
        r, stats, [&st](unsigned x, unsigned y, op_counts* o) { return st.at(x, y, o); },
        [&r, &unit](const pixel_geometry& g, const material& m) { return shade_specular(g, m, r.src->lights, unit); });
}

}  // namespace shading::scene
