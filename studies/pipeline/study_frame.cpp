// A pipeline frame in levels (study_frame.h).
#include "study_frame.h"

namespace shading::study {

std::vector<rgb_levels> levels_of(const pipeline::frame& f) {
    std::vector<rgb_levels> out(f.px.size(), rgb_levels{0.0, 0.0, 0.0});
    for (std::size_t i = 0; i < out.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) out[i][ch] = f.px[i][ch] * pipeline::pixel_fmt.lsb();
    return out;
}

}  // namespace shading::study
