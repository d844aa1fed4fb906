// Screen-space planes a x + b y + c stepped along a raster line, counted as scanline.h's span_stepper
// counts its own: a run start evaluates every plane at the pixel centre (2 mul, 2 add each), a step
// d pixels right adds d a (a shift for d = 2^k, a shift-and-add network otherwise: popcount(d) adds
// each). The interpolating schemes (Gouraud's colours, Lyon's normals) step their values with it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/counted.h"
#include "scene/raster.h"

namespace shading::scene {

// A triangle's screen-linear barycentric planes lambda_i = w_i g_i (raster.h: g_i = lambda_i / w_i),
// w_i the vertex's clip w: its view depth along the camera's axis (perspective) or 1 (orthographic).
// The rasteriser's own edge functions, shared by every path: not counted.
std::array<glm::dvec3, 3> screen_barycentric_planes(const rasterised& r, const triangle_setup& ts);

// The plane of sum_i weights_i[k] * value_i per coefficient k (3 mul, 2 add each, charged to ops):
// the set-up of one interpolated quantity from its three vertex values.
inline glm::dvec3 plane_of(const std::array<glm::dvec3, 3>& weights, const std::array<double, 3>& value,
                           op_counts* ops) {
    auto c = [ops](double v) { return cnum(v, ops); };
    glm::dvec3 out;
    for (int k = 0; k < 3; ++k)
        out[k] = (c(weights[0][k]) * c(value[0]) + c(weights[1][k]) * c(value[1]) + c(weights[2][k]) * c(value[2]))
                     .value();
    return out;
}

// Stepped values of one triangle along one raster line, as many as the planes given to at().
class plane_steps {
public:
    // The values at pixel (x, y) of triangle `tri` with planes `pl` (a, b, c): a step from the pixel
    // before when that is on the same triangle, the same line and to the left; a run start otherwise.
    // Returns true for a step.
    bool at(int32_t tri, const std::vector<glm::dvec3>& pl, unsigned x, unsigned y, op_counts* ops) {
        auto c = [ops](double v) { return cnum(v, ops); };
        const bool step = tri == tri_ && y == y_ && x > x_ && v_.size() == pl.size();
        if (step) {
            const unsigned d = x - x_;
            unsigned ones = 0;
            for (unsigned b = d; b; b >>= 1) ones += b & 1u;
            for (std::size_t k = 0; k < pl.size(); ++k) {
                if (ops) ops->add += ones - 1;
                v_[k] = (c(v_[k]) + c(d * pl[k].x)).value();
            }
        } else {
            const cnum px = c(x + 0.5), py = c(y + 0.5);
            v_.resize(pl.size());
            for (std::size_t k = 0; k < pl.size(); ++k) v_[k] = (c(pl[k].x) * px + c(pl[k].y) * py + c(pl[k].z)).value();
        }
        tri_ = tri;
        x_ = x;
        y_ = y;
        return step;
    }
    double value(std::size_t k) const { return v_[k]; }

private:
    std::vector<double> v_;
    int32_t tri_ = -1;
    unsigned x_ = 0, y_ = 0;
};

}  // namespace shading::scene
