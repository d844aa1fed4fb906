// Where a raster line's colour bends: at each change of triangle along a segment, whether the two
// triangles share an edge (the line crosses it: the Phong normal is continuous, its slope jumps) or
// only a vertex (the line passes the vertex through triangles that no pixel centre on this line
// falls in), and at a shared edge the colour's exact slope jump there. For the edge study
// (edge_split.h): with every jump known, is what is left to a polynomial any smoother?
//
// The colour is real-valued Phong (exact cos^n, scene::shade_phong) of one triangle's attributes
// extended along the line: the planes U_N = sum g_i N_i and U_P = sum g_i P_i over Q = sum g_i
// (raster.h), evaluated at any screen x. The edge is where the plane g of the vertex A has and B
// lacks is 0; the slope on each side a central difference over +-1e-3 pixels.
#pragma once

#include <cstdint>
#include <vector>

#include "edge_split.h"
#include "golden_pipeline/pipeline.h"
#include "scene/mesh.h"
#include "scene/raster.h"

namespace shading::study {

// Phong colour (levels, unclamped) of triangle t's attributes at screen point (xs, ys), pixel
// centres at x + 0.5. Uncounted.
rgb_levels colour_on(const scene::rasterised& r, int32_t t, double xs, double ys);

// How far each vertex normal stands out from its neighbours': |N_v - mean of N_u over the vertices
// u that share a triangle with v| (a discrete Laplacian of the normal field; 0 for a vertex in no
// triangle). Smooth meshes keep it near their curvature times an edge (sphere: a median 0.0025);
// a scan's noisy normals do not (head: 0.075).
std::vector<double> normal_laplacian(const scene::mesh& m);

// Triangles ta and tb (indices into r.setups) are one patch of the mesh: the same triangle, or two of
// one object sharing at least one vertex. Neighbouring pixels on triangles that are not lie across a
// silhouette or a fold.
bool one_patch(const scene::rasterised& r, int32_t ta, int32_t tb);

struct segment_kinks {
    std::vector<uint8_t> vertex_pass;  // per pixel: pixel i - 1 and i share a vertex, not an edge
    std::vector<uint32_t> passed;      // per pixel with vertex_pass: the vertex passed (else 0)
    std::vector<slope_jump> jumps;     // at every shared edge crossed, e in the segment's pixel units
    std::size_t edges = 0, vertices = 0;
};
// Pixels x0..x1 of line y, all covered (a pipeline segment). Triangles that share no vertex (a fold)
// are neither: the planner cuts segments there.
segment_kinks kinks_of(const scene::rasterised& r, unsigned y, unsigned x0, unsigned x1);

}  // namespace shading::study
