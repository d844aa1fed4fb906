#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "formats/specular_formats.h"

namespace shading::scene {

std::vector<double> sphere_line_cos(double y, unsigned pixels, double light_x, double light_y,
                                    double light_z) {
    const glm::dvec3 l = glm::normalize(glm::dvec3(light_x, light_y, light_z));
    const glm::dvec3 v(0.0, 0.0, 1.0);
    const glm::dvec3 h = glm::normalize(l + v);
    std::vector<double> out;
    out.reserve(pixels);
    for (unsigned i = 0; i < pixels; ++i) {
        const double x = pixels > 1 ? -1.0 + 2.0 * i / (pixels - 1) : 0.0;
        const double z2 = 1.0 - x * x - y * y;
        if (z2 <= 0.0) {
            out.push_back(0.0);
            continue;
        }
        const glm::dvec3 n(x, y, std::sqrt(z2));  // unit normal of the unit sphere
        out.push_back(std::max(0.0, glm::dot(n, h)));
    }
    return out;
}

uint32_t cos_code(double c) {
    const double scaled = std::round(std::clamp(c, 0.0, 1.0) * static_cast<double>(spec::cos_one));
    return static_cast<uint32_t>(scaled);
}

uint32_t ksi_code(double ks_times_i) {
    const double full = static_cast<double>(spec::ksi_fmt.mask());  // 255
    return static_cast<uint32_t>(std::round(std::clamp(ks_times_i, 0.0, 1.0) * full));
}

double device_out_value(uint64_t out_code) {
    return static_cast<double>(out_code & spec::out_fmt.mask()) / static_cast<double>(1u << spec::out_fmt.frac);
}

}  // namespace shading::scene
