#include "scene/image.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <utility>

#include <png.h>

namespace shading::scene {

namespace {

// A 5x7 pixel font (rows top to bottom, bit 4 = leftmost column), the classic LCD character shapes.
struct glyph {
    char c;
    uint8_t rows[7];
};
constexpr glyph font[] = {
    {'A', {0x0E, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11}}, {'B', {0x1E, 0x11, 0x11, 0x1E, 0x11, 0x11, 0x1E}},
    {'C', {0x0E, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0E}}, {'D', {0x1C, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1C}},
    {'E', {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F}}, {'F', {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x10}},
    {'G', {0x0E, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0F}}, {'H', {0x11, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11}},
    {'I', {0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}}, {'J', {0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0C}},
    {'K', {0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11}}, {'L', {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F}},
    {'M', {0x11, 0x1B, 0x15, 0x15, 0x11, 0x11, 0x11}}, {'N', {0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11}},
    {'O', {0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}}, {'P', {0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10}},
    {'Q', {0x0E, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0D}}, {'R', {0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11}},
    {'S', {0x0F, 0x10, 0x10, 0x0E, 0x01, 0x01, 0x1E}}, {'T', {0x1F, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04}},
    {'U', {0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}}, {'V', {0x11, 0x11, 0x11, 0x11, 0x11, 0x0A, 0x04}},
    {'W', {0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0A}}, {'X', {0x11, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x11}},
    {'Y', {0x11, 0x11, 0x11, 0x0A, 0x04, 0x04, 0x04}}, {'Z', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1F}},
    {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}}, {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}}, {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
    {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}}, {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
    {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}}, {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}}, {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
    {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C}}, {',', {0x00, 0x00, 0x00, 0x00, 0x0C, 0x04, 0x08}},
    {':', {0x00, 0x0C, 0x0C, 0x00, 0x0C, 0x0C, 0x00}}, {'-', {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00}},
    {'+', {0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00}}, {'=', {0x00, 0x00, 0x1F, 0x00, 0x1F, 0x00, 0x00}},
    {'/', {0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x00}}, {'(', {0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02}},
    {')', {0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08}}, {'%', {0x18, 0x19, 0x02, 0x04, 0x08, 0x13, 0x03}},
    {'_', {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x1F}}, {' ', {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}},
    {'^', {0x04, 0x0A, 0x11, 0x00, 0x00, 0x00, 0x00}}, {'?', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x00, 0x04}},
};
constexpr unsigned glyph_w = 5, glyph_h = 7, glyph_advance = 6;

const glyph& find_glyph(char c) {
    const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    for (const auto& g : font)
        if (g.c == u) return g;
    return font[sizeof(font) / sizeof(font[0]) - 1];  // '?'
}

void draw_text(rgb_image& img, unsigned x0, unsigned y0, const std::string& text, unsigned max_width) {
    unsigned x = x0;
    for (char ch : text) {
        if (x + glyph_w > x0 + max_width || x + glyph_w > img.width) break;
        const glyph& g = find_glyph(ch);
        for (unsigned r = 0; r < glyph_h && y0 + r < img.height; ++r)
            for (unsigned col = 0; col < glyph_w; ++col)
                if (g.rows[r] >> (glyph_w - 1 - col) & 1u) std::fill_n(img.at(x + col, y0 + r), 3, uint8_t{230});
        x += glyph_advance;
    }
}

// The file is closed and, on failure, removed, whatever happens.
struct png_file {
    std::FILE* f = nullptr;
    std::string path;
    bool ok = false;
    ~png_file() {
        if (f) std::fclose(f);
        if (!ok) std::remove(path.c_str());
    }
};
}  // namespace

void save_png(const rgb_image& img, const std::string& path) {
    if (img.width == 0 || img.height == 0 || img.data.size() != static_cast<std::size_t>(img.width) * img.height * 3)
        throw image_error("PNG '" + path + "': empty or inconsistent image");
    png_file file;
    file.path = path;
    file.f = std::fopen(path.c_str(), "wb");
    if (!file.f) throw image_error("PNG '" + path + "': cannot be opened for writing");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        png_destroy_write_struct(&png, &info);
        throw image_error("PNG '" + path + "': libpng could not start");
    }
    // libpng reports errors by longjmp: only plain data lives between here and the end.
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        throw image_error("PNG '" + path + "': write failed");
    }
    png_init_io(png, file.f);
    png_set_IHDR(png, info, img.width, img.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (unsigned y = 0; y < img.height; ++y) png_write_row(png, img.at(0, y));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    if (std::fflush(file.f) != 0) throw image_error("PNG '" + path + "': write failed");
    file.ok = true;
}

namespace {
std::string pixel_name(std::size_t i, unsigned width) {
    return "(" + std::to_string(width ? i % width : i) + ", " + std::to_string(width ? i / width : 0) + ")";
}
}  // namespace

rgb_image to_rgb8(const shaded_image& s) {
    rgb_image out(s.width, s.height);
    for (std::size_t i = 0; i < s.value.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            // std::clamp passes NaN through, and lround(NaN) has no defined level.
            if (std::isnan(s.value[i][c]))
                throw image_error("to_rgb8: pixel " + pixel_name(i, s.width) + " channel " + std::to_string(c) +
                                  " is not a number");
            out.data[3 * i + c] = static_cast<uint8_t>(std::lround(std::clamp(s.value[i][c], 0.0, 255.0)));
        }
    return out;
}

image_diff compare_images(const shaded_image& test, const shaded_image& ref) {
    if (test.width != ref.width || test.height != ref.height) throw image_error("compare_images: images of different sizes");
    double num = 0.0, den = 0.0;
    image_diff d;
    for (std::size_t i = 0; i < ref.value.size(); ++i) {
        if (!ref.covered[i]) continue;
        for (int c = 0; c < 3; ++c) {
            const double e = test.value[i][c] - ref.value[i][c];
            num += e * e;
            den += ref.value[i][c] * ref.value[i][c];
            d.max_abs = std::max(d.max_abs, std::abs(e));
        }
    }
    d.nmse = den > 0.0 ? num / den : 0.0;
    return d;
}

std::vector<double> abs_error(const shaded_image& a, const shaded_image& b) {
    if (a.width != b.width || a.height != b.height) throw image_error("abs_error: images of different sizes");
    std::vector<double> e(a.value.size());
    for (std::size_t i = 0; i < e.size(); ++i) {
        const rgb d = glm::abs(a.value[i] - b.value[i]);
        e[i] = std::max({d.x, d.y, d.z});
    }
    return e;
}

rgb_image heat_map(const std::vector<double>& values, unsigned width, unsigned height, double full_scale,
                   const std::vector<uint8_t>* mask) {
    if (values.size() != static_cast<std::size_t>(width) * height) throw image_error("heat_map: size mismatch");
    // Piecewise-linear ramp through black, blue, red, yellow, white.
    static constexpr double stops[5][3] = {{0, 0, 0}, {0, 0, 255}, {255, 0, 0}, {255, 255, 0}, {255, 255, 255}};
    rgb_image out(width, height);
    for (std::size_t i = 0; i < values.size(); ++i) {
        uint8_t* p = &out.data[3 * i];
        if (mask && !(*mask)[i]) {
            std::fill_n(p, 3, uint8_t{40});
            continue;
        }
        if (std::isnan(values[i])) throw image_error("heat_map: pixel " + pixel_name(i, width) + " is not a number");
        const double t = full_scale > 0.0 ? std::clamp(values[i] / full_scale, 0.0, 1.0) * 4.0 : 0.0;
        const int k = std::min(3, static_cast<int>(t));
        const double f = t - k;
        for (int c = 0; c < 3; ++c)
            p[c] = static_cast<uint8_t>(std::lround(stops[k][c] + f * (stops[k + 1][c] - stops[k][c])));
    }
    return out;
}

rgb_image side_by_side(const std::vector<rgb_image>& images, const std::vector<std::string>& labels, unsigned gap) {
    unsigned w = gap, h = 0;
    for (const auto& im : images) {
        w += im.width + gap;
        h = std::max(h, im.height);
    }
    const bool any_label = std::any_of(labels.begin(), labels.end(), [](const std::string& s) { return !s.empty(); });
    const unsigned top = any_label ? gap + glyph_h + 4 : gap;
    rgb_image out(w, h + top + gap, 24);
    unsigned x0 = gap;
    for (std::size_t k = 0; k < images.size(); ++k) {
        const rgb_image& im = images[k];
        if (k < labels.size()) draw_text(out, x0, gap, labels[k], im.width);
        for (unsigned y = 0; y < im.height; ++y) std::copy_n(im.at(0, y), 3 * im.width, out.at(x0, top + y));
        x0 += im.width + gap;
    }
    return out;
}

rgb_image stacked(const std::vector<rgb_image>& rows) {
    unsigned w = 0, h = 0;
    for (const auto& im : rows) {
        w = std::max(w, im.width);
        h += im.height;
    }
    rgb_image out(w, h, 24);
    unsigned y0 = 0;
    for (const auto& im : rows) {
        for (unsigned y = 0; y < im.height; ++y) std::copy_n(im.at(0, y), 3 * im.width, out.at(0, y0 + y));
        y0 += im.height;
    }
    return out;
}

rgb_image heat_map_legend(unsigned width, unsigned height, double full_scale, const std::string& caption) {
    rgb_image out(width, height, 24);
    constexpr unsigned margin = 16, bar_h = 24, ticks = 4;
    if (width < 2 * margin + 2 || height < bar_h + 4 * glyph_h) return out;  // too small to draw: left blank
    const unsigned bar_w = width - 2 * margin, y_bar = (height - bar_h) / 2;
    std::vector<double> ramp(static_cast<std::size_t>(bar_w) * bar_h);
    for (unsigned y = 0; y < bar_h; ++y)
        for (unsigned x = 0; x < bar_w; ++x) ramp[static_cast<std::size_t>(y) * bar_w + x] = full_scale * x / (bar_w - 1);
    const rgb_image bar = heat_map(ramp, bar_w, bar_h, full_scale);
    for (unsigned y = 0; y < bar_h; ++y) std::copy_n(bar.at(0, y), 3 * bar_w, out.at(margin, y_bar + y));
    draw_text(out, margin, y_bar - 2 * glyph_h, caption, bar_w);
    for (unsigned t = 0; t <= ticks; ++t) {
        char label[32];
        std::snprintf(label, sizeof label, "%g", full_scale * t / ticks);
        const unsigned text_w = static_cast<unsigned>(std::string(label).size()) * glyph_advance;
        const unsigned x_tick = margin + (bar_w - 1) * t / ticks;
        const unsigned x_text = std::min(x_tick - std::min(x_tick, text_w / 2), width - text_w);
        for (unsigned y = y_bar + bar_h; y < y_bar + bar_h + 4; ++y) std::fill_n(out.at(x_tick, y), 3, uint8_t{230});
        draw_text(out, x_text, y_bar + bar_h + 7, label, text_w);
    }
    return out;
}

}  // namespace shading::scene
