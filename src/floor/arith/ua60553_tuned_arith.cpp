#include "arith/ua60553_tuned_arith.h"

namespace shading {

uint64_t golden_a_tuned(uint64_t n_bits, const ua60553::tuned_generator& g) {
    using namespace ua60553;
    const uint64_t n = n_bits & n_fmt.mask();
    if (n < 2) return 0;                                                    // OR(n[9:1]) = 0
    const int64_t mul6 = static_cast<int64_t>(n * bits_from_string(g.k31_bits));  // 10.0 x 0.7 -> 10.7
    const int64_t k32 = static_cast<int64_t>(bits_from_string(g.k32_bits));       // Q0.7 magnitude
    return wrap_bits(mul6 + (g.k32_negative ? -k32 : k32), a_fmt.width);         // 10.7 + 1.7s -> 11.7
}

datapath_nets golden_ua60553_tuned(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi,
                                   overflow_mode mode, const ua60553::tuned_generator& g) {
    return golden_datapath(golden_a_tuned(n_bits, g), ua60553::a_fmt.frac, cos_bits, ksi, mode);
}

}  // namespace shading
