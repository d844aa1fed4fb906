// What a shading scheme must hold besides the frame buffer, in bits, so the race's schemes are
// compared on their memory as well as their operations: the words a triangle holds while the scan
// reaches it (its plane or expansion coefficients and the values stepped along its spans), and the
// scheme's fixed stores (tables, ROMs, line and band buffers). The race multiplies the per-triangle
// words by the most triangles live at once in the scheme's read order.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace shading::scene {

// One word width for every scheme's geometry and shading values, stated once: a single-precision
// float (the stepped normals, positions, colours and their gradients and expansion coefficients).
inline constexpr unsigned state_word_bits = 32;

struct state_item {
    std::string what;   // "specular power table", "band buffer"
    uint64_t words = 0;
    unsigned bits = 0;  // per word
    uint64_t total_bits() const { return words * bits; }
};

struct scheme_state {
    unsigned per_triangle_words = 0;  // words of state_word_bits a live triangle holds
    std::vector<state_item> fixed;    // the scheme's stores whatever the scene
    // The whole state with `live` triangles held at once.
    uint64_t bits(uint64_t live) const {
        uint64_t b = live * per_triangle_words * uint64_t(state_word_bits);
        for (const auto& f : fixed) b += f.total_bits();
        return b;
    }
};

}  // namespace shading::scene
