// Bishop and Weimer, "Fast Phong Shading" (SIGGRAPH 1986): the shader a user builds instead of a
// specular unit, as a peer of the per-pixel and scan-line Phong references (shade.h), every operation
// counted (counted.h). Per triangle, each shading expression A.N/|N| (A = L: the diffuse term; A = H:
// the specular argument N.H) is expanded in a second-order Taylor series in screen x, y,
//   f(x, y) ~ T5 x^2 + T4 x y + T3 y^2 + T2 x + T1 y + T0   (x, y offsets from the expansion point),
// and evaluated along each span by forward differences: two additions a pixel per expression. The
// power S = spec^n is taken once a pixel: through a specular device's golden model (device_specular)
// or through a table of 2^table_bits 16-bit entries per exponent, built per frame.
//
// Choices, stated:
//  - N is the rasteriser's unnormalised perspective-correct normal U_N = sum g_i N_i, which is linear
//    in screen x, y (raster.h: g_i = lambda_i / w_i); the true normal U_N / Q points the same way, so
//    A.N/|N| = A.U_N/|U_N| exactly, with U_N linear: Bishop and Weimer's p / sqrt(q) (p linear, q
//    quadratic) holds under perspective too, and nothing of the normal is lost to the camera.
//  - Expansion point: the triangle's screen centroid (the mean of its screen vertices), not a vertex:
//    the dropped third-order term grows with the cube of the distance, and the centroid's farthest
//    point is a vertex at 2/3 of a median, against a whole edge from a vertex (equilateral: s / sqrt 3
//    against s, about 5 times less third-order error at the far point).
//  - V and H: their model has viewer and light at infinity (H constant). Our cameras are perspective,
//    so V = normalize(eye - P) and H = normalize(L + V) are taken once per triangle (or sub-triangle)
//    at its centroid's perspective-correct position P, and held for all its pixels; a point light's L
//    likewise. Orthographic camera and directional lights: H is a frame constant (not counted).
//  - The screen vertices are the rasteriser's (recovered from its planes: vertex i where
//    g_j = g_k = 0); like its coverage, shared by every path, not counted.
//
// Counts (the hand counts in testbenches/scene/test_fast_phong.cpp), with E = 2 expressions a light:
//  - triangle set-up (once per triangle a frame shows): U_N's screen gradients u_x, u_y (18 mul, 12 add)
//    and their products u_x.u_x, u_x.u_y, u_y.u_y (9 mul, 6 add);
//  - part set-up (the triangle, or each of its sub-triangles, and each parent judged before a split):
//    centroid, U_N there, P, V, H where needed, 1/sqrt(U.U) (one sqrt, one div), the expansion's
//    shared terms and per expression its six coefficients; halvings and doublings are shifts, free;
//  - run start (a pixel not one right of the last pixel on the same part): the offsets (2 add) and
//    per expression the polynomial by Horner's rule and its first difference: 5 mul, 7 add;
//  - step: per expression F += D, D += 2 T5: 2 add;
//  - per pixel shading: the N.L > 0 gate and max(N.H, 0) (2 cmp a light), per channel
//    255 k_d I * d + spec + acc (1 mul, 2 add); the table path adds k_s I * S (3 mul) and a look-up
//    (counted in fast_phong_stats::lookups, not an arithmetic operation); the device path's output
//    is already scaled by its k_s I codes. The table's build (2^table_bits powers per exponent, once
//    per frame) is counted in the shading counts and in fast_phong_stats::table_build.
//
// Split variant (budget > 0): a triangle's expansion misses the budget when the estimate of its
// error, from what its set-up computes, exceeds `budget` 8-bit levels. The estimate, per light:
//   255 max_c(k_d I) (D + |dL|) + 255 max_c(k_s I) n s^(n-1) (S + |dH|),
// D and S the largest |third-order term| (the first one the expansion drops) of the diffuse and
// specular expressions at the part's three vertices and three edge midpoints (the cubic grows as the
// cube of the distance from the centroid, so these far points carry it); dL and dH how far the held
// L and H stray at the vertices, to first order (d / |eye - P_c| for V, d / |light - P_c| for a point
// light's L, their sum over |L + V| for H, d the largest world distance of a vertex from the centroid's
// P_c: zero when orthographic with directional lights); s the largest expanded N.H at those points and
// the centroid, clamped to [0, 1] (n s^(n-1): the slope of the power there). An estimate, not a bound:
// higher orders are not in it, and max_depth caps the splitting. A part that misses is split into
// four through its edge midpoints (corners 0, 1, 2, then the middle; a midpoint's world position
// perspective-correct), recursively to max_depth; each part gets its own expansion (its own centroid,
// U_N, H), and every set-up, judged or kept, is counted. Pixels map to the leaf parts by their
// screen barycentrics; each part is a triangle to the rasteriser (its coverage not counted), so a
// span crossing parts pays a run start at each.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/scheme_state.h"
#include "scene/shade.h"

namespace shading::scene {

enum class specular_path { device, table };

struct fast_phong_config {
    specular_path power = specular_path::device;
    unsigned table_bits = 10;    // table path: 2^table_bits entries per exponent, 1..16
    double budget = 0.0;         // estimated error in 8-bit levels a part may keep; 0: no split
    unsigned max_depth = 4;      // split levels at most (up to 4^max_depth parts a triangle), 0..8
};

// Where a frame's work went. setup + run_start + step = render_stats::geometry.
struct fast_phong_stats {
    std::size_t triangles = 0;        // triangles set up (those with a visible pixel)
    std::size_t setups = 0;           // part set-ups: the parts kept and every parent judged and split
    std::size_t parts = 0;            // the parts shaded from (leaves): triangles when nothing splits
    std::size_t split_triangles = 0;  // triangles split at least once
    std::size_t max_parts = 0;        // the most parts one triangle was split into
    std::size_t run_starts = 0, steps = 0, lookups = 0;
    op_counts setup, run_start, step, table_build;
};

// T5 x^2 + T4 x y + T3 y^2 + T2 x + T1 y + T0.
struct quadratic {
    double t5 = 0.0, t4 = 0.0, t3 = 0.0, t2 = 0.0, t1 = 0.0, t0 = 0.0;
    double at(double x, double y) const { return ((t5 * x + t4 * y + t2) * x + (t3 * y + t1) * y + t0); }
};

// One expression's expansion: the quadratic and the third-order coefficients of x^3, x^2 y, x y^2, y^3.
struct expansion {
    quadratic q;
    std::array<double, 4> third{};
};

// f(x, y) = A.U / |U| with U(x, y) = u0 + u_x x + u_y y, about (0, 0), for every A in `dirs`: the
// second-order Taylor coefficients and, with third_order, the third-order ones, counted on u0's counts.
// Zero when |u0| = 0.
std::vector<expansion> expand_normalised(const cvec3& u0, const cvec3& ux, const cvec3& uy,
                                         const std::vector<cvec3>& dirs, bool third_order);

// The quadratic along one line: at x = dx0, dx0 + 1, ..., `count` points, y = dy, by forward
// differences: a run start (5 mul, 7 add: Horner and the first difference), then 2 adds a point.
std::vector<double> forward_differences(const quadratic& q, double dx0, double dy, unsigned count, op_counts* ops);

// The table path's power table: entry i = round(((i + 1/2) / 2^bits)^n * 65535), the power at its
// bin's middle in 16 bits (65535 = 1.0); indexed by the top `bits` fraction bits of max(s, 0)
// (s >= 1: the last entry). Each entry's power by pow_int, counted on `ops`.
struct power_table {
    unsigned n = 0, bits = 0;
    std::vector<uint16_t> entry;
    std::size_t index(double s) const;
    double value(double s) const { return entry[index(s)] / 65535.0; }
};
power_table make_power_table(unsigned n, unsigned bits, op_counts* ops);

// The fast Phong image, shaded as shade.h's references: I_c = 255 (ambient + sum over lights with
// d > 0 of I (k_d d + k_s S)), d and s the expanded expressions, S = the device's or the table's
// power of max(s, 0). Throws scene_error for table_bits outside 1..16, a budget negative or not a
// number, or max_depth above 8. `state`: per live triangle, the words of all its parts
// (per part 2 + 8 E: the expansion point, E x 6 coefficients, E x (value, difference)); the table
// path's tables (2^table_bits x 16 bits per exponent) in fixed.
shaded_image render_fast_phong(const rasterised& r, const device_config& dev, const fast_phong_config& c,
                               render_stats* stats = nullptr, scheme_state* state = nullptr,
                               fast_phong_stats* fs = nullptr);

}  // namespace shading::scene
