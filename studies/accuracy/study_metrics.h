// Accuracy measures of the quadratic-BRDF paper for the study and the generator search (plain C++, no SystemC):
//  - max_rel_err_056: the largest |approx - cos^n| / cos^n over the Q1.15 cos codes where
//    cos^n >= 0.56 (the quadratic-BRDF paper, Fig. 3);
//  - nmse: sum (approx - cos^n)^2 / sum (cos^n)^2 over the whole grid of the 32769 Q1.15 codes
//    c = k / 32768, k = 0..32768 (a uniform grid of cos in [0, 1], step 2^-15).
// Every method is evaluated on the same codes, the bit-accurate devices through their golden
// models' ADD11 output (the BRDF, Q1.15, before the colour multipliers).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

namespace shading::study {

struct error_pair {
    double max_rel_056 = 0;
    double nmse = 0;
};

// approx(c_code) -> value in real units, for one n.
using approx_fn = std::function<double(uint64_t cos_code)>;

class grid {
public:
    grid();  // precomputes cos^n for every n in [0, 1023] on the codes where it is >= 0.56
    double max_rel_err_056(unsigned n, const approx_fn& f, double abort_above = 1e300) const;
    double nmse(unsigned n, const approx_fn& f) const;
    // The Q1.15 codes where cos^n >= 0.56, in decreasing order, and cos^n there.
    const std::vector<uint64_t>& codes(unsigned n) const { return codes_[n]; }
    const std::vector<double>& exact(unsigned n) const { return exact_[n]; }

private:
    std::vector<std::vector<uint64_t>> codes_;
    std::vector<std::vector<double>> exact_;
};

// BRDF (ADD11, saturate mode) of the shared datapath for an `a` bus word, in real units.
double datapath_brdf(uint64_t a_bits, int a_frac, uint64_t cos_code);

// The quadratic-BRDF paper's (cos k gamma)^(n/k): k by n's range (README): k = 2^floor(log2(n) / 2), i.e.
// 1 for n < 4, 2 for 4..15, 4 for 16..63, 8 for 64..255, 16 for 256..1023.
double cosk_k_for(unsigned n);

}  // namespace shading::study
