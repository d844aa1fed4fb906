#include "arith/sqmul_arith.h"

#include <algorithm>

#include "formats/specular_formats.h"
#include "formats/sqmul_formats.h"

namespace shading {

sqmul_nets golden_sqmul(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi, overflow_mode mode) {
    using namespace sqmul;
    sqmul_nets r;
    const uint64_t n = n_bits & n_fmt.mask();
    uint64_t c = (cos_bits & spec::cos_fmt.mask()) << cos_align;
    if (mode == overflow_mode::saturate) c = std::min(c, p_one);
    uint64_t p = c;
    int top = static_cast<int>(n_fmt.width) - 1;
    while (top > 0 && !((n >> top) & 1u)) --top;
    for (int b = top - 1; b >= 0; --b) {
        p = ((p * p) >> p_frac) & p_fmt.mask();
        ++r.squares;
        if ((n >> b) & 1u) {
            p = ((p * c) >> p_frac) & p_fmt.mask();
            ++r.multiplies;
        }
    }
    r.p = p;
    const uint64_t q15 = (p >> (p_frac - spec::brdf_fmt.frac)) & spec::brdf_fmt.mask();
    for (std::size_t i = 0; i < 3; ++i)
        r.out[i] = ((q15 * (ksi[i] & spec::ksi_fmt.mask())) >> spec::out_drop) & spec::out_fmt.mask();
    return r;
}

}  // namespace shading
