// Test scenes: the cos(gamma) values a rasteriser would feed the specular unit, computed with GLM.
#pragma once

#include <cstdint>
#include <vector>

namespace shading::scene {

// One raster line across a unit sphere seen along -z by a distant viewer, lit by a distant light
// (Blinn: cos gamma = N . H, H = normalize(L + V)). `y` is the line's height in [-1, 1], `pixels`
// samples span x in [-1, 1]; pixels off the sphere or facing away give cos = 0. Returns reals.
std::vector<double> sphere_line_cos(double y, unsigned pixels, double light_x, double light_y,
                                    double light_z);

// Round a real cos in [0, 1] to the Q1.15 input code (nearest; 1.0 -> 0x8000).
uint32_t cos_code(double c);

}  // namespace shading::scene
