// The shading components interpolated apart, as the interpolation paper does (docs/deviations.md,
// row 22), against the model's one polynomial per channel for their sum. Each component gets its own
// plan (the same adaptive policy, its own tolerance and longest interval): ambient + diffuse, and
// specular. The pixel is their sum, saturated to the pixel format. What that costs is bounded from
// below from the two plans' own counts (components.cpp says how), so a ratio against the scan-line
// Phong computed from it is the most the apart design could reach.
#pragma once

#include <cstddef>
#include <vector>

#include "golden_pipeline/pipeline.h"

namespace shading::study {

// The frame constants of one component: ambient + diffuse (k_s I = 0), or specular alone
// (k_d I = 0, ambient = 0). The sample stage's sum of the two, saturated, is the sum's sample.
pipeline::frame_constants diffuse_part(const pipeline::frame_constants& k);
pipeline::frame_constants specular_part(const pipeline::frame_constants& k);

// Two frames of one rasterised scene added pixel by pixel, saturated to pixel_fmt (an adder and a
// clamp per channel after the two evaluators).
pipeline::frame add_saturated(const pipeline::frame& a, const pipeline::frame& b);

// Pixels that are some job's sample point (pipeline.h's sets; an exact pixel is its own sample), as
// a flag per pixel index of the frame.
std::vector<uint8_t> sample_pixels(const pipeline::plan& p, interp::sample_set set);

// A lower bound on the pixels whose geometry the diffuse plan computed and the specular plan did not:
// |D \ E| >= |D| - |S_d n S_e| - |X_d| - |X_e|, with D, E the plans' geometry points, S their sample
// pixels and X = D \ S (check points, candidates tried and not sent), |X| = geometry_points - |S|.
std::size_t diffuse_only_points_bound(const pipeline::plan& d, const std::vector<uint8_t>& sd,
                                      const pipeline::plan& e, const std::vector<uint8_t>& se);

// The long operations the apart design needs at least, for the two plans (their configurations and
// the device as counted by pipeline::hardware_ops):
//  - the specular plan as counted, less the diffuse multipliers (3 a colour) it does not need;
//  - each diffuse-only geometry point at least N normalised and N.L: diffuse_point_long_min;
//  - the diffuse plan's colours (samples and check points): the diffuse multipliers only;
//  - the diffuse plan's interpolation as counted.
inline constexpr unsigned diffuse_point_long_min = 8 + 3;  // normalize(N): 3 mul, sqrt, div, 3 mul; N.L: 3 mul
inline constexpr unsigned diffuse_colour_long = 3;         // k_d I x N.L per channel
struct apart_cost {
    double specular = 0.0;           // long operations of the specular plan (without diffuse multipliers)
    double diffuse = 0.0;            // the diffuse plan's lower bound
    std::size_t diffuse_only = 0;    // diffuse_only_points_bound
    double total() const { return specular + diffuse; }
};
apart_cost apart_cost_bound(const pipeline::plan& d, const pipeline::plan_config& cd, const pipeline::plan& e,
                            const pipeline::plan_config& ce, const scene::device_config& dev, unsigned n);

}  // namespace shading::study
