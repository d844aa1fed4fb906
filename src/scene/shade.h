// The two per-pixel references, double precision, every operation counted (counted.h):
//  (a) Phong with exact cos^n, Blinn's N.H: what users compare against;
//  (b) the same, with the specular term from a specular device's bit-accurate golden model
//      (UA 60553 with the patent's or a tuned generator, the UA 22802 ROM prototype, or our
//      squared-quadratic device: the quadratic at n / 2^k squared k times; or the square-and-multiply
//      device: cos^n over the bits of n).
// So the device's BRDF error is (b) against (a), and an interpolating pipeline's error is measured
// against (b). Both shade with
//   I_c = 255 * (ambient_c + sum over lights with N.L > 0 of I_l,c * (k_d,c * N.L + k_s,c * S))
// where S = max(N.H, 0)^n for (a) and the device's output for (b); images are clamped to [0, 255].
// The specular term is gated by N.L > 0 (no highlight on a surface the light does not reach).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "arith/device_specular.h"  // specular_device, device_config, device_specular (the floor)
#include "formats/fixed_point.h"
#include "scene/raster.h"
#include "scene/scanline.h"

namespace shading::scene {

const char* device_name(specular_device d);
// "patent", "minimax", "rom_matched", "ua22802", "squared", "sqmul"; throws scene_error otherwise.
specular_device parse_device(const std::string& name);
std::vector<std::string> device_names();

// Any specular unit with the devices' interface: (n, Q1.15 cos code, 8-bit k_s*I codes) -> out25..27
// codes (Q9.8). For models that are not scene devices (studies' variants, comparison designs); the
// image is shaded exactly as through device_specular.
using specular_fn =
    std::function<std::array<uint64_t, 3>(unsigned n, uint32_t cos_code, const std::array<uint64_t, 3>& ksi)>;

// A device's operations per specular sample: Fig. 1's datapath for UA 60553, UA 22802 and the tuned
// generators (MUL7, MUL10, MUL12..14; ADD9, ADD11: 5 mul, 2 add); the squared-quadratic device adds
// one multiplication per squaring, k = floor(log2 n) (its generator, like the others', works once per
// frame on RG1); the square-and-multiply device has MUL_P once per square and per multiplication
// (floor(log2 n) + popcount(n) - 1) and MUL12..14, no adder. shade_device charges them per call.
op_counts device_sample_ops(const device_config& dev, unsigned n);

// x^n for an integer n >= 1 by left-to-right binary exponentiation: floor(log2 n) squarings and
// popcount(n) - 1 further multiplications, all counted; exact to double rounding.
cnum pow_int(cnum x, unsigned n);

// One pixel, given its geometry. Values in 8-bit units, not yet clamped.
rgb shade_phong(const pixel_geometry& g, const material& m, const std::vector<light>& lights);
rgb shade_device(const pixel_geometry& g, const material& m, const std::vector<light>& lights,
                 const device_config& dev);
rgb shade_specular(const pixel_geometry& g, const material& m, const std::vector<light>& lights,
                   const specular_fn& unit);

// An image of reals in 8-bit units (clamped to [0, 255], not rounded); empty pixels are 0.
struct shaded_image {
    unsigned width = 0, height = 0;
    std::vector<rgb> value;
    std::vector<uint8_t> covered;
};

// Operation counts over a frame: geometry (barycentrics, normal, V, L, H) and shading (dots, cos^n,
// colour), summed over the covered pixels. The rasteriser's coverage and depth test, shared by every
// path, and per-frame constants (k_d*I, the device's codes, a directional L) are not counted.
struct render_stats {
    op_counts geometry, shading;
    std::size_t pixels = 0;
    double seconds = 0.0;
    op_counts total() const {
        op_counts t = geometry;
        t += shading;
        return t;
    }
};

shaded_image render_phong(const rasterised& r, render_stats* stats = nullptr);
// The scan-line Phong reference: render_phong's shading (exact cos^n) on geometry stepped along each
// span (scanline.h: span_stepper); the same image to rounding. `steps`: where its geometry went.
// walk_edges: run starts walked from the triangle's last point (scanline.h), not evaluated.
shaded_image render_phong_scanline(const rasterised& r, render_stats* stats = nullptr,
                                   stepping_stats* steps = nullptr, bool walk_edges = false);
shaded_image render_device(const rasterised& r, const device_config& dev, render_stats* stats = nullptr);
// Phong 1975's stepped geometry with the specular term through the device (render_device's shading).
shaded_image render_device_scanline(const rasterised& r, const device_config& dev, render_stats* stats = nullptr,
                                    bool walk_edges = false);
shaded_image render_specular(const rasterised& r, const specular_fn& unit, render_stats* stats = nullptr);
// Phong 1975's stepped geometry with the specular term from any unit (render_specular's shading): the
// unit's own operations are its caller's to count (a cost model pricing the device apart).
shaded_image render_specular_scanline(const rasterised& r, const specular_fn& unit, render_stats* stats = nullptr,
                                      bool walk_edges = false);

}  // namespace shading::scene
