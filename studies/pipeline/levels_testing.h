// Test helper of the study's suites (test_edge_split, test_two_line): the squared error between two
// runs of colours in levels, summed over pixels and channels, for hand-worked expectations.
#pragma once

#include <vector>

#include "levels.h"

namespace shading::study::test_helpers {

inline double squared_error(const std::vector<rgb_levels>& a, const std::vector<rgb_levels>& b) {
    double se = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) se += (a[i][ch] - b[i][ch]) * (a[i][ch] - b[i][ch]);
    return se;
}

}  // namespace shading::study::test_helpers
