#include "arith/squared_arith.h"

#include <algorithm>

#include "formats/specular_formats.h"
#include "formats/squared_formats.h"

namespace shading {

squared_a_nets golden_squared_a(uint64_t n_bits) {
    using namespace squared;
    squared_a_nets g{};
    const uint64_t n = n_bits & n_fmt.mask();
    unsigned z = 0;
    while (z < n_fmt.width && !((n >> (n_fmt.width - 1 - z)) & 1u)) ++z;
    g.z = z;
    g.mant = (n << z) & mant_fmt.mask();
    g.f = g.mant & f_fmt.mask();
    g.e = g.f * (~g.f & f_fmt.mask());                                        // 9 x 9 -> 18, exact
    g.esh = (g.e << z) & ((1ull << esh_width) - 1);
    g.bend = (g.esh >> (esh_frac - bend_fmt.frac)) & bend_fmt.mask();         // floor
    g.a = ((g.f << (a_fmt.frac - f_fmt.frac)) + g.bend) & a_fmt.mask();
    g.k = z <= z_full ? z_full - z : 0;
    return g;
}

squared_nets golden_squared(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi,
                            overflow_mode mode) {
    using namespace squared;
    squared_nets r{};
    r.gen = golden_squared_a(n_bits);
    const int64_t c = static_cast<int64_t>(cos_bits & spec::cos_fmt.mask());       // Q1.15
    r.cos2 = static_cast<uint64_t>(c * c);                                         // Q2.30
    const int64_t diff = c * c - (c << spec::inv8_align);                          // Q2.30, exact
    r.diff = wrap_bits(diff, spec::d_fmt.width);
    const __int128 full = static_cast<__int128>(r.gen.a) * diff;                   // Q2.42
    const int64_t prod = floor_shift(full, mul10_drop);                            // Q2.18, floor
    r.prod = wrap_bits(prod, mul10_fmt.width);
    const int64_t sum = code_value(r.prod, mul10_fmt) + (c << cos_align);          // Q1.18
    r.q = mode == overflow_mode::saturate
              ? static_cast<uint64_t>(std::clamp<int64_t>(sum, q_sat_lo, q_sat_hi))
              : wrap_bits(sum, q_fmt.width);
    uint64_t s = r.q;
    r.sq[0] = s;
    for (unsigned i = 1; i <= r.gen.k; ++i) {
        s = ((s * s) >> q_frac) & sq_fmt.mask();  // 19 x 19 -> Q2.36, floor to Q1.18, high wires dropped
        r.sq[i] = s;
    }
    r.brdf = s;
    const uint64_t q15 = (s >> sq_to_brdf_drop) & spec::brdf_fmt.mask();
    for (std::size_t i = 0; i < 3; ++i)
        r.out[i] = ((q15 * (ksi[i] & spec::ksi_fmt.mask())) >> spec::out_drop) & spec::out_fmt.mask();
    return r;
}

}  // namespace shading
