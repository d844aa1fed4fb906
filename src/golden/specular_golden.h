// Golden model of the specular datapath (UA 60553 / UA 22802): its bit-exact function is shared
// arithmetic, in the floor (arith/specular_arith.h), because the fast models and the TLM wrappers
// call it too; this header keeps the golden layer's name for it (golden -> floor).
#pragma once

#include "arith/specular_arith.h"
