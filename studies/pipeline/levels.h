// A colour in 8-bit levels, real-valued, three channels: what the studies' reconstructions and
// emulations work in (the hardware's rounding left out; pipeline::pixel_fmt holds the codes).
#pragma once

#include <array>

namespace shading::study {

using rgb_levels = std::array<double, 3>;

}  // namespace shading::study
