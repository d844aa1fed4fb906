// The shading pipeline's evaluator: seed 004's Fig. 4 Horner unit, or our forward differences.
#pragma once

namespace shading {

enum class pipe_eval { horner, fd };

}  // namespace shading
