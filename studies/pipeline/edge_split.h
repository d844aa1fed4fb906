// Where a polynomial through a raster line's samples misses: inside one triangle, or across a
// triangle's edge. Within a triangle the Phong normal (its vertex normals interpolated, then
// normalised) is a smooth function of x along the line, so the colour is too; across an edge the
// normal is continuous but its slope jumps, and so does the colour's. A polynomial over a gap that
// spans an edge meets that kink whatever its degree.
//
// Samples every h pixels along a segment (pipeline::line_segments: no discontinuity inside), each
// gap between two samples reconstructed by one of three real-valued rules through the same samples,
// so every rule costs the same geometry points:
//  - linear: the two samples of the gap;
//  - quadratic: the samples in pairs of gaps, t = 0, 1/2, 1 (the interpolation paper's quadratic
//    with the shared sample carried: 2 new points per 2h pixels); a last single gap takes the
//    quadratic through the sample before it (the linear one if there is none);
//  - cubic: the four samples nearest the gap (one either side where the segment has them).
// Pixels after the last sample are exact (each its own point). Real-valued: the hardware's rounding
// (below 0.01 levels) is not modelled; it changes none of the shares this measures.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "levels.h"

namespace shading::study {

enum class reconstruction { linear, quadratic, cubic };
const char* reconstruction_name(reconstruction k);

// One segment's pixels rebuilt from samples every h pixels (h >= 1), and the points it used (the
// samples and the exact pixels).
std::vector<rgb_levels> reconstruct(const std::vector<rgb_levels>& v, unsigned h, reconstruction k,
                                    std::size_t* points);

// A kink: the colour's slope jumps by s (levels per pixel, per channel) at e (pixel units of the
// segment, pixel 0 at 0; between two pixels), where the line crosses a triangle edge.
struct slope_jump {
    double e;
    rgb_levels s;
};
// The same reconstruction with the kinks taken out first: v - sum_j s_j max(0, x - e_j) rebuilt from
// its samples, the ramps added back. With every slope jump known, what is left to a polynomial is
// the colour's curvature.
std::vector<rgb_levels> reconstruct_ramped(const std::vector<rgb_levels>& v, const std::vector<slope_jump>& jumps,
                                           unsigned h, reconstruction k, std::size_t* points);

// The squared error of a reconstruction, split by where it lies. The pixels of gap g (g h .. g h +
// h - 1) are "within" when they and the gap's closing sample (g h + h) lie on one triangle, else
// "crossing"; crossing gaps in which the line passes a mesh vertex (vertex_pass[i]: pixels i - 1 and
// i lie on triangles that share one vertex, not an edge, for some i in g h + 1 .. g h + h) are also
// counted "past a vertex". The last sample and the pixels after it are exact (no error, in no part).
struct edge_split {
    std::size_t pixels_within = 0, pixels_crossing = 0, pixels_exact = 0, points = 0;
    std::size_t pixels_past_vertex = 0;  // part of pixels_crossing
    double se_within = 0.0, se_crossing = 0.0;  // squared error, 8-bit levels squared, three channels
    double se_past_vertex = 0.0;                // part of se_crossing
    double ref2 = 0.0;                          // the reference's sum of squares (the NMSE's denominator)
    edge_split& operator+=(const edge_split& o);
    std::size_t interpolated() const { return pixels_within + pixels_crossing; }
    std::size_t pixels() const { return interpolated() + pixels_exact; }
};
// v: the segment's reference colours (levels), tri: its pixels' triangles (the same length);
// vertex_pass: empty (no pass) or the same length; jumps: null, or the kinks to take out first
// (reconstruct_ramped).
edge_split split_errors(const std::vector<rgb_levels>& v, const std::vector<int32_t>& tri, unsigned h,
                        reconstruction k, const std::vector<uint8_t>& vertex_pass = {},
                        const std::vector<slope_jump>* jumps = nullptr);

// Every other line (or column) rebuilt from the lines either side: at each pixel of an odd line
// (across_lines) or an odd column (along the lines), the mean of its two neighbours one pixel away,
// the linear rule at spacing 2 in either direction. Counted only where the three pixels' triangles
// are one patch of the mesh (one_patch holds for the middle one and each neighbour), so no
// silhouette or fold is bridged; the other pixels of those lines count as exact. colour and tri are
// row-major, width x height, tri < 0 uncovered; ref2 sums every covered pixel's reference.
struct midpoint_error {
    std::size_t pixels = 0;  // rebuilt
    double se = 0.0, ref2 = 0.0;
};
midpoint_error midpoint_errors(const std::vector<rgb_levels>& colour, const std::vector<int32_t>& tri, unsigned width,
                               unsigned height, bool across_lines,
                               const std::function<bool(int32_t, int32_t)>& one_patch);

// A line predicted from the lines either side, its own samples correcting the prediction: on each
// odd line, in runs of pixels whose triangles and those above and below are one patch (one_patch, as
// midpoint_errors; a run also ends where two neighbours on the line are not), the residual
// c - (above + below) / 2 sampled every h pixels and rebuilt by `rule` (reconstruct: the same samples,
// the pixels after a run's last sample exact), the mean added back; against the same samples rebuilding
// the colour directly. The lines either side are exact (the reference's): what the prediction could
// give a second pass over a frame whose even lines are done. se sums the odd lines' runs; ref2 every
// covered pixel, so se / ref2 is their part of the image's NMSE.
struct predicted_lines {
    std::size_t pixels = 0, points = 0;
    double se_direct = 0.0, se_predicted = 0.0, ref2 = 0.0;
};
predicted_lines odd_lines_predicted(const std::vector<rgb_levels>& colour, const std::vector<int32_t>& tri,
                                    unsigned width, unsigned height, unsigned h, reconstruction rule,
                                    const std::function<bool(int32_t, int32_t)>& one_patch);

}  // namespace shading::study
