// Lyon's reformulation of Phong shading (R. F. Lyon, "Phong Shading Reformulation for Hardware
// Renderer Simplification", Apple Technical Report #43, 1993) as the quadratic-BRDF paper describes
// it (reference/brdf_reference.h: lyon_power), per pixel, every operation counted (counted.h):
//  - geometry: the normal stepped along the span as the scan-line Phong reference steps it (the same
//    planes U_N = sum g_i N_i, U_P and Q = 1/w, set-up, run starts and steps as scanline.h counts
//    them; plane_steps.h), perspective-correct: N = U_N / Q shares the division P = U_P / Q needs
//    (3 mul more; orthographic: N = U_N, no division). N is then normalised with lyon_normalize (no
//    division, no square root); V, L, H as geometry_at derives them (add_view_and_lights).
//  - shading, per light with N.L > 0: the chord D = N - H, x = (n / 2 gamma) D.D, the power
//    max(0, 1 - x)^gamma by log2(gamma) squarings; the colour as shade_phong's. gamma = 2^k: from n
//    (gamma = 0: reference lyon_gamma, the largest power of two not above n) or given.
// The report's own datapath (its Fig. on the title page) takes D = R - L with Phong's reflection
// vector R and the shape f_k(x) = (1 - x/2^k)^(2^k) at x = (n/2) D.D; the quadratic-BRDF paper restates
// it with Blinn's N and H, which is the form here. Its report text past the abstract was not at hand,
// so the Taylor form of 1/sqrt(N.N) below (three terms about N.N = 1) is the paper's description.
#pragma once

#include "scene/raster.h"
#include "scene/scheme_state.h"
#include "scene/shade.h"

namespace shading::scene {

// N times the first three terms of 1/sqrt(s) about s = 1: 1 - u/2 + 3u^2/8, u = N.N - 1 (Horner:
// 1 + u (3u/8 - 1/2)). 8 mul, 5 add; no division, no square root. Relative error of the length
// about -5u^3/16 (the next term).
cvec3 lyon_normalize(const cvec3& n);

// `gamma`: 0 picks it from each material's n (reference lyon_gamma), else a power of two (throws
// scene_error otherwise). `state`: 4 words per stepped component a live triangle holds (the plane
// a, b, c and the stepped value: U_N, and U_P, Q where a position is needed; 28 with a perspective
// camera), no fixed store.
shaded_image render_lyon(const rasterised& r, render_stats* stats = nullptr, scheme_state* state = nullptr,
                         unsigned gamma = 0 /*0: from n*/);

}  // namespace shading::scene
