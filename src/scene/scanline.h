// Scan-line geometry: the interpolated attributes stepped along the raster line with additions, as
// Phong's own renderer does (B. T. Phong, "Illumination for Computer Generated Pictures", CACM 1975:
// the normal interpolated along the span and normalised at every pixel), instead of geometry_at's
// barycentrics from scratch at every pixel. Every
// operation counted (counted.h), so the scan-line Phong reference and the hardware's geometry side
// are charged what a stepping geometry unit does:
//
//  - triangle set-up, once per triangle a frame uses: the screen-space planes of each stepped
//    quantity, Q = 1/w = sum_i g_i (2 adds per plane coefficient: 6 adds), U_N = sum_i g_i N_i and,
//    where a position is needed (a perspective camera or a point light), U_P = sum_i g_i P_i
//    (per component and coefficient 3 mul, 2 add: 9 mul, 6 add per component), with g_i = the
//    rasteriser's plane of lambda_i / w_i (raster.h: its set-up, shared by every path, is not counted).
//  - run start, where a point is not on the triangle of the point before it on the line (or lies
//    left of it): every stepped component evaluated at the pixel centre, a x + b y + c (2 mul, 2 add).
//  - step, to a point d pixels right of the point before on the same triangle: each component + d a
//    (or, for a point read down a column, d lines below it: + d b);
//    d a is a shift of the x gradient when d is a power of two, a shift-and-add network otherwise:
//    popcount(d) adds per component.
//  - edge walking (optional, `walk_edges`): a scan-line renderer's active-edge walker carries each
//    triangle's values from line to line, so only a triangle's first run starts from a x + b y + c;
//    every later run start is reached from the triangle's last point (x', y') by additions:
//    (y - y') b, one add a line per component (down, or up where lines are not rendered top to
//    bottom), and (x - x') a, popcount(|x - x'|) adds, while the points come in raster order (the
//    adds are a lower estimate of a walker that steps every active triangle on every line); once
//    they leave it (the cells' bands and levels), a jump: (y - y') b and (x - x') a a multiplication
//    by a small integer and an add each.
//  - per point: N = normalize(U_N) (U_N / Q points the same way, so no division for N); with a
//    perspective camera V = normalize(Q E - U_P) (3 mul, 3 add: Q E - U_P = Q (E - P), so P = U_P / Q
//    is never formed), a point light's L the same; H as geometry_at. Each normalize is one 1/sqrt
//    pair (counted.h: a square root and a division, or one reciprocal square root).
//
// The values equal geometry_at's to rounding (different association): the Phong 1975 image equals
// the per-pixel one within ~1e-12 levels. Positions, N, V, L and H as geometry_at.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/raster.h"

namespace shading::scene {

// Where the counts of a stepping geometry unit went (all of them are in the op_counts given to at()).
struct stepping_stats {
    std::size_t triangle_setups = 0, run_starts = 0, steps = 0, points = 0;
    std::size_t walked_starts = 0;  // run starts reached by edge walking (counted in run_starts too)
};

class span_stepper {
public:
    // The rasterised frame must outlive the stepper.
    // walk_edges: run starts on a triangle already visited are walked to, not evaluated (above).
    explicit span_stepper(const rasterised& r, bool walk_edges = false);
    // The geometry at covered pixel (x, y), charged to `ops` (nullptr: uncounted). Points of one line
    // in increasing x step; anything else starts a run. With `down`, the point steps instead from the
    // point before it when that lies above it in the same column on the same triangle: + d b per
    // component, d lines down (the same adds, the other gradient; for runs read down a column).
    pixel_geometry at(unsigned x, unsigned y, op_counts* ops, bool down = false);
    const stepping_stats& stats() const { return stats_; }
    // The words a live triangle holds (scheme_state.h): per stepped component (U_N, and U_P and Q
    // where a position is needed) its plane a, b, c and its stepped value: 28 with a perspective camera.
    unsigned words_per_triangle() const { return 4u * (3u + (need_p_ ? 3u : 0u) + (perspective_ ? 1u : 0u)); }

private:
    // Per stepped component: the plane a x + b y + c.
    struct plane3 {
        double a = 0.0, b = 0.0, c = 0.0;
    };
    struct gradients {
        bool ready = false;
        plane3 q;
        std::array<plane3, 3> n, p;
        // The triangle's last point and its stepped values (edge walking).
        bool visited = false;
        unsigned last_x = 0, last_y = 0;
        double last_q = 0.0;
        std::array<double, 3> last_un{}, last_up{};
    };
    void setup(int32_t t, op_counts* ops);

    const rasterised& r_;
    bool need_p_ = false, perspective_ = false, walk_ = false;
    std::vector<gradients> grad_;
    // The current run.
    int32_t tri_ = -1;
    unsigned x_ = 0, y_ = 0;
    cnum q_;
    cvec3 un_, up_;
    bool raster_ = true;  // every point so far came after the one before it in raster order
    stepping_stats stats_;
};

}  // namespace shading::scene
