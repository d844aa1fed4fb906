// 8-bit RGB images: PNG output (libpng), conversion from the references' real images, a heat map
// for error images, and a side-by-side sheet.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/shade.h"

namespace shading::scene {

struct rgb_image {
    unsigned width = 0, height = 0;
    std::vector<uint8_t> data;  // R, G, B per pixel, rows from the top
    rgb_image() = default;
    rgb_image(unsigned w, unsigned h, uint8_t fill = 0)
        : width(w), height(h), data(static_cast<std::size_t>(w) * h * 3, fill) {}
    uint8_t* at(unsigned x, unsigned y) { return &data[(static_cast<std::size_t>(y) * width + x) * 3]; }
    const uint8_t* at(unsigned x, unsigned y) const { return &data[(static_cast<std::size_t>(y) * width + x) * 3]; }
};

class image_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Writes an 8-bit RGB PNG. Throws image_error naming the file if it cannot be written; a partly
// written file is removed.
void save_png(const rgb_image& img, const std::string& path);

// Rounds to nearest, clamped to [0, 255]. A value that is not a number has no level: throws
// image_error naming the pixel (a cast of NaN to an integer is undefined).
rgb_image to_rgb8(const shaded_image& s);

// An image against a reference over the reference's covered pixels, every channel:
// NMSE = sum (test - ref)^2 / sum ref^2, and the largest |test - ref| (8-bit units). Same sizes required.
struct image_diff {
    double nmse = 0.0, max_abs = 0.0;
};
image_diff compare_images(const shaded_image& test, const shaded_image& ref);

// Per pixel, the largest absolute channel difference |a - b| (8-bit units). Same sizes required.
std::vector<double> abs_error(const shaded_image& a, const shaded_image& b);

// A heat map of `values` (width * height, row-major): 0 black, then blue, red, yellow, white at
// `full_scale` and above. Pixels where `mask` (if given) is 0 are drawn dark grey. A value that is
// not a number on a drawn pixel throws image_error naming it.
rgb_image heat_map(const std::vector<double>& values, unsigned width, unsigned height, double full_scale,
                   const std::vector<uint8_t>* mask = nullptr);

// Images side by side on a dark background with `gap` pixels between them; each image gets its
// label (if any) printed above it in a 5x7 pixel font (A-Z, 0-9 and . , : - + = / ( ) % _ and
// space; lower case printed as upper case; other characters as '?').
rgb_image side_by_side(const std::vector<rgb_image>& images, const std::vector<std::string>& labels = {},
                       unsigned gap = 8);

// Images one below the other, left-aligned, on the same dark background (e.g. rows of side_by_side).
rgb_image stacked(const std::vector<rgb_image>& rows);

// The key of heat_map at `full_scale`: a colour bar from 0 to full_scale with five tick labels and
// the caption `caption`, centred in a width x height dark image (sized to sit beside heat maps).
rgb_image heat_map_legend(unsigned width, unsigned height, double full_scale, const std::string& caption);

}  // namespace shading::scene
