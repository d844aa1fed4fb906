// Throughput of the UA 60553 TLM-2.0 wrapper (modules/tlm/specular_tlm.h), one core, untraced:
// evaluated pixels per second of the loosely-timed burst path (issue 9's target: >= 5e7) and of
// the pin-accurate path, each shading whole raster lines (a 1024-pixel COS_BLOCK write, then a
// read of the RESULT_BLOCK) from an initiator thread. Every 61st pixel of each line is checked
// against the golden model in the loop (under 2 % of the work); a mismatch exits 1.
//   bench_specular_tlm [--lt-pixels N] [--pin-pixels N]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "golden/specular_golden.h"
#include "tlm/specular_tlm.h"
#include "tlm_initiator.h"

using namespace shading;
namespace m = shading::tlm_map;

namespace {

struct figures {
    std::size_t pixels = 0, mismatches = 0;
    double seconds = 0;
    sc_core::sc_time model_time;
};

// Shades `pixels` (whole lines of 1024) through one initiator; codes vary per line.
figures run(tb::tlm_initiator& i, std::size_t pixels) {
    figures f;
    const std::array<uint64_t, 3> k{255, 140, 40};
    i.write32(m::N, 120);
    for (unsigned c = 0; c < 3; ++c) i.write32(m::KSI_R + 4 * c, static_cast<uint32_t>(k[c]));
    std::vector<uint16_t> codes(m::BLOCK_PIXELS);
    std::vector<uint32_t> res(4 * m::BLOCK_PIXELS);
    const std::size_t lines = (pixels + m::BLOCK_PIXELS - 1) / m::BLOCK_PIXELS;
    tlm::tlm_generic_payload w, r;
    w.set_command(tlm::TLM_WRITE_COMMAND);
    w.set_address(m::COS_BLOCK);
    w.set_data_ptr(reinterpret_cast<unsigned char*>(codes.data()));
    w.set_data_length(2 * m::BLOCK_PIXELS);
    w.set_streaming_width(2 * m::BLOCK_PIXELS);
    r.set_command(tlm::TLM_READ_COMMAND);
    r.set_address(m::RESULT_BLOCK);
    r.set_data_ptr(reinterpret_cast<unsigned char*>(res.data()));
    r.set_data_length(16 * m::BLOCK_PIXELS);
    r.set_streaming_width(16 * m::BLOCK_PIXELS);
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
    const sc_core::sc_time t0 = sc_core::sc_time_stamp();
    const auto c0 = std::chrono::steady_clock::now();
    for (std::size_t l = 0; l < lines; ++l) {
        for (std::size_t p = 0; p < m::BLOCK_PIXELS; ++p)
            codes[p] = static_cast<uint16_t>((l * 7919 + p * 31) % (spec::cos_one + 1));
        i.socket->b_transport(w, delay);
        i.socket->b_transport(r, delay);
        if (w.get_response_status() != tlm::TLM_OK_RESPONSE || r.get_response_status() != tlm::TLM_OK_RESPONSE) {
            ++f.mismatches;
            break;
        }
        // Check a sample of each line (every 61st pixel) against the golden model, cheaply.
        for (std::size_t p = l % 61; p < m::BLOCK_PIXELS; p += 61) {
            const auto g = golden_ua60553(120, codes[p], k, overflow_mode::saturate);
            f.mismatches += res[4 * p] != g.out[0] || res[4 * p + 1] != g.out[1] || res[4 * p + 2] != g.out[2];
        }
    }
    f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count();
    f.model_time = sc_core::sc_time_stamp() - t0 + delay;
    f.pixels = lines * m::BLOCK_PIXELS;
    return f;
}

struct top : sc_core::sc_module {
    specular_tlm_ua60553 lt, pin;
    tb::tlm_initiator init_lt, init_pin;
    figures f_lt, f_pin;
    top(const sc_core::sc_module_name& name, std::size_t lt_px, std::size_t pin_px)
        : sc_module(name),
          lt("lt", tlm_timing::loosely_timed),
          pin("pin", tlm_timing::pin_accurate),
          init_lt("init_lt", nullptr),
          init_pin("init_pin", [=](tb::tlm_initiator& p) {
              f_lt = run(init_lt, lt_px);
              f_pin = run(p, pin_px);
          }) {
        init_lt.socket.bind(lt.socket);
        init_pin.socket.bind(pin.socket);
    }
};

void print(const char* what, const figures& f) {
    std::printf("%-15s %10zu px  %8.3f s  %12.4g px/s  model time %s (%.1f ns/px)  mismatches %zu\n", what,
                f.pixels, f.seconds, f.pixels / f.seconds, f.model_time.to_string().c_str(),
                f.model_time.to_seconds() * 1e9 / static_cast<double>(f.pixels), f.mismatches);
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    std::size_t lt_px = 100'000'000, pin_px = 200'000;
    for (int a = 1; a + 1 < argc; a += 2) {
        if (!std::strcmp(argv[a], "--lt-pixels")) lt_px = std::strtoull(argv[a + 1], nullptr, 10);
        else if (!std::strcmp(argv[a], "--pin-pixels")) pin_px = std::strtoull(argv[a + 1], nullptr, 10);
        else {
            std::fprintf(stderr, "usage: %s [--lt-pixels N] [--pin-pixels N]\n", argv[0]);
            return 2;
        }
    }
    top t("top", lt_px, pin_px);
    sc_core::sc_start();
    std::printf("UA 60553 TLM-2.0 wrapper, raster lines of %zu pixels per access (one core, untraced)\n",
                m::BLOCK_PIXELS);
    print("loosely timed", t.f_lt);
    print("pin-accurate", t.f_pin);
    std::printf("loosely timed / pin-accurate: %.0fx\n",
                (t.f_lt.pixels / t.f_lt.seconds) / (t.f_pin.pixels / t.f_pin.seconds));
    return t.f_lt.mismatches + t.f_pin.mismatches == 0 && t.f_lt.pixels > 0 && t.f_pin.pixels > 0 ? 0 : 1;
}
