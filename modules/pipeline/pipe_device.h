// The specular unit a shading pipeline drives, named by its generator of `a`: a_gen_linear,
// a_gen_tuned or a_gen_rom give UA 60553's Fig. 1 device (specular_device<AGen>: output 29 is
// strobe 17, one clock per sample); squared_device names itself (ours: a clocked squaring stage,
// output 29 rises k + 4 clocks after the strobe, so the sample controller waits for it), and so does
// sqmul_device (ours: one multiplier walking n's bits, floor(log2 n) + popcount(n) + 3 clocks).
#pragma once

#include "specular/specular_device.h"
#include "sqmul/sqmul_device.h"
#include "squared/squared_device.h"

namespace shading {

template <class Unit>
struct pipe_device {
    using type = specular_device<Unit>;
    static constexpr bool clocked = false;  // no clk pin; output 29 = strobe 17
};

template <>
struct pipe_device<squared_device> {
    using type = squared_device;
    static constexpr bool clocked = true;   // the squaring stage runs on the pipeline's clock
};

template <>
struct pipe_device<sqmul_device> {
    using type = sqmul_device;
    static constexpr bool clocked = true;   // the stage runs on the pipeline's clock
};

}  // namespace shading
