// render_pipeline's PNGs (render_program.h): the images, error heat maps, degree, interval and zone
// maps and the sheet.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render_program.h"

namespace shading::render_program {

namespace {

// A map: each covered pixel gets colour_of(i), darkened by the Phong image's brightness so the face
// stays legible; empty pixels dark grey (as heat_map draws them).
scene::rgb_image shaded_map(const frame& f, const scene::shaded_image& shade,
                            const std::function<std::array<double, 3>(std::size_t)>& colour_of) {
    scene::rgb_image img(f.width, f.height, 40);
    for (unsigned y = 0; y < f.height; ++y)
        for (unsigned x = 0; x < f.width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * f.width + x;
            if (!f.covered[i]) continue;
            const auto& v = shade.value[i];
            const double lum = (0.299 * v[0] + 0.587 * v[1] + 0.114 * v[2]) / 255.0;
            const double k = 0.45 + 0.55 * std::min(1.0, lum);
            const auto c = colour_of(i);
            uint8_t* p = img.at(x, y);
            for (int ch = 0; ch < 3; ++ch) p[ch] = static_cast<uint8_t>(std::lround(std::clamp(c[ch] * k, 0.0, 255.0)));
        }
    return img;
}

// Degree map: exact pixels white, quadratic orange, cubic blue.
std::array<double, 3> degree_colour(uint8_t d) {
    switch (d) {
        case 1: return {235, 235, 235};
        case 2: return {245, 150, 40};
        case 3: return {60, 125, 235};
        default: return {40, 40, 40};
    }
}
// Interval map by log2 of the interval length: exact white, m = 2 red, 3 orange, 4 green, 5 cyan, 6 violet.
std::array<double, 3> length_colour(uint8_t m) {
    switch (m) {
        case 0: return {235, 235, 235};
        case 1: return {250, 120, 160};
        case 2: return {225, 50, 50};
        case 3: return {245, 160, 40};
        case 4: return {80, 195, 80};
        case 5: return {60, 175, 225};
        case 6: return {150, 85, 225};
        default: return {255, 0, 255};
    }
}
// Zone map: other grey, forehead, brows, eyes, nose, cheeks, mouth, chin.
std::array<double, 3> zone_colour(uint8_t z) {
    static constexpr std::array<std::array<double, 3>, zone_count> c{{{150, 150, 150},
                                                                      {90, 170, 235},
                                                                      {150, 95, 60},
                                                                      {60, 200, 200},
                                                                      {235, 90, 60},
                                                                      {245, 190, 110},
                                                                      {215, 60, 150},
                                                                      {120, 200, 80}}};
    return z < zone_count ? c[z] : std::array<double, 3>{255, 0, 255};
}

// Sheets one above the other, left-aligned, on side_by_side's dark background.
scene::rgb_image stack_rows(const std::vector<scene::rgb_image>& rows) {
    unsigned w = 0, h = 0;
    for (const auto& r : rows) {
        w = std::max(w, r.width);
        h += r.height;
    }
    scene::rgb_image img(w, h, 24);
    unsigned y0 = 0;
    for (const auto& r : rows) {
        for (unsigned y = 0; y < r.height; ++y) std::copy_n(r.at(0, y), 3 * r.width, img.at(0, y0 + y));
        y0 += r.height;
    }
    return img;
}

}  // namespace

scene::shaded_image displayed(const scene::shaded_image& img) {
    scene::shaded_image out = img;
    for (auto& v : out.value)
        for (int c = 0; c < 3; ++c) v[c] = std::round(std::clamp(v[c], 0.0, 255.0));
    return out;
}

void write_images(const options& o, render_data& d, staged_output& out) {
    const auto t = std::chrono::steady_clock::now();
    const plan_config& cfg = d.cfg;
    const scene::rasterised& r = d.r;
    const frame& hw = d.hw;
    const plan& p = d.p;
    const scene::shaded_image &phong = d.phong, &hw_img = d.hw_img, &pp_img = d.pp_img, &devref = d.devref;
    const scene::material& mat = d.s.objects.front().mat;
    std::vector<std::string>& written = d.written;
    const unsigned w = r.width, h = r.height;
    const scene::rgb_image a = scene::to_rgb8(phong), b = scene::to_rgb8(hw_img), c = scene::to_rgb8(pp_img);
    const scene::rgb_image e1 = scene::heat_map(scene::abs_error(hw_img, pp_img), w, h, o.error_scale, &hw.covered);
    const scene::rgb_image e2 = scene::heat_map(scene::abs_error(hw_img, phong), w, h, o.error_scale_total, &hw.covered);
    const scene::rgb_image dm = shaded_map(hw, phong, [&](std::size_t i) { return degree_colour(hw.degree[i]); });
    const scene::rgb_image im = shaded_map(hw, phong, [&](std::size_t i) { return length_colour(hw.log2_len[i]); });
    const scene::rgb_image zm = shaded_map(hw, phong, [&](std::size_t i) { return zone_colour(hw.zone[i]); });
    // The interval map marks each interval's first pixel darker, so the intervals can be counted.
    scene::rgb_image im_marked = im;
    for (const auto& j : p.jobs)
        if (j.len > 1)
            for (int ch = 0; ch < 3; ++ch) im_marked.at(j.x0, j.y)[ch] = static_cast<uint8_t>(im.at(j.x0, j.y)[ch] / 2);
    auto save = [&](const scene::rgb_image& img, const std::string& name) {
        scene::save_png(img, out.path(name));
        written.push_back(name);
    };
    save(a, "phong.png");
    save(b, "hardware.png");
    save(c, "per_pixel.png");
    save(scene::to_rgb8(devref), "device_reference.png");
    save(e1, "error_interp.png");
    save(e2, "error_total.png");
    save(dm, "degree_map.png");
    save(im_marked, "interval_map.png");
    save(zm, "zone_map.png");
    char l_hw[96], l_e1[64], l_e2[64];
    const std::string& length = d.maker ? d.maker->length_name : o.length;  // a study's plan under its own name
    std::snprintf(l_hw, sizeof l_hw, "HARDWARE: %s%s, %s, %s, %s", length.c_str(),
                  cfg.length == length_policy::fixed ? (" M=" + std::to_string(cfg.m)).c_str() : "", o.degree.c_str(),
                  o.eval.c_str(), o.device.c_str());
    std::snprintf(l_e1, sizeof l_e1, "VS PER-PIXEL (WHITE = %g)", o.error_scale);
    std::snprintf(l_e2, sizeof l_e2, "VS PHONG (WHITE = %g)", o.error_scale_total);
    save(stack_rows({scene::side_by_side({a, b, dm}, {"PHONG N=" + std::to_string(mat.n), l_hw, "DEGREE"}),
                     scene::side_by_side({e2, e1, im_marked}, {l_e2, l_e1, "INTERVAL LENGTH 2 POWER M"})}),
         "sheet.png");
    d.wall["images"] = seconds_since(t);
}

}  // namespace shading::render_program
