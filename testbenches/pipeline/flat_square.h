// A flat square seen square-on by an orthographic camera, for the cells' tests (the golden cells', the
// cell unit's and the cells study's): every pixel of the size x size frame covered, one segment a
// line, one patch throughout; lit along its normal, so every pixel's N.H and N.L, and its colour, are
// the same. flat_strip: the same square narrowed to the middle column of an odd size (pixel centres
// 2 / size apart, the middle one at x = 0; the strip spans x = -+1 / size), so each line holds one
// pixel.
#pragma once

#include <deque>
#include <utility>

#include "golden_pipeline/pipeline.h"
#include "scene/scene.h"

namespace shading::tb {

inline scene::rasterised flat_rectangle(unsigned size, double half_width) {
    scene::world w;
    w.name = "flat";
    w.cam.fov_y_deg = 0.0;  // orthographic
    w.cam.ortho_height = 2.0;
    w.cam.width = w.cam.height = size;
    scene::mesh m;
    const double hw = half_width;
    m.positions = {{-hw, -1.5, 0.0}, {hw, -1.5, 0.0}, {hw, 1.5, 0.0}, {-hw, 1.5, 0.0}};
    m.normals = {{0.0, 0.0, 1.0}, {0.0, 0.0, 1.0}, {0.0, 0.0, 1.0}, {0.0, 0.0, 1.0}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    w.objects.push_back({"square", m, scene::material{}});
    w.lights.push_back({scene::light::kind::directional, {0.0, 0.0, 1.0}, {1.0, 1.0, 1.0}});
    static std::deque<scene::world> keep;  // the raster points at its world (a deque never moves it)
    keep.push_back(w);
    return scene::rasterise(keep.back());
}

inline scene::rasterised flat_square(unsigned size) { return flat_rectangle(size, 1.5); }
inline scene::rasterised flat_strip(unsigned size) { return flat_rectangle(size, 1.0 / double(size)); }

// One of them with its frame constants and the squared device, as the cells' tests shade it.
struct flat_frame {
    explicit flat_frame(scene::rasterised raster) : r(std::move(raster)), k(pipeline::frame_constants_of(*r.src)) {
        dev.device = scene::parse_device("squared");
    }
    scene::rasterised r;
    pipeline::frame_constants k;
    scene::device_config dev;
};

}  // namespace shading::tb
