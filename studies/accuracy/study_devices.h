// The specular devices the studies measure, bit-accurate through their golden models: UA 22802's
// ROM prototype, UA 60553 with the patent's and the two tuned generators, the squared-quadratic
// device (ours) and the square-and-multiply baseline (ours, for comparison). Each gives its BRDF
// word in real units (ADD11 for the quadratic devices, the squaring register RG_SQ after the k-th
// square, the product P) and its out25..27 codes for rendering through the scene library.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scene/shade.h"

namespace shading::study {

struct study_device {
    std::string id, label;
    std::function<double(unsigned n, uint64_t cos_code)> brdf;  // saturate mode
    scene::specular_fn out;                                     // saturate mode
};

// In the order of the study's tables: rom, patent, minimax, rom_matched, squared, sqmul.
std::vector<study_device> study_devices();

}  // namespace shading::study
