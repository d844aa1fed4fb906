// Golden models of the interpolation paper's interpolation hardware. Their bit-exact functions
// (coefficient units, Horner unit, forward differences, the raster-line unit) are shared
// arithmetic, in the floor (arith/interp_arith.h), because the fast models and the line wrapper
// call them too; what only the checks and studies use is declared here.
#pragma once

#include <cstdint>
#include <vector>

#include "arith/interp_arith.h"

namespace shading::interp {

// The Horner unit's micro-steps (golden_horner_into) as a vector: RG after each, as coef_fmt bus bits.
std::vector<uint64_t> golden_horner_steps(const cubic_coefs& k, uint64_t t_code, bool degree2);

// Worst-case accumulated error after k steps of the recurrence when each set-up difference is
// floored (D1, D2 sums of 3 floored terms, D3 of 2): (3k + 3 C(k,2) + 2 C(k,3)) * 2^-frac,
// plus nothing when frac >= 16 + 3m (exact set-up). In units of the real value.
double fd_error_bound(unsigned k, unsigned m, int frac);

}  // namespace shading::interp
