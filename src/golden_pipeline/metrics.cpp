// Error measures of the shading pipeline (pipeline.h): a frame's codes as 8-bit values, and NMSE,
// PSNR, the largest error and the pixels beyond error_levels against a reference image over its
// covered pixels, whole or per zone.
#include <algorithm>
#include <cmath>
#include <limits>

#include "golden_pipeline/pipeline.h"

namespace shading::pipeline {

scene::shaded_image to_image(const frame& f) {
    scene::shaded_image img;
    img.width = f.width;
    img.height = f.height;
    img.covered = f.covered;
    img.value.resize(f.px.size());
    const double lsb = pixel_fmt.lsb();  // 1/256 of an 8-bit level
    for (std::size_t i = 0; i < f.px.size(); ++i)
        img.value[i] = {static_cast<double>(f.px[i][0]) * lsb, static_cast<double>(f.px[i][1]) * lsb,
                        static_cast<double>(f.px[i][2]) * lsb};
    return img;
}

error_stats compare(const scene::shaded_image& a, const scene::shaded_image& ref, const std::vector<uint8_t>* zones,
                    int zone) {
    const std::size_t n = ref.value.size();
    if (a.width != ref.width || a.height != ref.height || a.value.size() != n || ref.covered.size() != n)
        throw scene::scene_error("compare: images of different sizes (" + std::to_string(a.width) + "x" +
                                 std::to_string(a.height) + " against " + std::to_string(ref.width) + "x" +
                                 std::to_string(ref.height) + ")");
    if (zone >= 0 && (!zones || zones->size() != n))
        throw scene::scene_error("compare: a zone was asked for without a zone map of the image's size");
    // Pixels the reference covers (a pixel a misses counts with its value 0: a hole is an error).
    double sum_d2 = 0.0, sum_r2 = 0.0;
    error_stats st;
    for (std::size_t i = 0; i < n; ++i) {
        if (!ref.covered[i]) continue;
        if (zone >= 0 && (*zones)[i] != zone) continue;
        ++st.pixels;
        double worst = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double d = a.value[i][c] - ref.value[i][c];
            sum_d2 += d * d;
            sum_r2 += ref.value[i][c] * ref.value[i][c];
            worst = std::max(worst, std::abs(d));
        }
        st.max_abs = std::max(st.max_abs, worst);
        for (std::size_t k = 0; k < error_levels.size(); ++k)
            if (worst > error_levels[k]) ++st.pixels_over[k];
    }
    const double inf = std::numeric_limits<double>::infinity();
    // A black (or empty) reference: NMSE 0 if a equals it, else unbounded.
    st.nmse = sum_r2 > 0.0 ? sum_d2 / sum_r2 : (sum_d2 > 0.0 ? inf : 0.0);
    const double mse = st.pixels ? sum_d2 / (3.0 * static_cast<double>(st.pixels)) : 0.0;
    st.psnr_db = mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : inf;
    return st;
}

}  // namespace shading::pipeline
