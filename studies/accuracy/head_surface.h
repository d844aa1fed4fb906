// The distribution of cos = N.H over a rendered surface, for the accuracy study's image-weighted
// measure: the head scan (data/head/) rasterised once by the scene library, and the Q1.15 codes the
// specular device receives at its covered pixels, one per pixel and light with N.L > 0 (where the
// references shade a highlight; scene/shade.h), counted per code.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/image.h"
#include "scene/raster.h"
#include "scene/shade.h"
#include "scene/world.h"

namespace shading::study {

// The built-in head at size x size, rasterised. Not copyable: the raster points at the scene.
class head_surface {
public:
    head_surface(const std::string& data_dir, unsigned size);
    head_surface(const head_surface&) = delete;
    head_surface& operator=(const head_surface&) = delete;
    // Sets every object's exponent (the references read n from the material).
    void set_n(unsigned n);
    const scene::rasterised& raster() const { return raster_; }

private:
    scene::world world_;
    scene::rasterised raster_;
};

// The scene library's two references (scene::render_phong, scene::render_specular) replayed for
// any n from one pass over the geometry: per covered pixel it keeps what does not depend on the
// specular term (the ambient term, k_d I N.L per light, N.H) and redoes the shading's sums in the
// same order, so the images are the library's bit for bit (test_squared_variants checks), at a
// small fraction of the cost; a specular unit is evaluated once per distinct N.H code. For scans
// over every n. The raster (and its scene) must outlive it; the material's n is not read.
class shading_replay {
public:
    explicit shading_replay(const scene::rasterised& r);
    // The covered pixels' values, in raster order (row by row, left to right).
    std::vector<glm::dvec3> phong(unsigned n) const;
    std::vector<glm::dvec3> specular(unsigned n, const scene::specular_fn& unit) const;
    // As scene::compare_images of the two images (the same sums in the same order).
    static scene::image_diff compare(const std::vector<glm::dvec3>& test, const std::vector<glm::dvec3>& ref);
    // The values as a whole image (as the scene library's renders give it).
    scene::shaded_image image(const std::vector<glm::dvec3>& values) const;

private:
    struct lit {            // one light with N.L > 0 at one pixel
        glm::dvec3 diffuse;  // k_d I N.L, 8-bit units, per channel
        double ndh;          // max(N.H, 0)
        uint32_t code;       // its Q1.15 code
        uint32_t source;     // object * lights + light: which k_s I
    };
    struct pixel {
        std::size_t index;
        glm::dvec3 ambient;
        uint32_t first, count;  // into lits_
    };
    template <class Specular>
    std::vector<glm::dvec3> shade(Specular spec) const;
    const scene::rasterised* r_;
    std::vector<pixel> pixels_;
    std::vector<lit> lits_;
    std::vector<glm::dvec3> ksi_real_;                 // per source: 255 k_s I (Phong)
    std::vector<std::array<uint64_t, 3>> ksi_codes_;  // per source: the device's 8-bit codes
    std::vector<std::vector<uint32_t>> codes_;         // per source: the distinct codes met
};

struct cos_distribution {
    std::vector<uint32_t> codes;  // the distinct Q1.15 codes, ascending
    std::vector<double> weight;   // how many (pixel, light) pairs receive each
    std::size_t samples = 0;      // their sum
};
cos_distribution nh_distribution(const scene::rasterised& r);

// NMSE of a law over the distribution: sum w (approx(c) - c^n)^2 / sum w (c^n)^2, c = code / 2^15.
// `exact` (optional) holds c^n per distribution entry, so repeated calls for one n can share it.
double distribution_nmse(const cos_distribution& d, unsigned n, const std::function<double(uint64_t code)>& approx,
                         const std::vector<double>* exact = nullptr);
std::vector<double> distribution_exact(const cos_distribution& d, unsigned n);

}  // namespace shading::study
