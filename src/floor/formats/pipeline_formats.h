// Number formats of the shading pipeline's sample stage (the interpolation paper leaves them open): one table, read
// by the golden pipeline (src/golden_pipeline/pipeline.h) and the SystemC sample channel
// (modules/pipeline/sample_channel.h). Notation: Qi.f = i integer bits, f fraction bits.
#pragma once

#include "formats/fixed_point.h"
#include "formats/interp_formats.h"
#include "formats/specular_formats.h"

namespace shading::pipeline {

// k_d * I_l per channel: 255 k_d I as Q8.8 (rounded), a frame constant. Why 8 fraction bits: an
// 8-bit integer code, like the device's k_s*I pins (spec::ksi_fmt), rounds 255 k_d I by up to half a
// level, a bias over every lit pixel of the frame: on the head at 512 (k_d = 0.66, 0.50, 0.42:
// 168.3, 127.5, 107.1) it was the sample stage's whole error against the double reference (NMSE
// 4.3e-6 of 4.3e-6; 5.9e-7 once exact), more than half of what the hardware image may lose against
// Phong. Cost: three diffuse multipliers 16 x 16 instead of 8 x 16, three 16-bit registers.
inline constexpr qfmt kdi_fmt{16, false, 8};
// Diffuse multiplier: k_d*I (Q8.8) x N.L (Q1.15) -> Q9.23, the 15 low wires dropped (floor) -> Q9.8,
// in 8-bit image units like the device's out25..27 (spec::out_fmt).
inline constexpr qfmt diffuse_fmt = spec::out_fmt;
inline constexpr unsigned diffuse_drop = spec::cos_fmt.frac + kdi_fmt.frac - diffuse_fmt.frac;  // 15
// Ambient term per channel: 255 * ambient as an unsigned Q8.8 code (rounded), a frame constant.
inline constexpr qfmt ambient_fmt = interp::sample_fmt;
// ambient + diffuse: Q8.8 + Q9.8 -> Q10.8, one bit wider, never overflows.
inline constexpr qfmt ad_fmt{diffuse_fmt.width + 1, false, diffuse_fmt.frac};
// Colour sample: ambient + diffuse + specular, saturated to interp::sample_fmt (Q8.8 unsigned,
// largest code 0xFFFF = 255.996): the coefficient units' input format.
inline constexpr qfmt colour_fmt = interp::sample_fmt;
// Output stage: the evaluator's Q16.16 signed pixel clamped to [0, 0xFFFF] of Q8.8 unsigned (the
// 8 low fraction wires dropped, floor). The frame buffer stores these; PNGs round them to 8 bits.
inline constexpr qfmt pixel_fmt = interp::sample_fmt;

// Frame buffer (ours; modules/pipeline/frame_buffer.h, rtl/pipeline/frame_buffer.v): one word per
// pixel, the three channels' pixel_fmt codes side by side, {r, g, b} (r on the high wires).
inline constexpr unsigned frame_word_width = 3 * pixel_fmt.width;
// Its row pitch: the width rounded up to a power of two, so that the word of (x, y) is at {y, x}
// (wiring, no multiplier); the words of x in width..pitch-1 are never written.
constexpr unsigned frame_pitch(unsigned width) {
    unsigned p = 1;
    while (p < width) p <<= 1;
    return p;
}

}  // namespace shading::pipeline
