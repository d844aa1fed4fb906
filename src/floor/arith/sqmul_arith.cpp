#include "arith/sqmul_arith.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "formats/specular_formats.h"

namespace shading {

namespace {

sqmul::p_word_fmt checked_word(unsigned p_frac) {
    if (p_frac < sqmul::p_frac_min || p_frac > sqmul::p_frac_max)
        throw std::invalid_argument("golden_sqmul: P word with " + std::to_string(p_frac) + " fraction bits");
    return sqmul::p_word(p_frac);
}

// cos (Q1.15) on the P word, clamped to 1.0 in saturate mode.
uint64_t load_cos(uint64_t cos_bits, overflow_mode mode, const sqmul::p_word_fmt& w) {
    const uint64_t c = (cos_bits & spec::cos_fmt.mask()) << w.cos_align;
    return mode == overflow_mode::saturate ? std::min(c, w.one) : c;
}

// A product on the word: floor, then the word's wires.
uint64_t product(uint64_t a, uint64_t b, const sqmul::p_word_fmt& w) { return ((a * b) >> w.frac) & w.fmt.mask(); }

// The colour multipliers on P's 16 high wires (Q1.15) times the 8-bit k_s*I, Q9.8.
void colour(sqmul_nets& r, const std::array<uint64_t, 3>& ksi, const sqmul::p_word_fmt& w) {
    const uint64_t q15 = (r.p >> (w.frac - spec::brdf_fmt.frac)) & spec::brdf_fmt.mask();
    for (std::size_t i = 0; i < 3; ++i)
        r.out[i] = ((q15 * (ksi[i] & spec::ksi_fmt.mask())) >> spec::out_drop) & spec::out_fmt.mask();
}

}  // namespace

sqmul_nets golden_sqmul(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi, overflow_mode mode,
                        unsigned p_frac) {
    const sqmul::p_word_fmt w = checked_word(p_frac);
    sqmul_nets r;
    const uint64_t n = n_bits & sqmul::n_fmt.mask();
    const uint64_t c = load_cos(cos_bits, mode, w);
    uint64_t p = c;
    int top = static_cast<int>(sqmul::n_fmt.width) - 1;
    while (top > 0 && !((n >> top) & 1u)) --top;
    for (int b = top - 1; b >= 0; --b) {
        p = product(p, p, w);
        ++r.squares;
        if ((n >> b) & 1u) {
            p = product(p, c, w);
            ++r.multiplies;
        }
    }
    r.steps = r.squares + r.multiplies;
    r.p = p;
    colour(r, ksi, w);
    return r;
}

sqmul_nets golden_sqmul_r2l(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi,
                            overflow_mode mode, unsigned p_frac) {
    const sqmul::p_word_fmt w = checked_word(p_frac);
    sqmul_nets r;
    uint64_t x = load_cos(cos_bits, mode, w), p = w.one;
    // Both products of a step are formed from the registers' old words, then latched together.
    for (uint64_t n = n_bits & sqmul::n_fmt.mask(); n != 0; n >>= 1) {
        if (n & 1u) {
            p = product(p, x, w);
            ++r.multiplies;
        }
        x = product(x, x, w);
        ++r.squares;
        ++r.steps;
    }
    r.p = p;
    colour(r, ksi, w);
    return r;
}

}  // namespace shading
