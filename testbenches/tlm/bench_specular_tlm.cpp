// Throughput of the UA 60553 TLM-2.0 wrapper (modules/tlm/specular_tlm.h), one core, untraced:
// evaluated pixels per second of the loosely-timed burst path (issue 9's target: >= 5e7) and of
// the pin-accurate path, each shading whole raster lines (a 1024-pixel COS_BLOCK write, then a
// read of the RESULT_BLOCK) from an initiator thread. Every 61st pixel of each line is checked
// against the golden model in the loop (under 2 % of the work); a mismatch exits 1. The timed loop,
// the options and the report are tlm_initiator.h's, shared with bench_line_tlm.
//   bench_specular_tlm [--lt-pixels N] [--pin-pixels N]
#include <array>
#include <string>
#include <vector>

#include "golden/specular_golden.h"
#include "tlm/specular_tlm.h"
#include "tlm_initiator.h"

using namespace shading;
namespace m = shading::tlm_map;

namespace {

// Shades `pixels` (whole lines of 1024) through one initiator; codes vary per line.
tb::tlm_figures run(tb::tlm_initiator& i, std::size_t pixels, const specular_tlm_ua60553&) {
    const std::array<uint64_t, 3> k{255, 140, 40};
    i.write32(m::N, 120);
    for (unsigned c = 0; c < 3; ++c) i.write32(m::KSI_R + 4 * c, static_cast<uint32_t>(k[c]));
    std::vector<uint16_t> codes(m::BLOCK_PIXELS);
    std::vector<uint32_t> res(4 * m::BLOCK_PIXELS);
    tlm::tlm_generic_payload w, r;
    tb::set_block(w, tlm::TLM_WRITE_COMMAND, m::COS_BLOCK, reinterpret_cast<unsigned char*>(codes.data()),
                  2 * m::BLOCK_PIXELS);
    tb::set_block(r, tlm::TLM_READ_COMMAND, m::RESULT_BLOCK, reinterpret_cast<unsigned char*>(res.data()),
                  16 * m::BLOCK_PIXELS);
    const auto fill = [&](std::size_t l) {
        for (std::size_t p = 0; p < m::BLOCK_PIXELS; ++p)
            codes[p] = static_cast<uint16_t>((l * 7919 + p * 31) % (spec::cos_one + 1));
    };
    // Check a sample of each line (every 61st pixel) against the golden model, cheaply.
    const auto check = [&](std::size_t l) {
        std::size_t bad = 0;
        for (std::size_t p = l % 61; p < m::BLOCK_PIXELS; p += 61) {
            const auto g = golden_ua60553(120, codes[p], k, overflow_mode::saturate);
            bad += res[4 * p] != g.out[0] || res[4 * p + 1] != g.out[1] || res[4 * p + 2] != g.out[2];
        }
        return bad;
    };
    return tb::time_bursts(i, (pixels + m::BLOCK_PIXELS - 1) / m::BLOCK_PIXELS, m::BLOCK_PIXELS, w, r, fill, check);
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    return tb::tlm_bench_main<specular_tlm_ua60553>(
        argc, argv, 100'000'000, 200'000,
        "UA 60553 TLM-2.0 wrapper, raster lines of " + std::to_string(m::BLOCK_PIXELS) +
            " pixels per access (one core, untraced)",
        run);
}
