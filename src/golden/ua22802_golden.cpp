#include "golden/ua22802_golden.h"

#include <cmath>

#include "reference/brdf_reference.h"
#include "formats/ua22802_formats.h"

namespace shading {

uint64_t golden_a_rom(uint64_t n_bits) {
    using namespace ua22802;
    const uint64_t n = n_bits & addr_fmt.mask();
    const double a = ref::a_exact(static_cast<double>(n));  // 0 for n = 0 and n = 1
    return static_cast<uint64_t>(std::floor(std::ldexp(a, a_fmt.frac) + 0.5)) & a_fmt.mask();
}

datapath_nets golden_ua22802(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi,
                             overflow_mode mode) {
    return golden_datapath(golden_a_rom(n_bits), ua22802::a_fmt.frac, cos_bits, ksi, mode);
}

}  // namespace shading
