// The race (race.h): every scheme on one frame, counted and measured alike.
#include "golden_pipeline/race.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "scene/fast_phong.h"
#include "scene/gouraud.h"
#include "scene/lyon.h"
#include "scene/shade.h"

namespace shading::pipeline {

// Chosen once on the head at 512, n = 20, the scene's light, the square-and-multiply device, each
// the largest setting on its grid whose frame meets the race's error (docs/race.md, "The frozen
// configuration", gives the command): total NMSE <= 1e-5 against exact Phong for the lines (length
// tolerance on a grid of 0.05 levels: 1.80) and the cells (T on a grid of 0.05: 0.85); for the split
// fast Phong, no pixel more than 4 levels off (its budget on the powers of two: 8), what splitting
// buys that the unsplit expansion, already within 1e-5, lacks.
race_config frozen_race_config() {
    race_config c;
    c.lines.length = length_policy::adaptive;
    c.lines.degree = degree_policy::cubic;
    c.lines.length_tol = 1.80;
    c.lines.m_max = 5;
    c.lines.above_slack = 2;
    c.lines.split_at_check = true;
    c.lines.carry_samples = true;
    c.lines.eval = evaluator::fd;
    c.lines.walk_edges = true;
    c.cell_lines.eval = evaluator::fd;
    c.cell_lines.length = length_policy::adaptive;  // the pipeline's fd channel for any m per interval
    c.cell_lines.walk_edges = true;
    c.cells.tol = 0.85;
    c.fast_phong_budget = 8.0;
    return c;
}

const std::vector<std::string>& race_schemes() {
    static const std::vector<std::string> names{"phong1975", "phong1975_device", "gouraud", "fast_phong",
                                                "fast_phong_table", "fast_phong_split", "lyon", "lines", "cells"};
    return names;
}

scene::shaded_image rounded(const scene::shaded_image& s) {
    scene::shaded_image out = s;
    for (auto& v : out.value)
        for (int ch = 0; ch < 3; ++ch) v[ch] = std::round(std::clamp(v[ch], 0.0, 255.0));
    return out;
}

namespace {

std::string words_text(uint64_t live, unsigned words) {
    return std::to_string(live) + " live triangles x " + std::to_string(words) + " words";
}

// What a frame's rows share: the reference, the covered pixels in raster order, the frame constants.
struct race_frame {
    const scene::rasterised& r;
    const scene::device_config& dev;
    frame_constants k;
    scene::shaded_image phong, phong8;
    std::size_t pixels = 0;
    uint64_t live_raster = 0;  // the most triangles live at once in raster order
    unsigned stepped_words = 0;

    race_frame(const scene::rasterised& rr, const scene::device_config& d)
        : r(rr), dev(d), k(frame_constants_of(*rr.src)), phong(scene::render_phong(rr)), phong8(rounded(phong)) {
        std::vector<std::array<unsigned, 2>> raster;
        for (unsigned y = 0; y < r.height; ++y)
            for (unsigned x = 0; x < r.width; ++x)
                if (r.covered(x, y)) raster.push_back({x, y});
        pixels = raster.size();
        live_raster = walker_live_triangles(r, raster);
        stepped_words = scene::span_stepper(r).words_per_triangle();
    }

    race_row row(const std::string& scheme, const std::string& what, const scene::op_counts& ops, uint64_t bits,
                 const std::string& state, scene::shaded_image img) const {
        race_row out;
        out.scheme = scheme;
        out.what = what;
        const double px = pixels ? double(pixels) : 1.0;
        out.long_ops = double(ops.long_ops()) / px;
        out.long_ops_rsqrt = double(ops.long_ops_rsqrt()) / px;
        out.adds = double(ops.add) / px;
        out.state_bits = bits;
        out.state = state;
        out.frame_buffer = compare(img, phong);
        out.image8 = compare(rounded(img), phong8);
        out.image = std::move(img);
        return out;
    }
};

race_row stepped_row(const race_frame& f, bool device, bool walk) {
    scene::render_stats st;
    scene::shaded_image img = device ? scene::render_device_scanline(f.r, f.dev, &st, walk)
                                     : scene::render_phong_scanline(f.r, &st, nullptr, walk);
    const uint64_t bits = f.live_raster * f.stepped_words * uint64_t(scene::state_word_bits);
    return f.row(device ? "phong1975_device" : "phong1975",
                 device ? "Phong 1975, the power through the device" : "Phong 1975: N stepped, normalised, exact cos^n",
                 st.total(), bits, words_text(f.live_raster, f.stepped_words), std::move(img));
}

race_row peer_row(const race_frame& f, const std::string& scheme, const std::string& what,
                  const std::function<scene::shaded_image(scene::render_stats*, scene::scheme_state*)>& render) {
    scene::render_stats st;
    scene::scheme_state state;
    scene::shaded_image img = render(&st, &state);
    std::string text = words_text(f.live_raster, state.per_triangle_words);
    for (const auto& item : state.fixed)
        text += " + " + item.what + " " + std::to_string(item.words) + " x " + std::to_string(item.bits);
    return f.row(scheme, what, st.total(), state.bits(f.live_raster), text, std::move(img));
}

race_row lines_row(const race_frame& f, const race_config& c) {
    const plan p = make_plan(f.r, f.k, f.dev, c.lines);
    const frame fr = golden_frame(p, f.k, f.dev, c.lines);
    const hardware_counts h = hardware_ops(p, c.lines, f.dev, f.k.n);
    const uint64_t live = walker_live_triangles(f.r, p.points);
    uint64_t bits = live * f.stepped_words * uint64_t(scene::state_word_bits);
    std::string text = words_text(live, f.stepped_words);
    if (c.lines.above_slack >= 0) {
        // The line above's interval level per pixel, m in 0..m_max: 3 bits.
        bits += uint64_t(f.r.width) * 3;
        text += " + line buffer " + std::to_string(f.r.width) + " x 3";
    }
    if (c.lines.carry_samples) {
        bits += 3 * 16;  // the sample stage's last-sample registers
        text += " + last sample 3 x 16";
    }
    return f.row("lines", "the interpolation paper's raster lines", h.total(), bits, text, to_image(fr));
}

race_row cells_row(const race_frame& f, const race_config& c) {
    const cell_plan p = make_cell_plan(f.r, f.k, f.dev, c.cell_lines, c.cells);
    const frame fr = golden_cell_frame(p, f.k, f.dev, c.cell_lines);
    const cell_counts n = cell_ops(f.r, p, f.dev, f.k.n, c.walk_edges);
    scene::op_counts ops = n.geometry;
    ops += n.colours;
    ops += p.decision;
    const uint64_t live = walker_live_triangles(f.r, p.points);
    // The band buffer: a band's s_max + 1 lines of colour samples (3 x 16 bits), read level by level
    // before its cells decide.
    const uint64_t band = uint64_t(c.cells.s_max + 1) * f.r.width;
    const uint64_t bits = live * f.stepped_words * uint64_t(scene::state_word_bits) + band * 48;
    return f.row("cells", "ours: biquadratic cells, the rest by the lines", ops, bits,
                 words_text(live, f.stepped_words) + " + band buffer " + std::to_string(band) + " x 48", to_image(fr));
}

}  // namespace

std::vector<race_row> run_race(const scene::rasterised& r, const scene::device_config& dev, const race_config& c,
                               const std::vector<std::string>& only) {
    validate(c.lines);
    validate(c.cell_lines);
    validate(c.cells);
    for (const std::string& s : only)
        if (std::find(race_schemes().begin(), race_schemes().end(), s) == race_schemes().end())
            throw scene::scene_error("race: no scheme '" + s + "'");
    const race_frame f(r, dev);
    auto wanted = [&only](const char* s) { return only.empty() || std::find(only.begin(), only.end(), s) != only.end(); };
    std::vector<race_row> rows;
    if (wanted("phong1975")) rows.push_back(stepped_row(f, false, c.walk_edges));
    if (wanted("phong1975_device")) rows.push_back(stepped_row(f, true, c.walk_edges));
    if (wanted("gouraud"))
        rows.push_back(peer_row(f, "gouraud", "Gouraud 1971: a colour per vertex, stepped",
                                [&](scene::render_stats* st, scene::scheme_state* s) {
                                    return scene::render_gouraud(r, dev, st, s);
                                }));
    const std::array<std::array<const char*, 2>, 3> fast{{{"fast_phong", "Bishop-Weimer 1986, the power through the device"},
                                                          {"fast_phong_table", "Bishop-Weimer 1986, a 2^10 x 16 power table"},
                                                          {"fast_phong_split", "Bishop-Weimer 1986, split to a budget"}}};
    for (std::size_t i = 0; i < fast.size(); ++i) {
        if (!wanted(fast[i][0])) continue;
        scene::fast_phong_config fc;
        fc.power = i == 1 ? scene::specular_path::table : scene::specular_path::device;
        fc.budget = i == 2 ? c.fast_phong_budget : 0.0;
        rows.push_back(peer_row(f, fast[i][0], fast[i][1], [&](scene::render_stats* st, scene::scheme_state* s) {
            return scene::render_fast_phong(r, dev, fc, st, s);
        }));
    }
    if (wanted("lyon"))
        rows.push_back(peer_row(f, "lyon", "Lyon 1993: Taylor normalisation, the power in the chord",
                                [&](scene::render_stats* st, scene::scheme_state* s) { return scene::render_lyon(r, st, s); }));
    if (wanted("lines")) rows.push_back(lines_row(f, c));
    if (wanted("cells")) rows.push_back(cells_row(f, c));
    return rows;
}

}  // namespace shading::pipeline
