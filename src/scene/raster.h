// Scan-line rasteriser with a depth buffer. Per pixel it keeps the nearest surface's view depth,
// triangle and object; per raster line it lists the visible spans and the places where the visible
// surface jumps (coverage edges, a change of object, a depth step). geometry_at() gives the
// interpolated geometry at any covered pixel: position, normal (perspective-correct barycentric
// interpolation of the vertex normals, then renormalised), V, and L and H per light, all in counted
// arithmetic (counted.h) so the references' per-pixel cost is measured.
//
// Conventions: pixel (x, y), y = 0 the top line; the pixel centre (x + 0.5, y + 0.5) is sampled.
// A triangle covers the pixels whose centres lie inside it, half-open on the right and bottom edges,
// so two triangles sharing an edge never both cover a pixel. Triangles with a vertex nearer than
// the camera's z_near are dropped (no clipping: the built-in cameras keep every mesh in front).
// No back-face culling: the depth buffer alone decides visibility (the head scan is open at the neck).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "scene/counted.h"
#include "scene/world.h"

namespace shading::scene {

// A triangle after set-up: per vertex i, the plane g_i(x, y) = a x + b y + c of lambda_i / w_i,
// where lambda_i is the screen-space barycentric and w_i the vertex's clip w (1 when orthographic).
// The perspective-correct barycentrics are b_i = g_i / (g_0 + g_1 + g_2).
struct triangle_setup {
    uint32_t object;
    uint32_t triangle;  // index into the object's mesh.triangles
    std::array<glm::dvec3, 3> plane;
};

struct rasterised {
    const world* src = nullptr;
    unsigned width = 0, height = 0;
    std::vector<double> depth;         // view depth along the camera's axis; +inf where empty
    std::vector<int32_t> tri;          // index into setups, -1 where empty
    std::vector<triangle_setup> setups;
    glm::dvec3 eye{0.0};               // camera position (world)
    glm::dvec3 view_dir{0.0};          // unit vector towards the camera (orthographic V)
    std::size_t index(unsigned x, unsigned y) const { return static_cast<std::size_t>(y) * width + x; }
    bool covered(unsigned x, unsigned y) const { return tri[index(x, y)] >= 0; }
    int32_t object_at(unsigned x, unsigned y) const {
        const int32_t t = tri[index(x, y)];
        return t < 0 ? -1 : static_cast<int32_t>(setups[static_cast<std::size_t>(t)].object);
    }
    std::size_t covered_pixels() const;
};

// The scene must outlive the result (it points at it). Throws scene_error on an invalid scene.
rasterised rasterise(const world& s);

// The frame transposed: pixel (x, y) of the result is pixel (y, x) of r, its lines r's columns; each
// set-up plane a x + b y + c becomes b x + a y + c. geometry_at(transposed(r), y, x) equals
// geometry_at(r, x, y) bit for bit (the two products are added in the other order, which IEEE
// addition does not see), so a planner written for raster lines runs down columns on it unchanged.
rasterised transposed(const rasterised& r);

// A maximal run of covered pixels [x_begin, x_end) on one raster line.
struct span {
    unsigned x_begin, x_end;
};
std::vector<span> line_spans(const rasterised& r, unsigned y);

// Where the visible surface jumps between pixel x - 1 and pixel x on line y (x = width: after the
// last pixel). Several kinds may hold at one place; they are OR-ed.
enum discontinuity_kind : unsigned {
    coverage_begin = 1u,  // x - 1 empty (or x = 0), x covered
    coverage_end = 2u,    // x - 1 covered, x empty (or x = width)
    object_change = 4u,   // both covered, different objects (meshes)
    depth_step = 8u,      // both covered, |depth(x) - depth(x-1)| beyond the threshold
};
struct discontinuity {
    unsigned x;
    unsigned kinds;
};
// `depth_threshold`: in world units (the head scan is about 0.45 units wide; 0.02 separates a nose
// from the cheek behind it at 256 pixels without firing on the skin's slope).
std::vector<discontinuity> line_discontinuities(const rasterised& r, unsigned y, double depth_threshold);

// The interpolated geometry at a covered pixel, as counted numbers charged to `ops`.
struct pixel_geometry {
    uint32_t object = 0;
    cvec3 p, n, v;       // position, unit normal, unit vector to the eye
    std::vector<cvec3> l, h;  // per light: unit L, unit Blinn half vector H = (L + V)/|L + V|
};
// Precondition: r.covered(x, y). `ops` may be nullptr: the same values, uncounted (e.g. for a
// pipeline that reads N.L and N.H at its sample points: dot(g.n, g.l[i]), dot(g.n, g.h[i])).
pixel_geometry geometry_at(const rasterised& r, unsigned x, unsigned y, op_counts* ops);
// V, then L and H for every light, from g.p (set first when the camera is perspective or a light is
// a point): the per-pixel geometry and the scan-line stepper (scanline.h) share it, so both
// baselines derive the shading vectors with the same counted operations.
void add_view_and_lights(const rasterised& r, pixel_geometry& g, op_counts* ops);
// The same with the unit vector from the point towards a world position e (the eye, a point light)
// given by `towards(e)`, for a unit that forms it without P (scanline.h: from Q E - U_P).
void add_view_and_lights(const rasterised& r, pixel_geometry& g, op_counts* ops,
                         const std::function<cvec3(const glm::dvec3&)>& towards);

}  // namespace shading::scene
