#include "arith/ua22802_arith.h"

#include <cmath>

#include "formats/ua22802_formats.h"

namespace shading {

double ua22802::a_formula(double n) {
    if (n <= 1.0) return 0.0;  // n = 1: cos^1 is the line itself
    const double t = std::sqrt((n - 1.0) / n);
    return (std::pow(t, n - 1.0) - 1.0) / (t - 1.0);
}

uint64_t golden_a_rom(uint64_t n_bits) {
    using namespace ua22802;
    const uint64_t n = n_bits & addr_fmt.mask();
    const double a = a_formula(static_cast<double>(n));  // 0 for n = 0 and n = 1
    return static_cast<uint64_t>(std::floor(std::ldexp(a, a_fmt.frac) + 0.5)) & a_fmt.mask();
}

datapath_nets golden_ua22802(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi,
                             overflow_mode mode) {
    return golden_datapath(golden_a_rom(n_bits), ua22802::a_fmt.frac, cos_bits, ksi, mode);
}

}  // namespace shading
