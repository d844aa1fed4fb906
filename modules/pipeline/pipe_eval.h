// The shading pipeline's evaluator: the interpolation paper's Fig. 4 Horner unit, or our forward differences.
#pragma once

namespace shading {

enum class pipe_eval { horner, fd };

}  // namespace shading
