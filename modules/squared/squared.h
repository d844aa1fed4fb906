// The squared-quadratic specular device (ours): the block-level model (squared_device.h, every
// block of its figure) and the fast pin-level model (squared_fast.h), with the same pins, timing
// and constructor (name, overflow mode, block delays), so a top switches by the type alone.
#pragma once

#include <type_traits>

#include "core/abstraction.h"
#include "squared/squared_device.h"
#include "squared/squared_fast.h"

namespace shading {

using device_squared = squared_device;
using device_squared_fast = squared_fast;

template <abstraction A>
using squared_model = std::conditional_t<A == abstraction::block, squared_device, squared_fast>;

}  // namespace shading
