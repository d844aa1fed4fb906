// The tuned variant of UA 60553 (modules/tuned/README.md, "A better ROM-free a(n)"): the specular datapath with
// the tuned generator of `a` (a_gen_tuned.h: signed node 32, n < 2 forces a = 0). The patent's
// device, device_ua60553, is unchanged. Construct as
// device_ua60553_tuned(name, mode, generator = ua60553::minimax, block delays).
#pragma once

#include "specular/specular_device.h"
#include "specular/specular_fast.h"
#include "tuned/a_gen_tuned.h"

namespace shading {

using device_ua60553_tuned = specular_device<a_gen_tuned>;
// The fast pin-level abstraction (specular/specular_fast.h): same pins, timing and constructor.
using device_ua60553_tuned_fast = specular_fast<a_gen_tuned>;

}  // namespace shading
