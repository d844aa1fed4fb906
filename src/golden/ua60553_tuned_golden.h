// Golden model of the tuned UA 60553 variant: its bit-exact function is shared arithmetic, in the
// floor (arith/ua60553_tuned_arith.h), because a_gen_tuned and the TLM wrapper call it too; this
// header keeps the golden layer's name for it.
#pragma once

#include "arith/ua60553_tuned_arith.h"
