// Throughput of the specular TLM-2.0 wrapper (modules/tlm/specular_tlm.h), one device per run, one
// core, untraced: evaluated pixels per second of the loosely-timed burst path (target: >= 5e7) and
// of the pin-accurate path, each shading whole raster lines (a 1024-pixel COS_BLOCK write, then a
// read of the RESULT_BLOCK; --burst P: P pixels per access, 1 for a transaction per pixel and
// direction) from an initiator thread, at n = 120 (the squared device: k = 6, ten clocks a pixel;
// the square-and-multiply device: 120 = 0b1111000, 6 squares and 3 multiplications, thirteen
// clocks a pixel). Every 61st pixel of each line is checked against the device's golden model in
// the loop (under 2 % of the work); a mismatch exits 1. The timed loop and the report are
// tlm_initiator.h's, shared with bench_line_tlm. --device takes render_pipeline's names.
//   bench_specular_tlm [--device patent|minimax|rom_matched|ua22802|squared|sqmul] [--lt-pixels N] [--pin-pixels N]
//                      [--burst P]
#include <array>
#include <string>
#include <vector>

#include "testbenches/options/tool_options.h"
#include "arith/specular_arith.h"
#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "arith/ua22802_arith.h"
#include "arith/ua60553_tuned_arith.h"
#include "tlm/specular_tlm.h"
#include "tlm_initiator.h"

using namespace shading;
namespace m = shading::tlm_map;

namespace {

constexpr unsigned bench_n = 120;
using golden_fn = std::array<uint64_t, 3> (*)(uint64_t cos, const std::array<uint64_t, 3>& ksi);

// The tuned generator with the ROM-matched constants (a_gen_tuned's default is minimax).
struct specular_tlm_rom_matched : specular_tlm_ua60553_tuned {
    specular_tlm_rom_matched(const sc_core::sc_module_name& name, tlm_timing t)
        : specular_tlm_ua60553_tuned(name, t, ua60553::rom_matched) {}
};

// Shades `pixels` (whole bursts of `burst` pixels) through one initiator; codes vary per burst.
tb::tlm_figures run(tb::tlm_initiator& i, std::size_t pixels, std::size_t burst, golden_fn golden) {
    const std::array<uint64_t, 3> k{255, 140, 40};
    i.write32(m::N, bench_n);
    for (unsigned c = 0; c < 3; ++c) i.write32(m::KSI_R + 4 * c, static_cast<uint32_t>(k[c]));
    std::vector<uint16_t> codes(burst);
    std::vector<uint32_t> res(4 * burst);
    tlm::tlm_generic_payload w, r;
    tb::set_block(w, tlm::TLM_WRITE_COMMAND, m::COS_BLOCK, reinterpret_cast<unsigned char*>(codes.data()), 2 * burst);
    tb::set_block(r, tlm::TLM_READ_COMMAND, m::RESULT_BLOCK, reinterpret_cast<unsigned char*>(res.data()), 16 * burst);
    const auto fill = [&](std::size_t l) {
        for (std::size_t p = 0; p < burst; ++p)
            codes[p] = static_cast<uint16_t>((l * 7919 + p * 31) % (spec::cos_one + 1));
    };
    // Check a sample of each burst (every 61st pixel; of 1-pixel bursts every 61st) against the
    // golden model, cheaply.
    const auto check = [&](std::size_t l) {
        std::size_t bad = 0;
        for (std::size_t p = l % 61; p < burst; p += 61) {
            const auto g = golden(codes[p], k);
            bad += res[4 * p] != g[0] || res[4 * p + 1] != g[1] || res[4 * p + 2] != g[2];
        }
        return bad;
    };
    return tb::time_bursts(i, (pixels + burst - 1) / burst, burst, w, r, fill, check);
}

template <class W>
int bench(const std::string& what, std::size_t lt_px, std::size_t pin_px, std::size_t burst, golden_fn golden) {
    return tb::tlm_bench_run<W>(lt_px, pin_px,
                                what + " TLM-2.0 wrapper, n = " + std::to_string(bench_n) + ", bursts of " +
                                    std::to_string(burst) + " pixels per access (one core, untraced)",
                                [golden, burst](tb::tlm_initiator& i, std::size_t px, const W&) {
                                    return run(i, px, burst, golden);
                                });
}

constexpr auto sat = overflow_mode::saturate;

}  // namespace

int sc_main(int argc, char* argv[]) {
    tb::bench_specular_tlm_options o;
    if (auto rc = tb::parse_bench_specular_tlm(argc, argv, o)) return *rc;
    const std::string& device = o.device;
    const std::size_t lt_px = o.lt_pixels, pin_px = o.pin_pixels;
    const std::size_t burst = o.burst;
    if (device == "patent")
        return bench<specular_tlm_ua60553>("UA 60553", lt_px, pin_px, burst, [](uint64_t c, const std::array<uint64_t, 3>& k) {
            return golden_ua60553(bench_n, c, k, sat).out;
        });
    if (device == "minimax")
        return bench<specular_tlm_ua60553_tuned>(
            "UA 60553 tuned (minimax)", lt_px, pin_px, burst,
            [](uint64_t c, const std::array<uint64_t, 3>& k) { return golden_ua60553_tuned(bench_n, c, k, sat).out; });
    if (device == "rom_matched")
        return bench<specular_tlm_rom_matched>("UA 60553 tuned (ROM-matched)", lt_px, pin_px, burst,
                                               [](uint64_t c, const std::array<uint64_t, 3>& k) {
                                                   return golden_ua60553_tuned(bench_n, c, k, sat, ua60553::rom_matched).out;
                                               });
    if (device == "ua22802")
        return bench<specular_tlm_ua22802>("UA 22802", lt_px, pin_px, burst, [](uint64_t c, const std::array<uint64_t, 3>& k) {
            return golden_ua22802(bench_n, c, k, sat).out;
        });
    if (device == "sqmul")
        return bench<specular_tlm_sqmul>("Square-and-multiply", lt_px, pin_px, burst,
                                         [](uint64_t c, const std::array<uint64_t, 3>& k) {
                                             return golden_sqmul(bench_n, c, k, sat).out;
                                         });
    return bench<specular_tlm_squared>("Squared-quadratic", lt_px, pin_px, burst,
                                       [](uint64_t c, const std::array<uint64_t, 3>& k) {
                                           return golden_squared(bench_n, c, k, sat).out;
                                       });
}
