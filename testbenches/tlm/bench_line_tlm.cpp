// Throughput of the raster-line unit's TLM-2.0 wrapper (modules/tlm/line_tlm.h, m = 5, case 1,
// shift-and-add /3: the README's default line), one core, untraced: evaluated pixels per second of
// the loosely-timed burst path (the speed target: >= 5e7) and of the pin-accurate path, each
// shading whole windows (a 256-interval INTERVAL_BLOCK write of 32-pixel intervals, 8192 pixels,
// then a read of PIXEL_BLOCK) from an initiator thread. Samples vary per burst. Every 61st interval
// of each burst is checked against the golden chain (golden_interp_line on that interval alone,
// under 2 % of the work); a mismatch, an error response or a model time other than the documented
// P + 1 clocks per burst exits 1. The timed loop, the options and the report are tlm_initiator.h's,
// shared with bench_specular_tlm.
//   bench_line_tlm [--lt-pixels N] [--pin-pixels N]
#include <array>
#include <cstdio>
#include <cstring>
#include <vector>

#include "golden/interp_golden.h"
#include "tlm/line_tlm.h"
#include "tlm_initiator.h"

using namespace shading;
namespace m = shading::line_tlm_map;
namespace ip = shading::interp;

namespace {

constexpr unsigned M = 5;
constexpr ip::sample_set SET = ip::sample_set::case1;
constexpr ip::div3_mode DIV = ip::div3_mode::shift_add;
using wrapper = line_tlm<M, SET, DIV>;
constexpr std::size_t burst_pixels = m::BLOCK_INTERVALS << M;  // 8192

// Burst b's interval j: four Q8.8 sample codes that vary with b and j (a smooth-ish line).
std::array<uint16_t, 4> samples(std::size_t b, std::size_t j) {
    std::array<uint16_t, 4> s{};
    for (unsigned k = 0; k < 4; ++k) s[k] = static_cast<uint16_t>((b * 7919 + j * 613 + k * 4099) & 0xFFFF);
    return s;
}

// Shades `pixels` (whole 8192-pixel windows) through one initiator.
tb::tlm_figures run(tb::tlm_initiator& i, std::size_t pixels, const wrapper& dut) {
    std::vector<unsigned char> ivs(m::INTERVAL_STRIDE * m::BLOCK_INTERVALS);
    std::vector<uint32_t> px(burst_pixels);
    tlm::tlm_generic_payload w, r;
    tb::set_block(w, tlm::TLM_WRITE_COMMAND, m::INTERVAL_BLOCK, ivs.data(), ivs.size());
    tb::set_block(r, tlm::TLM_READ_COMMAND, m::PIXEL_BLOCK, reinterpret_cast<unsigned char*>(px.data()),
                  4 * burst_pixels);
    sc_core::sc_time expected_time;
    const auto fill = [&](std::size_t b) {
        for (std::size_t j = 0; j < m::BLOCK_INTERVALS; ++j) {
            const auto s = samples(b, j);
            const uint32_t len = 1u << M;
            std::memcpy(ivs.data() + j * m::INTERVAL_STRIDE, s.data(), 8);
            std::memcpy(ivs.data() + j * m::INTERVAL_STRIDE + m::IV_LEN, &len, 4);
        }
    };
    const auto check = [&](std::size_t b) {
        std::size_t bad = 0;
        for (std::size_t j = b % 61; j < m::BLOCK_INTERVALS; j += 61) {
            const auto s = samples(b, j);
            const auto g = ip::golden_interp_line({{{s[0], s[1], s[2], s[3]}, 1u << M}}, M, SET, DIV);
            for (std::size_t p = 0; p < g.size(); ++p) bad += px[(j << M) + p] != static_cast<uint32_t>(g[p]);
        }
        expected_time += dut.clock().burst_time(burst_pixels);
        return bad;
    };
    auto f = tb::time_bursts(i, (pixels + burst_pixels - 1) / burst_pixels, burst_pixels, w, r, fill, check);
    if (f.model_time != expected_time) ++f.mismatches;
    return f;
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    char title[160];
    std::snprintf(title, sizeof title,
                  "raster-line unit TLM-2.0 wrapper (m = %u, case 1, shift-and-add /3), bursts of %zu intervals = "
                  "%zu pixels per access (one core, untraced)",
                  M, m::BLOCK_INTERVALS, burst_pixels);
    return tb::tlm_bench_main<wrapper>(argc, argv, 200'000'000, 200'000, title, run);
}
