// The interpolation paper's shading pipeline, the part after the geometry side, as bit-exact plain
// C++: the sample stage (a colour sample from the device's specular term, the diffuse multiplier
// and the adders) and one interval through the coefficient unit and an evaluator to clamped pixels.
// The golden pipeline (src/golden_pipeline/pipeline.h: golden_interval, golden_frame) and the pipeline's
// fast model (modules/pipeline/shading_pipeline_fast.h) both compute intervals with it, so it is in
// the floor (docs/layers.md), apart from the rasteriser and the geometry side's plan.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "arith/device_specular.h"
#include "formats/interp_formats.h"
#include "formats/pipeline_formats.h"

namespace shading::pipeline {

using rgb_codes = std::array<uint64_t, 3>;

// ---- Sample stage ----
// Per-frame registers, loaded once per frame (UA 60553, Fig. 3: RG1 by strobe 15, RG3-5 by 20, 22, 24).
struct frame_constants {
    unsigned n = 32;           // the device's in16 (1..1000)
    rgb_codes ksi{};           // k_s * I_l, 8-bit codes (scene::ksi_code)
    rgb_codes kdi{};           // 255 k_d I_l, Q8.8 codes (kdi_code)
    rgb_codes ambient{};       // 255 * ambient, Q8.8 codes
};

// What the geometry side delivers per sample point: in18's Q1.15 codes (scene::cos_code) of N.H and
// N.L; both 0 where N.L <= 0 (no highlight where the light does not reach, as the references gate it).
struct sample_geometry {
    uint32_t cos_nh = 0, cos_nl = 0;
    bool operator==(const sample_geometry& o) const { return cos_nh == o.cos_nh && cos_nl == o.cos_nl; }
};

// One colour sample (colour_fmt codes per channel):
//   sat(ambient + floor(kdi * cos_nl >> 7) + device_specular(n, cos_nh, ksi)).
rgb_codes golden_sample(const scene::device_config& dev, const frame_constants& k, sample_geometry g);

// ---- One interval ----
enum class evaluator { horner, fd };  // the paper's Fig. 4 Horner unit, or our forward differences
const char* evaluator_name(evaluator e);  // "horner", "fd"

// An interval of a raster line as it enters the hardware: pixels x0 .. x0 + len - 1 of line y, pixel
// k at t = k / 2^m. Cubic: s[0..3] at the sample set's points (case 1: t = 0, 1/4, 1/2, 1; case 2:
// 0, 1/2, 3/4, 1). Quadratic (deg2): s[0..2] at t = 0, 1/2, 1, s[3] = s[2]. The sample at t = 1 is
// pixel x0 + 2^m, the next interval's first pixel (shared, not recomputed by the geometry side).
// An exact pixel is m = 0, len = 1, deg2 = false, all four samples equal: the cubic through four
// equal samples is that constant (A = B = C = 0, D = I1), so the hardware needs no special case.
struct interval_job {
    unsigned y = 0, x0 = 0;
    unsigned len = 1;        // 1 .. 2^m (shorter only when the plan says so)
    unsigned m = 0;          // 0 (exact pixel) or interp::m_min .. interp::m_max
    bool deg2 = false;
    std::array<sample_geometry, 4> s{};
    uint8_t zone = 0;        // the zone of the interval's first pixel (head_zone), for maps and reports
};

// The intervals the hardware can take: m = 0 (an exact pixel: len 1, cubic) or interp::m_min ..
// interp::m_max with len 1..2^m. interval_problem says why not ("" for a valid job), naming the
// job's line, x, m, len and degree.
bool interval_valid(const interval_job& job);
std::string interval_problem(const interval_job& job);

// Every pixel of one valid interval, pixel_fmt codes per channel: golden_sample at each sample point
// -> golden_cubic_coefs (sample set, /3 mode; whole-sum grouping) or golden_quad_coefs -> per pixel
// golden_horner (t code k << (8 - m)) or golden_fd (fixed m; quadratic as A = 0, B = a, C = b, D = c)
// -> golden_output_clamp. An invalid job gives no pixels (golden_interval, pipeline.h, throws instead;
// the fast model drops it with a warning before it gets here, as the sample controller does).
rgb_codes::value_type golden_output_clamp(uint64_t coef_bits);
std::vector<rgb_codes> interval_pixels(const interval_job& job, const frame_constants& k,
                                       const scene::device_config& dev, evaluator e, interp::sample_set set,
                                       interp::div3_mode div);
// The quadratic through three colour samples (colour_fmt codes) at t = 0, 1/2, 1 of an interval of
// 2^m pixels, pixels 0 .. len - 1: interval_pixels' quadratic after the sample stage (golden_quad_coefs,
// the evaluator, golden_output_clamp). The cells' biquadratic (cells.h) runs it down the lattice
// columns and then along each row. m outside 1 .. interp::m_max or len outside 1 .. 2^m: no pixels.
std::vector<rgb_codes> quadratic_pixels(const std::array<rgb_codes, 3>& smp, unsigned m, unsigned len, evaluator e);

}  // namespace shading::pipeline
