// Golden model of the squared-quadratic specular device (ours): its bit-exact function is shared
// arithmetic, in the floor (arith/squared_arith.h), because the device's fast model, its TLM wrapper
// and the pipeline's fast model call it too; this header keeps the golden layer's name for it.
#pragma once

#include "arith/squared_arith.h"
