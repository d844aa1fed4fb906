// Fixed-point formats shared by the golden models (src/) and the SystemC modules (modules/).
// A format is a bus: `width` bits, two's complement when `is_signed`, `frac` fraction bits.
// The integer part is width - frac (including the sign bit when signed).
#pragma once

#include <cstdint>
#include <string_view>

namespace shading {

struct qfmt {
    unsigned width;
    bool is_signed;
    int frac;

    constexpr int int_bits() const { return static_cast<int>(width) - frac; }
    constexpr double lsb() const { return 1.0 / static_cast<double>(1ull << frac); }
    constexpr uint64_t mask() const { return width >= 64 ? ~0ull : ((1ull << width) - 1); }
};

// Raw bus bits -> signed integer value of the code (sign-extends when the format is signed).
constexpr int64_t code_value(uint64_t bits, qfmt f) {
    bits &= f.mask();
    if (f.is_signed && f.width < 64 && (bits >> (f.width - 1)) & 1u)
        return static_cast<int64_t>(bits) - static_cast<int64_t>(1ull << f.width);
    return static_cast<int64_t>(bits);
}

inline double to_real(uint64_t bits, qfmt f) {
    return static_cast<double>(code_value(bits, f)) * f.lsb();
}

// Two's-complement wrap of an integer into the bus (what dropping the high wires does).
constexpr uint64_t wrap_bits(int64_t v, unsigned width) {
    return static_cast<uint64_t>(v) & (width >= 64 ? ~0ull : ((1ull << width) - 1));
}

// Arithmetic shift right = truncation toward minus infinity (dropping low wires of a
// two's-complement bus).
constexpr int64_t floor_shift(__int128 v, unsigned drop) {
    return static_cast<int64_t>(v >> drop);
}

// A hardwired constant written as the patent gives it: a string of bits, most significant
// first ("1100101" for UA 60553 node 31). Any other character is a programming error.
constexpr uint64_t bits_from_string(std::string_view s) {
    uint64_t v = 0;
    for (char ch : s) {
        if (ch != '0' && ch != '1') throw "bits_from_string: only '0' and '1' allowed";
        v = (v << 1) | static_cast<uint64_t>(ch - '0');
    }
    return v;
}

// What an adder does with a result that does not fit its output bus.
enum class overflow_mode {
    wrap,      // the real two's-complement adder: the output wires carry the low bits
    saturate,  // clamp to a documented [lo, hi] range
};

}  // namespace shading

#include <ostream>
namespace shading {
inline std::ostream& operator<<(std::ostream& os, overflow_mode m) {
    return os << (m == overflow_mode::saturate ? "saturate" : "wrap");
}
}  // namespace shading
