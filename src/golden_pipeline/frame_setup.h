// What a render of a built-in scene or an OBJ file starts from, shared by render_cells and the studies that render
// one: the scene rasterised, its frame constants, the device, per-pixel shading through the device
// (the interpolation reference, per_pixel_frame) and the two baselines a pixel's long operations are
// held against, the scan-line Phong and the from-scratch Phong (scene/shade.h). As render_pipeline's
// --light and --n: a light direction replacing the scene's and an exponent.
#pragma once

#include <string>
#include <vector>

#include "golden_pipeline/pipeline.h"
#include "scene/raster.h"

namespace shading::pipeline {

// A built-in scene by name, or an OBJ file (a name ending in .obj, framed as scene::obj_scene frames
// it), size x size; light and n as frame_setup takes them. Throws what builtin_scene and obj_scene throw.
scene::world scene_of(const std::string& scene, const std::string& data_dir, unsigned size,
                      const std::vector<double>& light = {}, unsigned n = 0);

struct frame_setup {
    // Throws what scene_of, parse_device and frame_constants_of throw. walk_edges: the scan-line
    // Phong walks each triangle's values from line to line (render_pipeline's --walk-edges). light:
    // {azimuth, elevation} in degrees of one directional light instead of the scene's (empty: the
    // scene's); n: every material's exponent (0: the scene's).
    frame_setup(const std::string& scene, const std::string& data_dir, unsigned size, const std::string& device,
                bool walk_edges, const std::vector<double>& light = {}, unsigned n = 0);
    frame_setup(const frame_setup&) = delete;  // r points at w
    frame_setup& operator=(const frame_setup&) = delete;

    scene::world w;
    scene::rasterised r;
    frame_constants k;
    scene::device_config dev;
    frame per_pixel;
    std::size_t pixels = 0;  // covered
    double scanline = 0.0;   // the scan-line Phong's long operations a covered pixel (0: none covered)
    double phong = 0.0;      // the from-scratch Phong's (each pixel's geometry from scratch)
};

}  // namespace shading::pipeline
