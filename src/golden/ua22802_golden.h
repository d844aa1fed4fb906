// Golden model of UA 22802 (the ROM prototype): its bit-exact function is shared arithmetic, in the
// floor (arith/ua22802_arith.h), because the pipeline's fast model reaches it through
// device_specular; this header keeps the golden layer's name for it.
#pragma once

#include "arith/ua22802_arith.h"
