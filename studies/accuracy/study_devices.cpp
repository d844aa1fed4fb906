#include "study_devices.h"

#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "arith/ua22802_arith.h"
#include "arith/ua60553_tuned_arith.h"
#include "formats/sqmul_formats.h"
#include "formats/squared_formats.h"
#include "formats/ua22802_formats.h"
#include "formats/ua60553_formats.h"
#include "study_metrics.h"

namespace shading::study {

namespace {
constexpr auto sat = overflow_mode::saturate;

scene::specular_fn scene_device(scene::specular_device d) {
    return [d](unsigned n, uint32_t code, const std::array<uint64_t, 3>& ksi) {
        return scene::device_specular({d, sat}, n, code, ksi);
    };
}
}  // namespace

std::vector<study_device> study_devices() {
    return {
        {"rom", "UA 22802 ROM device (Q10.6 a, bit-accurate)",
         [](unsigned n, uint64_t code) { return datapath_brdf(golden_a_rom(n), ua22802::a_fmt.frac, code); },
         scene_device(scene::specular_device::ua22802)},
        {"patent", "UA 60553, patent a = 0.7890625 n + 0.5 (bit-accurate)",
         [](unsigned n, uint64_t code) {
             return datapath_brdf(golden_a_linear(n, ua60553::patent), ua60553::a_fmt.frac, code);
         },
         scene_device(scene::specular_device::patent)},
        {"minimax", "UA 60553 tuned, a = 0.7890625 n - 0.625, n<2: a=0 (bit-accurate)",
         [](unsigned n, uint64_t code) {
             return datapath_brdf(golden_a_tuned(n, ua60553::minimax), ua60553::a_fmt.frac, code);
         },
         scene_device(scene::specular_device::minimax)},
        {"rom_matched", "UA 60553 tuned, a = 0.7890625 n - 0.5703125, n<2: a=0 (bit-accurate)",
         [](unsigned n, uint64_t code) {
             return datapath_brdf(golden_a_tuned(n, ua60553::rom_matched), ua60553::a_fmt.frac, code);
         },
         scene_device(scene::specular_device::rom_matched)},
        {"squared", "squared-quadratic device (ours), RG_SQ after the k-th square (bit-accurate)",
         [](unsigned n, uint64_t code) { return to_real(golden_squared(n, code, {0, 0, 0}, sat).brdf, squared::sq_fmt); },
         scene_device(scene::specular_device::squared)},
        {"sqmul", "square-and-multiply, Q1.18 (ours, for comparison; bit-accurate)",
         [](unsigned n, uint64_t code) { return to_real(golden_sqmul(n, code, {0, 0, 0}, sat).p, sqmul::p_fmt); },
         [](unsigned n, uint32_t code, const std::array<uint64_t, 3>& ksi) { return golden_sqmul(n, code, ksi, sat).out; }},
    };
}

}  // namespace shading::study
