// The race: every shading scheme a user would build instead of per-pixel Phong, and ours, on one
// frame, with one cost convention and one error measure.
//
// Schemes (each a golden model with counted arithmetic, counted.h):
//   phong1975        Phong 1975: N stepped along the span, normalised per pixel, exact cos^n (scanline.h)
//   phong1975_device the same geometry, the specular power through the device per pixel
//   gouraud          Gouraud 1971: a colour per vertex through the device, stepped (gouraud.h)
//   fast_phong       Bishop and Weimer 1986: second-order expansion per triangle, the power through the device
//   fast_phong_table the same, the power from a table of 2^10 x 16 bits
//   fast_phong_split the same as fast_phong, a triangle split where its expansion misses a budget
//   lyon             Lyon 1993: Taylor normalisation, the power in the chord N - H (lyon.h)
//   lines            the interpolation paper's raster lines: adaptive length, the sample stage, forward differences
//   cells            ours: biquadratic cells, the rest by the lines (cells.h)
//
// One cost convention, stated once: long operations are multiplications, divisions and square roots
// (counted.h), a covered pixel's share of the frame's (set-ups, run starts, decisions, the device's
// multipliers and the table's build included); `long_ops_rsqrt` counts each normalisation's square
// root and division as one reciprocal square root. Every scheme forms V from Q E - U_P where its
// geometry allows (no division for P); a walker's jump is additions in raster order and a
// multiplication by a small integer otherwise (scanline.h). The rasteriser's coverage, depth test
// and set-up planes are shared by every scheme and not counted.
//
// State: the words a live triangle holds times the most triangles live at once in the scheme's read
// order, plus its fixed stores (scheme_state.h). The frame buffer, shared by all, is not counted, nor
// the device (the same unit in every scheme that has one: docs/devices.md gives its bits).
//
// Error: against exact Phong (scene::render_phong) over the covered pixels, on the frame buffer (the
// scheme's values, 8-bit units, unrounded) and on the 8-bit image (both rounded).
#pragma once

#include <string>
#include <vector>

#include "golden_pipeline/cells.h"
#include "golden_pipeline/pipeline.h"
#include "scene/scheme_state.h"

namespace shading::pipeline {

// The adaptive schemes' settings. frozen_race_config() is the one every case runs at: chosen once on
// the head at 512, n = 20, the scene's light (race.cpp says how), and never per case.
struct race_config {
    plan_config lines;      // the interpolation paper's raster lines
    plan_config cell_lines; // what the cells leave to the lines (cells.h: its length fields unread)
    cell_config cells;
    double fast_phong_budget = 0.0;  // levels: the split variant's budget
    bool walk_edges = true;          // every stepping geometry side walks its triangles (scanline.h)
};
race_config frozen_race_config();

struct race_row {
    std::string scheme;          // phong1975, gouraud, ...
    std::string what;            // a few words
    bool frozen = true;          // false: a setting other than frozen_race_config()'s
    double long_ops = 0.0, long_ops_rsqrt = 0.0;  // a covered pixel
    double adds = 0.0;           // additions a covered pixel
    uint64_t state_bits = 0;
    std::string state;           // what the bits are
    error_stats frame_buffer, image8;  // against exact Phong
    scene::shaded_image image;
};

// Every scheme on the frame (a single directional or point light, one material: frame_constants_of's
// rule for the lines and cells), in the order above; `only`: just these schemes. Throws
// scene::scene_error for a scene the hardware schemes cannot take or an invalid configuration.
std::vector<race_row> run_race(const scene::rasterised& r, const scene::device_config& dev, const race_config& c,
                               const std::vector<std::string>& only = {});
// The schemes' names, in the race's order.
const std::vector<std::string>& race_schemes();

// The 8-bit image's values: each channel rounded to nearest (scene::to_rgb8's rule), empty pixels 0.
scene::shaded_image rounded(const scene::shaded_image& s);

}  // namespace shading::pipeline
