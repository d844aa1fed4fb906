// A flat square seen square-on by an orthographic camera, for the cells' tests: every pixel of the
// size x size frame covered, one segment a line, one patch throughout; lit along its normal, so every
// pixel's N.H and N.L, and its colour, are the same.
#pragma once

#include <deque>

#include "scene/scene.h"

namespace shading::study {

inline scene::rasterised flat_square(unsigned size) {
    scene::world w;
    w.name = "flat";
    w.cam.fov_y_deg = 0.0;  // orthographic
    w.cam.ortho_height = 2.0;
    w.cam.width = w.cam.height = size;
    scene::mesh m;
    m.positions = {{-1.5, -1.5, 0.0}, {1.5, -1.5, 0.0}, {1.5, 1.5, 0.0}, {-1.5, 1.5, 0.0}};
    m.normals = {{0.0, 0.0, 1.0}, {0.0, 0.0, 1.0}, {0.0, 0.0, 1.0}, {0.0, 0.0, 1.0}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    w.objects.push_back({"square", m, scene::material{}});
    w.lights.push_back({scene::light::kind::directional, {0.0, 0.0, 1.0}, {1.0, 1.0, 1.0}});
    static std::deque<scene::world> keep;  // the raster points at its world (a deque never moves it)
    keep.push_back(w);
    return scene::rasterise(keep.back());
}

}  // namespace shading::study
