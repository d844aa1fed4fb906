// The lit guard's geometry (plan_config::lit_guard, used by plan.cpp): whether a pixel of a run is lit,
// known without shading it. Inside a triangle N = sum g_i N_i / |sum g_i N_i| with every g_i > 0 (the
// rasteriser's planes of lambda_i / w_i), so a pixel is lit (N.L > 0) exactly where the triangle's lit
// plane s = sum_i (N_i.L) g_i is > 0, and s is linear along a line: a run of pixels on one triangle is
// lit somewhere iff s > 0 at one of its ends. Exact for a directional light; with a point light the
// vertices' own L stand in (an approximation). Internal to src/golden_pipeline: the contract is pipeline.h.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/counted.h"
#include "scene/raster.h"

namespace shading::pipeline {

class lit_planes {
public:
    explicit lit_planes(const scene::rasterised& r) : r_(r) {}
    // Whether any pixel xa..xb (inclusive) of line y, all covered, is lit: run by run over the
    // rasteriser's triangles (a compare a pixel to find the runs), each run by lit_somewhere. Charged to ops.
    bool any_lit(unsigned xa, unsigned xb, unsigned y, scene::op_counts& ops);
    // Whether a pixel xa..xb (inclusive) of line y, all on triangle setup t, is lit. Charged to ops: per
    // triangle, once, the three vertex dot products and their signs (9 mul, 6 add, 3 cmp), and if a
    // vertex normal faces the light the plane (9 mul, 6 add; a triangle whose vertex normals all face
    // away is lit nowhere); per run end a x + b y + c and its sign (2 mul, 2 add, 1 cmp).
    bool lit_somewhere(int32_t t, unsigned xa, unsigned xb, unsigned y, scene::op_counts& ops);

private:
    struct lit_state {
        bool known = false, may_be_lit = false;
        glm::dvec3 plane{0.0};  // a, b, c of the lit plane s = a x + b y + c (pixel centres)
    };
    const scene::rasterised& r_;
    std::vector<lit_state> lit_;  // per triangle setup, filled as they are consulted
};

}  // namespace shading::pipeline
