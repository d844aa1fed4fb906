// The specular devices by name and their one bit-exact output function, plain C++: the scene's
// device reference (scene/shade.h), the golden pipeline and the pipeline's fast model
// (modules/pipeline/shading_pipeline_fast.h) all shade through device_specular, so it is in the
// floor (docs/layers.md). Declared in namespace scene, where every caller names them
// (scene::device_config); scene/shade.h adds their names for programs (device_name, parse_device).
#pragma once

#include <array>
#include <cstdint>

#include "formats/fixed_point.h"

namespace shading::scene {

enum class specular_device { patent, minimax, rom_matched, ua22802, squared, sqmul };

struct device_config {
    specular_device device = specular_device::patent;
    overflow_mode mode = overflow_mode::saturate;
};

// The device's out25..27 codes (Q9.8) for exponent n, the Q1.15 cos code and the 8-bit k_s*I codes:
// UA 60553 with the patent's generator or a tuned one (minimax, rom_matched), UA 22802, the
// squared-quadratic device or the square-and-multiply device, each through its golden function
// (specular_arith.h and beside it).
std::array<uint64_t, 3> device_specular(const device_config& dev, unsigned n, uint32_t cos_code,
                                        const std::array<uint64_t, 3>& ksi);

}  // namespace shading::scene
