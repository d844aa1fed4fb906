// What the studies that render a built-in scene start from (two_line_study, cell_study and their
// tests): the scene rasterised, its frame constants, the device, per-pixel shading through it in
// levels (the interpolation reference), and the scan-line and the from-scratch Phong's long
// operations a pixel. As
// render_pipeline's --light and --n: a light direction replacing the scene's and an exponent.
#pragma once

#include <string>
#include <vector>

#include "edge_split.h"
#include "golden_pipeline/pipeline.h"
#include "scene/raster.h"

namespace shading::study {

struct study_frame {
    // Throws what builtin_scene, parse_device and frame_constants_of throw. walk_edges: the scan-line
    // Phong walks each triangle's values from line to line (render_pipeline's --walk-edges). light:
    // {azimuth, elevation} in degrees of one directional light instead of the scene's (empty: the
    // scene's); n: every material's exponent (0: the scene's).
    study_frame(const std::string& scene, const std::string& data_dir, unsigned size, const std::string& device,
                bool walk_edges, const std::vector<double>& light = {}, unsigned n = 0);
    study_frame(const study_frame&) = delete;  // r points at w
    study_frame& operator=(const study_frame&) = delete;

    scene::world w;
    scene::rasterised r;
    pipeline::frame_constants k;
    scene::device_config dev;
    pipeline::frame per_pixel;
    std::vector<rgb_levels> colour;  // per_pixel in levels
    std::size_t pixels = 0;          // covered
    double scanline = 0.0;           // the scan-line Phong's long operations a covered pixel (0: none covered)
    double phong = 0.0;              // the from-scratch Phong's (each pixel's geometry from scratch)
};

}  // namespace shading::study
