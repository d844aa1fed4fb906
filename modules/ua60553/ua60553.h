// UA 60553 (Fig. 1): the specular datapath with the ROM-free generator of `a`,
// a = n * K31 + K32 (formula 10, a_gen_linear.h). Construct as
// device_ua60553(name, mode, generator constants = ua60553::patent, block delays).
#pragma once

#include "specular/specular_device.h"
#include "specular/specular_fast.h"
#include "ua60553/a_gen_linear.h"

namespace shading {

using device_ua60553 = specular_device<a_gen_linear>;
// The fast pin-level abstraction (specular/specular_fast.h): same pins, timing and constructor.
using device_ua60553_fast = specular_fast<a_gen_linear>;

}  // namespace shading
