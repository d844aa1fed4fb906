// The square-and-multiply specular device (ours): the block-level model (sqmul_device.h, every block
// of its RTL twin) and the fast pin-level model (sqmul_fast.h), with the same pins, timing and
// constructor (name, overflow mode, block delays), so a top switches by the type alone.
#pragma once

#include <type_traits>

#include "core/abstraction.h"
#include "sqmul/sqmul_device.h"
#include "sqmul/sqmul_fast.h"

namespace shading {

using device_sqmul = sqmul_device;
using device_sqmul_fast = sqmul_fast;

template <abstraction A>
using sqmul_model = std::conditional_t<A == abstraction::block, sqmul_device, sqmul_fast>;

}  // namespace shading
