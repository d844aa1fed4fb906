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

// The quantisation steps between the real-valued geometry and the specular devices, in one place
// (the device reference, shade.h, and the SystemC pipeline use these and nothing else):
// cos(gamma) = N.H, a real, -> in18's Q1.15 code: clamped to [0, 1], rounded to nearest, so
// 1.0 -> 0x8000 (spec::cos_fmt). A format conversion, not arithmetic: not counted as an operation.
uint32_t cos_code(double c);
// k_s * I per channel, a real in [0, 1] (255 = full scale of the 8-bit image), -> in19/21/23's
// 8-bit code (spec::ksi_fmt): clamped to [0, 1], times 255, rounded to nearest. A frame constant.
uint32_t ksi_code(double ks_times_i);
// The device's out25..27 code (Q9.8, spec::out_fmt) -> the specular term in 8-bit image units.
double device_out_value(uint64_t out_code);

}  // namespace shading::scene
