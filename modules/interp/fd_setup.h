// The forward-difference set-up as shift-and-add term tables, shared by fd_eval<M> and
// fd_eval_var<MMIN, MMAX> so that every interval length gets the same network. For N = 2^m the
// Q16.16 coefficients (network inputs 0 = A, 1 = B, 2 = C) land on the Q22.34 bus (fd_fmt) shifted
// by `align` - k*m for a division by N^k; 6A = 4A + 2A. Exact for m <= interp::m_max (interp_formats.h).
#pragma once

#include <vector>

#include "blocks/shift_add_network.h"
#include "formats/interp_formats.h"

namespace shading::fd_setup {

inline constexpr int align = interp::fd_fmt.frac - interp::coef_fmt.frac;  // 18: Q.16 -> Q.34

// D1 = A/N^3 + B/N^2 + C/N (inputs A, B, C).
inline std::vector<sa_term> d1_terms(unsigned m) {
    const int sm = static_cast<int>(m);
    return {{0, align - 3 * sm, false}, {1, align - 2 * sm, false}, {2, align - sm, false}};
}
// D2 = (4A + 2A)/N^3 + 2B/N^2 (inputs A, B).
inline std::vector<sa_term> d2_terms(unsigned m) {
    const int sm = static_cast<int>(m);
    return {{0, align - 3 * sm + 2, false}, {0, align - 3 * sm + 1, false}, {1, align - 2 * sm + 1, false}};
}
// D3 = (4A + 2A)/N^3 (input A).
inline std::vector<sa_term> d3_terms(unsigned m) {
    const int sm = static_cast<int>(m);
    return {{0, align - 3 * sm + 2, false}, {0, align - 3 * sm + 1, false}};
}

}  // namespace shading::fd_setup
