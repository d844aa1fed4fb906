// The lit guard's geometry (lit_planes.h).
#include "golden_pipeline/lit_planes.h"

#include <array>
#include <cstddef>

#include "scene/world.h"

namespace shading::pipeline {

bool lit_planes::any_lit(unsigned xa, unsigned xb, unsigned y, scene::op_counts& ops) {
    for (unsigned x = xa; x <= xb;) {
        const int32_t t = r_.tri[r_.index(x, y)];
        unsigned last = x;  // the run on triangle t: x..last
        while (last < xb && r_.tri[r_.index(last + 1, y)] == t) ++last;
        ops.cmp += last - x + 1;  // the rasteriser's triangle index compared along the run
        if (lit_somewhere(t, x, last, y, ops)) return true;
        x = last + 1;
    }
    return false;
}

bool lit_planes::lit_somewhere(int32_t t, unsigned xa, unsigned xb, unsigned y, scene::op_counts& ops) {
    if (lit_.empty()) lit_.resize(r_.setups.size());
    lit_state& st = lit_[std::size_t(t)];
    if (!st.known) {
        const scene::triangle_setup& ts = r_.setups[std::size_t(t)];
        const scene::world& w = *r_.src;
        const scene::mesh& mesh = w.objects[ts.object].geometry;
        const scene::light& l = w.lights.at(0);
        std::array<double, 3> nl{};
        for (std::size_t i = 0; i < 3; ++i) {
            const uint32_t vi = mesh.triangles[ts.triangle][i];
            const glm::dvec3 to_light =
                l.type == scene::light::kind::directional ? l.vector : l.vector - mesh.positions[vi];
            nl[i] = glm::dot(mesh.normals[vi], to_light);  // its sign: no normalising
        }
        ops.mul += 9;
        ops.add += 6;
        ops.cmp += 3;
        st.known = true;
        st.may_be_lit = nl[0] > 0.0 || nl[1] > 0.0 || nl[2] > 0.0;
        if (st.may_be_lit) {
            st.plane = nl[0] * ts.plane[0] + nl[1] * ts.plane[1] + nl[2] * ts.plane[2];
            ops.mul += 9;
            ops.add += 6;
        }
    }
    if (!st.may_be_lit) return false;
    auto lit_at = [&](unsigned x) {
        ops.mul += 2;
        ops.add += 2;
        ++ops.cmp;
        return st.plane.x * (x + 0.5) + st.plane.y * (y + 0.5) + st.plane.z > 0.0;
    };
    return lit_at(xa) || (xb != xa && lit_at(xb));
}

}  // namespace shading::pipeline
