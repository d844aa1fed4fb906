// What the studies that render a built-in scene start from (two_line_study, cell_study and their
// tests): the golden pipeline's frame set-up (golden_pipeline/frame_setup.h: the scene rasterised,
// its constants, the device, per-pixel shading through it and the Phong baselines), with the
// per-pixel frame in levels, the colours the real-valued emulations rebuild.
#pragma once

#include <string>
#include <vector>

#include "golden_pipeline/frame_setup.h"
#include "golden_pipeline/pipeline.h"
#include "levels.h"

namespace shading::study {

// A frame's pixels in 8-bit levels (pixel_fmt codes scaled), 0 where not covered.
std::vector<rgb_levels> levels_of(const pipeline::frame& f);

struct study_frame : pipeline::frame_setup {
    // As frame_setup's.
    study_frame(const std::string& scene, const std::string& data_dir, unsigned size, const std::string& device,
                bool walk_edges, const std::vector<double>& light = {}, unsigned n = 0)
        : frame_setup(scene, data_dir, size, device, walk_edges, light, n), colour(levels_of(per_pixel)) {}

    std::vector<rgb_levels> colour;  // per_pixel in levels
};

}  // namespace shading::study
