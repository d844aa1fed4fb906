#include "scene/plane_steps.h"

namespace shading::scene {

std::array<glm::dvec3, 3> screen_barycentric_planes(const rasterised& r, const triangle_setup& ts) {
    const world& s = *r.src;
    const mesh& m = s.objects[ts.object].geometry;
    const auto& t = m.triangles[ts.triangle];
    std::array<glm::dvec3, 3> out;
    for (int i = 0; i < 3; ++i) {
        // glm::perspective's clip w is the view depth -z_eye = (eye - P) . view_dir (raster.cpp).
        const double w = s.cam.orthographic() ? 1.0 : glm::dot(r.eye - m.positions[t[i]], r.view_dir);
        out[i] = ts.plane[i] * w;
    }
    return out;
}

}  // namespace shading::scene
