// Hand-countable scenes shared by the scene suites: one triangle on an 8x8 screen.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "scene/counted.h"
#include "scene/world.h"

namespace shading::scene::tiny {

// An 8x8 orthographic camera, one world unit per pixel: screen (sx, sy) = (X + 4, 4 - Y).
inline camera ortho8() {
    camera c;
    c.position = {0.0, 0.0, 10.0};
    c.fov_y_deg = 0.0;
    c.ortho_height = 8.0;
    c.width = c.height = 8;
    return c;
}

// The screen triangle (0, 0), (8, 0), (0, 8) at depth 10 with three different vertex normals, one
// directional light along +z. Pixel (x, y) is covered when its centre lies left of the hypotenuse
// x + y = 8 (half-open): x + 0.5 < 7.5 - y, so line y holds x = 0 .. 6 - y: 7 - y pixels on lines
// 0 .. 6, 7 + 6 + ... + 1 = 28 pixels in 7 runs. Line 3 is the 4-pixel span x = 0 .. 3.
// Orthographic, the screen-space barycentrics of pixel (x, y) are (1 - (x + y + 1)/8, (x + 0.5)/8,
// (y + 0.5)/8) for the vertices (-4, 4), (4, 4), (-4, -4).
inline world one_triangle(bool perspective) {
    world s;
    s.name = "one triangle";
    s.cam = ortho8();
    if (perspective) {
        s.cam.position = {0.0, 0.0, 5.0};
        s.cam.fov_y_deg = 60.0;
    }
    s.lights.push_back({});
    object o{"tri", mesh{}, material{}};
    o.geometry.positions = {{-4.0, 4.0, 0.0}, {4.0, 4.0, 0.0}, {-4.0, -4.0, 0.0}};
    o.geometry.normals = {glm::normalize(glm::dvec3{0.2, 0.1, 1.0}), glm::normalize(glm::dvec3{-0.3, 0.2, 1.0}),
                          glm::normalize(glm::dvec3{0.1, -0.4, 1.0})};
    o.geometry.triangles = {{0, 1, 2}};
    s.objects.push_back(o);
    return s;
}

// Every square root in these cases is a normalisation's, so each is one 1/sqrt pair with a division.
inline op_counts counts(uint64_t mul, uint64_t div, uint64_t sqrt, uint64_t add) {
    op_counts c;
    c.mul = mul;
    c.div = div;
    c.sqrt = sqrt;
    c.add = add;
    c.rsqrt = sqrt;
    return c;
}

}  // namespace shading::scene::tiny
