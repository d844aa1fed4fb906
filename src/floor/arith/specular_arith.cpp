#include "arith/specular_arith.h"

#include <algorithm>

#include "formats/specular_formats.h"

namespace shading {

datapath_nets golden_datapath(uint64_t a_bits, int a_frac, uint64_t cos_bits,
                              const std::array<uint64_t, 3>& ksi, overflow_mode mode) {
    using namespace spec;
    datapath_nets r{};
    const int64_t c = static_cast<int64_t>(cos_bits & cos_fmt.mask());          // Q1.15
    r.cos2 = static_cast<uint64_t>(c * c);                                       // Q2.30
    r.inv8 = ~(static_cast<uint64_t>(c) << inv8_align) & inv8_fmt.mask();
    const int64_t diff = c * c - (c << inv8_align);                              // Q2.30, exact
    r.diff = wrap_bits(diff, d_fmt.width);
    const __int128 full = static_cast<__int128>(a_bits) * diff;                  // Q.(a_frac+30)
    const int64_t prod = floor_shift(full, mul10_drop(a_frac));                  // Q12.15, floor
    r.prod = wrap_bits(prod, mul10_fmt.width);
    const int64_t sum = code_value(r.prod, mul10_fmt) + c;                      // Q1.15 + carry 0
    r.brdf = mode == overflow_mode::saturate
                 ? static_cast<uint64_t>(std::clamp<int64_t>(sum, brdf_sat_lo, brdf_sat_hi))
                 : wrap_bits(sum, brdf_fmt.width);
    for (std::size_t i = 0; i < 3; ++i)
        r.out[i] = ((r.brdf * (ksi[i] & ksi_fmt.mask())) >> out_drop) & out_fmt.mask();
    return r;
}

uint64_t golden_a_linear(uint64_t n_bits, const ua60553::linear_generator& g) {
    using namespace ua60553;
    const uint64_t n = n_bits & n_fmt.mask();
    const uint64_t mul6 = n * bits_from_string(g.k31_bits);  // 10.0 x 0.7 -> 10.7
    return (mul6 + bits_from_string(g.k32_bits)) & a_fmt.mask();
}

datapath_nets golden_ua60553(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi,
                             overflow_mode mode, const ua60553::linear_generator& g) {
    return golden_datapath(golden_a_linear(n_bits, g), ua60553::a_fmt.frac, cos_bits, ksi, mode);
}

}  // namespace shading
