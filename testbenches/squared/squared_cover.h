// Stimulus pieces that cover what the squared-quadratic device can do, for its co-simulations and
// bench programs (streams for specular_stimulus, testbenches/specular/specular_tb.h):
//   cos_codes_near_levels - per n, the cos codes whose cos^n lies near given levels (0.5, 0.1,
//                           0.01), computed from the real-valued cos = level^(1/n), and neighbours:
//                           above n of about 90 fixed codes give cos^n of only 0 or full scale;
//   level_surfaces        - every n of a range with those codes and fixed ones;
//   bad_input_surfaces    - the bad inputs of modules/squared/README.md: n = 0, n = 1001..1023,
//                           cos > 1.0, with k_s*I reloaded between the pixels (single-pixel
//                           surfaces, each reloading another subset of RG3..RG5);
//   input_reports         - how many shading/input reports a stream must raise (hand count: one per
//                           out-of-range n latched by strobe 15, one per cos > 1.0 by strobe 17).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "formats/specular_formats.h"
#include "formats/squared_formats.h"
#include "testbenches/specular/specular_tb.h"

namespace shading::tb {

// The levels of cos^n the per-n codes aim at.
inline const std::vector<double>& cos_pow_levels() {
    static const std::vector<double> levels{0.5, 0.1, 0.01};
    return levels;
}

// The code nearest cos = level^(1/n) (n = 0 is read as n = 1 by the device) and `spread` codes
// either side, within 0..1.0, ascending, no repeats.
inline std::vector<uint32_t> cos_codes_near_levels(unsigned n, const std::vector<double>& levels, unsigned spread) {
    const double n_read = std::max(1u, n);
    const double one = static_cast<double>(spec::cos_one);
    std::vector<uint32_t> codes;
    for (double level : levels) {
        const auto c = static_cast<int64_t>(std::lround(std::pow(level, 1.0 / n_read) * one));
        for (int64_t d = -static_cast<int64_t>(spread); d <= static_cast<int64_t>(spread); ++d)
            codes.push_back(static_cast<uint32_t>(std::clamp<int64_t>(c + d, 0, static_cast<int64_t>(spec::cos_one))));
    }
    std::sort(codes.begin(), codes.end());
    codes.erase(std::unique(codes.begin(), codes.end()), codes.end());
    return codes;
}

// Every n of [first, last], each a surface of the codes near cos_pow_levels() (2 neighbours either
// side) and the fixed codes 0.5, 0.75, 0.9375 and 1.0.
inline std::vector<surface> level_surfaces(unsigned first, unsigned last) {
    std::vector<surface> s;
    for (unsigned n = first; n <= last; ++n) {
        surface x{n, {255, 17, 96}, cos_codes_near_levels(n, cos_pow_levels(), 2)};
        for (uint32_t c : {0x4000u, 0x6000u, 0x7800u, static_cast<uint32_t>(spec::cos_one)})
            if (std::find(x.cos_codes.begin(), x.cos_codes.end(), c) == x.cos_codes.end()) x.cos_codes.push_back(c);
        s.push_back(std::move(x));
    }
    return s;
}

// cos codes above 1.0: the first, a few between, the last.
inline const std::vector<uint32_t>& cos_codes_above_one() {
    static const std::vector<uint32_t> codes{0x8001, 0x8400, 0x9000, 0xA000, 0xB505, 0xC000, 0xE000, 0xFFFF};
    return codes;
}

// n = 0, n = 1001..1023 and, for contrast, n = 1, 512, 1000; for each: a surface loading n and
// k_s*I with cos near 0.5, then one single-pixel surface per code (above 1.0, then near the levels)
// that reloads only k_s*I, each time another non-empty subset of RG3..RG5 with new values.
inline std::vector<surface> bad_input_surfaces() {
    std::vector<unsigned> ns{0};
    for (unsigned n = squared::n_max + 1; n < (1u << squared::n_fmt.width); ++n) ns.push_back(n);
    for (unsigned n : {1u, 512u, squared::n_max}) ns.push_back(n);
    std::vector<surface> s;
    unsigned subset = 0;
    for (unsigned n : ns) {
        std::vector<uint32_t> codes = cos_codes_above_one();
        for (uint32_t c : cos_codes_near_levels(n, cos_pow_levels(), 0)) codes.push_back(c);
        s.push_back({n, {255, 128, 1}, cos_codes_near_levels(n, {0.5}, 0)});
        for (uint32_t c : codes) {
            subset = subset % 7 + 1;  // 1..7: which of R, G, B
            surface x{n, {}, {c}, {false, (subset & 1) != 0, (subset & 2) != 0, (subset & 4) != 0}};
            for (unsigned ch = 0; ch < 3; ++ch) x.ksi[ch] = (37 * (n + c) + 91 * ch) % 256;
            s.push_back(std::move(x));
        }
    }
    return s;
}

// The model's shading/input reports a stream raises: every out-of-range n strobe 15 latches and
// every cos > 1.0 strobe 17 latches.
inline std::size_t input_reports(const std::vector<surface>& s) {
    std::size_t r = 0;
    for (const auto& x : s) {
        if (x.reload[0] && (x.n < squared::n_min || x.n > squared::n_max)) ++r;
        for (uint32_t c : x.cos_codes) r += c > spec::cos_one ? 1 : 0;
    }
    return r;
}

}  // namespace shading::tb
