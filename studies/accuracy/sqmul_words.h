// The square-and-multiply designs (ours, for comparison; formats/sqmul_formats.h) at the word-length
// study's P words: left to right with one multiplier (golden_sqmul) and right to left with two
// (golden_sqmul_r2l), each at Q1.15 .. Q1.20 (the devices' word is Q1.18). Their words through the
// golden models, their clocks per sample (from the golden models' step counts, and by the
// hand-derived formula), and the relative-error measure over the codes where cos^n is at least a
// threshold (0.56: the quadratic-BRDF paper's; 0.1: deeper into the highlight's tail). Saturate mode.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace shading::study {

enum class sqmul_walk { left_to_right, right_to_left };

struct sqmul_design {
    std::string id, label;
    sqmul_walk walk;
    unsigned p_frac;
};

// Both walks at every word of the study, left to right first, shortest word first.
std::vector<sqmul_design> sqmul_designs();
const std::vector<unsigned>& sqmul_study_fracs();  // 15..20

uint64_t sqmul_design_word(const sqmul_design& d, unsigned n, uint64_t cos_code);  // P, Q1.p_frac
double sqmul_design_value(const sqmul_design& d, unsigned n, uint64_t cos_code);
std::array<uint64_t, 3> sqmul_design_out(const sqmul_design& d, unsigned n, uint64_t cos_code,
                                         const std::array<uint64_t, 3>& ksi);

// Rising edges of clk from strobe 17's fall to output 29's rise (rtl/sqmul/sqmul_ctrl.v,
// sqmul_r2l_ctrl.v): the synchroniser sync17's squared::sync_stages, the taking edge, the golden
// model's steps, the done edge.
unsigned sqmul_clocks(sqmul_walk w, unsigned n);
// The same by hand, for n >= 1 and the synchroniser's two: floor(log2 n) + popcount(n) + 3 left
// to right (one clock per square and per multiplication), floor(log2 n) + 5 right to left (one
// clock per bit of n).
unsigned sqmul_clocks_formula(sqmul_walk w, unsigned n);

// The largest |f(n, code) - cos^n| / cos^n over n in [1, n_max] and the Q1.15 codes where
// cos^n >= threshold; where it is, and how many n exceed 1 %.
struct rel_error {
    double worst = 0;
    unsigned at_n = 0;
    uint64_t at_code = 0;
    unsigned n_above_1pct = 0;
};
rel_error worst_rel_error(const std::function<double(unsigned n, uint64_t code)>& f, double threshold,
                          unsigned n_max);

}  // namespace shading::study
