// Gouraud shading (H. Gouraud, "Continuous Shading of Curved Surfaces", IEEE Trans. Computers, 1971)
// with the lighting of shade_device: the colour computed once per distinct vertex of a triangle the
// frame covers (the vertex's own normal; V, L and H at its position; the specular term through the
// specular device's golden model) and interpolated over the triangle. Counted (counted.h):
//  - per vertex: V, L, H to `geometry`, shade_device's dots and colour to `shading`, as render_phong;
//  - per triangle: the colour planes sum_i lambda_i C_i (3 channels x 3 coefficients x (3 mul, 2 add))
//    from the rasteriser's screen-space barycentric planes lambda_i (plane_steps.h, not counted);
//  - per pixel: a run start a x + b y + c (2 mul, 2 add a channel) or a step + d a (popcount(d) adds a
//    channel); the interpolation is charged to `geometry`.
// Interpolation is screen-linear, as Gouraud's and the classic scan-line hardware's: C = sum lambda_i
// C_i with lambda_i = w_i g_i (raster.h), no division per pixel (perspective-correct colours would
// need 1 / sum g_i at every pixel). Vertex colours are interpolated unclamped; pixels are clamped to
// [0, 255] like the other references.
#pragma once

#include "arith/device_specular.h"
#include "scene/raster.h"
#include "scene/scheme_state.h"
#include "scene/shade.h"

namespace shading::scene {

// `state`: 12 words a live triangle holds (3 channels x the plane a, b, c and the stepped value), no
// fixed store.
shaded_image render_gouraud(const rasterised& r, const device_config& dev, render_stats* stats = nullptr,
                            scheme_state* state = nullptr);

}  // namespace shading::scene
