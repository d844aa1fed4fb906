#include "head_surface.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "formats/specular_formats.h"
#include "scene/scene.h"

namespace shading::study {

head_surface::head_surface(const std::string& data_dir, unsigned size)
    : world_(scene::builtin_scene("head", data_dir, size, size)), raster_(scene::rasterise(world_)) {}

void head_surface::set_n(unsigned n) {
    for (auto& o : world_.objects) o.mat.n = n;
}

shading_replay::shading_replay(const scene::rasterised& r) : r_(&r) {
    constexpr double full_scale = 255.0;  // as scene/shade.cpp
    const auto& lights = r.src->lights;
    for (const auto& o : r.src->objects)
        for (const auto& l : lights) {
            ksi_real_.push_back(full_scale * o.mat.k_s * l.intensity);
            const glm::dvec3 ks_i = o.mat.k_s * l.intensity;
            ksi_codes_.push_back({scene::ksi_code(ks_i.x), scene::ksi_code(ks_i.y), scene::ksi_code(ks_i.z)});
        }
    for (unsigned y = 0; y < r.height; ++y)
        for (const scene::span& sp : scene::line_spans(r, y))
            for (unsigned x = sp.x_begin; x < sp.x_end; ++x) {
                const scene::pixel_geometry g = scene::geometry_at(r, x, y, nullptr);
                const scene::material& m = r.src->objects[g.object].mat;
                pixel p{r.index(x, y), full_scale * m.ambient, static_cast<uint32_t>(lits_.size()), 0};
                for (std::size_t li = 0; li < lights.size(); ++li) {
                    const double ndl = dot(g.n, g.l[li]).value();
                    if (!(ndl > 0.0)) continue;
                    const double nh = dot(g.n, g.h[li]).value();
                    const double ndh = nh > 0.0 ? nh : 0.0;  // as cnum's max(N.H, 0)
                    lits_.push_back({full_scale * m.k_d * lights[li].intensity * ndl, ndh, scene::cos_code(ndh),
                                     static_cast<uint32_t>(g.object * lights.size() + li)});
                    ++p.count;
                }
                pixels_.push_back(p);
            }
    codes_.resize(ksi_codes_.size());
    for (const lit& l : lits_) codes_[l.source].push_back(l.code);
    for (auto& c : codes_) {
        std::sort(c.begin(), c.end());
        c.erase(std::unique(c.begin(), c.end()), c.end());
    }
}

template <class Specular>
std::vector<glm::dvec3> shading_replay::shade(Specular spec) const {
    std::vector<glm::dvec3> v(pixels_.size());
    for (std::size_t k = 0; k < pixels_.size(); ++k) {
        const pixel& p = pixels_[k];
        glm::dvec3 acc = p.ambient;
        for (uint32_t i = p.first; i < p.first + p.count; ++i) acc = acc + lits_[i].diffuse + spec(lits_[i]);
        v[k] = glm::clamp(acc, scene::rgb(0.0), scene::rgb(255.0));
    }
    return v;
}

std::vector<glm::dvec3> shading_replay::phong(unsigned n) const {
    return shade([this, n](const lit& l) {
        const double s = scene::pow_int(scene::cnum(l.ndh, nullptr), n).value();
        return ksi_real_[l.source] * s;
    });
}

std::vector<glm::dvec3> shading_replay::specular(unsigned n, const scene::specular_fn& unit) const {
    // The unit once per (source, code) met.
    std::vector<std::vector<glm::dvec3>> table(ksi_codes_.size());
    for (std::size_t s = 0; s < codes_.size(); ++s) {
        if (codes_[s].empty()) continue;
        table[s].resize(spec::cos_one + 1);
        for (uint32_t c : codes_[s]) {
            const auto out = unit(n, c, ksi_codes_[s]);
            table[s][c] = {scene::device_out_value(out[0]), scene::device_out_value(out[1]), scene::device_out_value(out[2])};
        }
    }
    return shade([&table](const lit& l) { return table[l.source][l.code]; });
}

scene::image_diff shading_replay::compare(const std::vector<glm::dvec3>& test, const std::vector<glm::dvec3>& ref) {
    double num = 0.0, den = 0.0;
    scene::image_diff d;
    for (std::size_t i = 0; i < ref.size() && i < test.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double e = test[i][c] - ref[i][c];
            num += e * e;
            den += ref[i][c] * ref[i][c];
            d.max_abs = std::max(d.max_abs, std::abs(e));
        }
    d.nmse = den > 0.0 ? num / den : 0.0;
    return d;
}

scene::shaded_image shading_replay::image(const std::vector<glm::dvec3>& values) const {
    scene::shaded_image img;
    img.width = r_->width;
    img.height = r_->height;
    img.value.assign(static_cast<std::size_t>(img.width) * img.height, scene::rgb(0.0));
    img.covered.assign(img.value.size(), 0);
    for (std::size_t k = 0; k < pixels_.size() && k < values.size(); ++k) {
        img.value[pixels_[k].index] = values[k];
        img.covered[pixels_[k].index] = 1;
    }
    return img;
}

cos_distribution nh_distribution(const scene::rasterised& r) {
    std::vector<double> count(spec::cos_one + 1, 0.0);
    std::size_t samples = 0;
    for (unsigned y = 0; y < r.height; ++y)
        for (const scene::span& sp : scene::line_spans(r, y))
            for (unsigned x = sp.x_begin; x < sp.x_end; ++x) {
                const scene::pixel_geometry g = scene::geometry_at(r, x, y, nullptr);
                for (std::size_t li = 0; li < g.l.size(); ++li) {
                    if (!(dot(g.n, g.l[li]).value() > 0.0)) continue;
                    count[scene::cos_code(std::max(dot(g.n, g.h[li]).value(), 0.0))] += 1.0;
                    ++samples;
                }
            }
    cos_distribution d;
    for (uint32_t c = 0; c <= spec::cos_one; ++c)
        if (count[c] > 0.0) {
            d.codes.push_back(c);
            d.weight.push_back(count[c]);
        }
    d.samples = samples;
    return d;
}

std::vector<double> distribution_exact(const cos_distribution& d, unsigned n) {
    std::vector<double> e(d.codes.size());
    for (std::size_t i = 0; i < e.size(); ++i) e[i] = std::pow(static_cast<double>(d.codes[i]) / spec::cos_one, n);
    return e;
}

double distribution_nmse(const cos_distribution& d, unsigned n, const std::function<double(uint64_t code)>& approx,
                         const std::vector<double>* exact) {
    std::vector<double> own;
    if (exact == nullptr) {
        own = distribution_exact(d, n);
        exact = &own;
    }
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < d.codes.size(); ++i) {
        const double p = (*exact)[i], e = approx(d.codes[i]) - p;
        num += d.weight[i] * e * e;
        den += d.weight[i] * p * p;
    }
    return den > 0.0 ? num / den : 0.0;
}

}  // namespace shading::study
