// Throughput of the raster-line unit's TLM-2.0 wrapper (modules/tlm/line_tlm.h, m = 5, case 1,
// shift-and-add /3: the README's default line), one core, untraced: evaluated pixels per second of
// the loosely-timed burst path (the speed target: >= 5e7) and of the pin-accurate path, each
// shading whole windows (an INTERVAL_BLOCK write of --burst 32-pixel intervals, 256 = 8192 pixels by
// default, then a read of their pixels from PIXEL_BLOCK; --burst 1 for two transactions per
// interval) from an initiator thread. Samples vary per burst. Every 61st interval of the stream is
// checked against the golden chain (golden_interp_line on that interval alone, under 2 % of the
// work); a mismatch, an error response or a model time other than the documented P + 1 clocks per
// burst exits 1. The timed loop and the report are tlm_initiator.h's, shared with
// bench_specular_tlm; the options are testbenches/options' (fuzzed by fuzz_options).
//   bench_line_tlm [--lt-pixels N] [--pin-pixels N] [--burst I]
#include <array>
#include <cstdio>
#include <cstring>
#include <vector>

#include "golden/interp_golden.h"
#include "testbenches/options/tool_options.h"
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

// The stream's interval j: four Q8.8 sample codes that vary with j.
std::array<uint16_t, 4> samples(std::size_t j) {
    std::array<uint16_t, 4> s{};
    for (unsigned k = 0; k < 4; ++k) s[k] = static_cast<uint16_t>((j * 613 + k * 4099) & 0xFFFF);
    return s;
}

// Shades `pixels` (whole bursts of `intervals` 32-pixel intervals) through one initiator.
tb::tlm_figures run(tb::tlm_initiator& i, std::size_t pixels, std::size_t intervals, const wrapper& dut) {
    const std::size_t burst_pixels = intervals << M;
    std::vector<unsigned char> ivs(m::INTERVAL_STRIDE * intervals);
    std::vector<uint32_t> px(burst_pixels);
    tlm::tlm_generic_payload w, r;
    tb::set_block(w, tlm::TLM_WRITE_COMMAND, m::INTERVAL_BLOCK, ivs.data(), ivs.size());
    tb::set_block(r, tlm::TLM_READ_COMMAND, m::PIXEL_BLOCK, reinterpret_cast<unsigned char*>(px.data()),
                  4 * burst_pixels);
    sc_core::sc_time expected_time;
    // Interval j of burst b is interval b * intervals + j of the stream: the samples and the checked
    // intervals (every 61st) are the same whatever the burst.
    const auto fill = [&](std::size_t b) {
        for (std::size_t j = 0; j < intervals; ++j) {
            const auto s = samples(b * intervals + j);
            const uint32_t len = 1u << M;
            std::memcpy(ivs.data() + j * m::INTERVAL_STRIDE, s.data(), 8);
            std::memcpy(ivs.data() + j * m::INTERVAL_STRIDE + m::IV_LEN, &len, 4);
        }
    };
    const auto check = [&](std::size_t b) {
        std::size_t bad = 0;
        const std::size_t first = b * intervals;
        for (std::size_t j = (61 - first % 61) % 61; j < intervals; j += 61) {
            const auto s = samples(first + j);
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
    tb::bench_line_tlm_options o;
    if (auto rc = tb::parse_bench_line_tlm(argc, argv, o)) return *rc;
    const std::size_t intervals = o.burst;
    char title[200];
    std::snprintf(title, sizeof title,
                  "raster-line unit TLM-2.0 wrapper (m = %u, case 1, shift-and-add /3), bursts of %zu intervals = "
                  "%zu pixels per access (one core, untraced)",
                  M, intervals, intervals << M);
    return tb::tlm_bench_run<wrapper>(o.lt_pixels, o.pin_pixels, title,
                                      [intervals](tb::tlm_initiator& i, std::size_t px, const wrapper& dut) {
                                          return run(i, px, intervals, dut);
                                      });
}
