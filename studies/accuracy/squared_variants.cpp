#include "squared_variants.h"

#include <algorithm>

#include "formats/specular_formats.h"
#include "formats/squared_formats.h"

namespace shading::study {

squared_variant squared_device_variant() { return {"s2", "a = f + f(1-f)/2^(k+2) (the device)", {2}, squared::q_frac}; }

std::vector<squared_variant> bend_variants() {
    return {
        {"f", "a = f (no bend)", {}, squared::q_frac},
        {"s1", "a = f + f(1-f)/2^(k+1)", {1}, squared::q_frac},
        squared_device_variant(),
        {"s3", "a = f + f(1-f)/2^(k+3)", {3}, squared::q_frac},
        {"s2s3", "a = f + 3 f(1-f)/2^(k+3) (two shifts)", {2, 3}, squared::q_frac},
    };
}

std::vector<squared_variant> fraction_variants() {
    std::vector<squared_variant> v;
    for (unsigned q = 16; q <= 20; ++q)
        v.push_back({"q" + std::to_string(q), "Q1." + std::to_string(q) + " q and square word", {2}, q});
    return v;
}

unsigned variant_k(unsigned n) {
    unsigned k = 0;
    while ((n & squared::n_fmt.mask()) >> (k + 1)) ++k;
    return k;
}

uint64_t variant_a(const squared_variant& v, unsigned n) {
    using squared::a_fmt;
    using squared::f_fmt;
    n &= squared::n_fmt.mask();
    const unsigned k = variant_k(n);
    // f: n's bits below its leading one, on Q0.9 (n = 2^k (1 + f)); ~f = 1 - f - 2^-9.
    const uint64_t f = n == 0 ? 0 : ((static_cast<uint64_t>(n) << (f_fmt.frac - static_cast<int>(k))) & f_fmt.mask());
    const uint64_t e = f * (~f & f_fmt.mask());  // Q0.18
    uint64_t a = f << (a_fmt.frac - f_fmt.frac);
    // e / 2^(k + s) on Q0.12: e / 2^(18 - 12 + k + s), floored.
    for (unsigned s : v.bend_shifts) a += e >> (2 * f_fmt.frac - a_fmt.frac + static_cast<int>(k + s));
    return a & a_fmt.mask();
}

uint64_t variant_word(const squared_variant& v, unsigned n, uint64_t cos_code) {
    const unsigned qf = v.q_frac;
    const uint64_t one = 1ull << qf, mask = (2ull << qf) - 1;  // Q1.qf: qf + 1 wires
    const int64_t c = static_cast<int64_t>(cos_code & spec::cos_fmt.mask());              // Q1.15
    const int64_t diff = c * c - (c << spec::cos_fmt.frac);                               // Q2.30
    const __int128 prod = static_cast<__int128>(variant_a(v, n)) * diff;                 // Q2.42
    const int64_t q = static_cast<int64_t>(prod >> (squared::a_fmt.frac + 2 * spec::cos_fmt.frac - static_cast<int>(qf))) +
                      (qf >= 15 ? c << (qf - 15) : c >> (15 - qf));                       // Q1.qf
    uint64_t s = static_cast<uint64_t>(std::clamp<int64_t>(q, 0, static_cast<int64_t>(one)));
    for (unsigned i = 0; i < variant_k(n); ++i) s = ((s * s) >> qf) & mask;
    return s;
}

double variant_value(const squared_variant& v, unsigned n, uint64_t cos_code) {
    return static_cast<double>(variant_word(v, n, cos_code)) / static_cast<double>(1ull << v.q_frac);
}

std::array<uint64_t, 3> variant_out(const squared_variant& v, unsigned n, uint64_t cos_code,
                                    const std::array<uint64_t, 3>& ksi) {
    const uint64_t q15 = (variant_word(v, n, cos_code) >> (v.q_frac - spec::brdf_fmt.frac)) & spec::brdf_fmt.mask();
    std::array<uint64_t, 3> out{};
    for (std::size_t i = 0; i < 3; ++i)
        out[i] = ((q15 * (ksi[i] & spec::ksi_fmt.mask())) >> spec::out_drop) & spec::out_fmt.mask();
    return out;
}

}  // namespace shading::study
