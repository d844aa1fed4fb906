// Throughput of the raster-line unit's TLM-2.0 wrapper (modules/tlm/line_tlm.h, m = 5, case 1,
// shift-and-add /3: the README's default line), one core, untraced: evaluated pixels per second of
// the loosely-timed burst path (issue 9's target: >= 5e7) and of the pin-accurate path, each
// shading whole windows (a 256-interval INTERVAL_BLOCK write of 32-pixel intervals, 8192 pixels,
// then a read of PIXEL_BLOCK) from an initiator thread. Samples vary per burst. Every 61st interval
// of each burst is checked against the golden chain (golden_interp_line on that interval alone,
// under 2 % of the work); a mismatch, an error response or a model time other than the documented
// P + 1 clocks per burst exits 1.
//   bench_line_tlm [--lt-pixels N] [--pin-pixels N]
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
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

struct figures {
    std::size_t pixels = 0, mismatches = 0;
    double seconds = 0, cpu_seconds = 0;  // wall clock; this process's CPU time (the machine may be shared)
    sc_core::sc_time model_time, expected_time;
};

// Burst b's interval j: four Q8.8 sample codes that vary with b and j (a smooth-ish line).
std::array<uint16_t, 4> samples(std::size_t b, std::size_t j) {
    std::array<uint16_t, 4> s{};
    for (unsigned k = 0; k < 4; ++k) s[k] = static_cast<uint16_t>((b * 7919 + j * 613 + k * 4099) & 0xFFFF);
    return s;
}

// Shades `pixels` (whole 8192-pixel windows) through one initiator.
figures run(tb::tlm_initiator& i, std::size_t pixels, const line_tlm_clock& ck) {
    figures f;
    std::vector<unsigned char> ivs(m::INTERVAL_STRIDE * m::BLOCK_INTERVALS);
    std::vector<uint32_t> px(burst_pixels);
    const std::size_t bursts = (pixels + burst_pixels - 1) / burst_pixels;
    tlm::tlm_generic_payload w, r;
    w.set_command(tlm::TLM_WRITE_COMMAND);
    w.set_address(m::INTERVAL_BLOCK);
    w.set_data_ptr(ivs.data());
    w.set_data_length(static_cast<unsigned>(ivs.size()));
    w.set_streaming_width(static_cast<unsigned>(ivs.size()));
    r.set_command(tlm::TLM_READ_COMMAND);
    r.set_address(m::PIXEL_BLOCK);
    r.set_data_ptr(reinterpret_cast<unsigned char*>(px.data()));
    r.set_data_length(static_cast<unsigned>(4 * burst_pixels));
    r.set_streaming_width(static_cast<unsigned>(4 * burst_pixels));
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
    const sc_core::sc_time t0 = sc_core::sc_time_stamp();
    const auto c0 = std::chrono::steady_clock::now();
    const std::clock_t cpu0 = std::clock();
    for (std::size_t b = 0; b < bursts; ++b) {
        for (std::size_t j = 0; j < m::BLOCK_INTERVALS; ++j) {
            const auto s = samples(b, j);
            const uint32_t len = 1u << M;
            std::memcpy(ivs.data() + j * m::INTERVAL_STRIDE, s.data(), 8);
            std::memcpy(ivs.data() + j * m::INTERVAL_STRIDE + m::IV_LEN, &len, 4);
        }
        w.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        r.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        i.socket->b_transport(w, delay);
        i.socket->b_transport(r, delay);
        if (w.get_response_status() != tlm::TLM_OK_RESPONSE || r.get_response_status() != tlm::TLM_OK_RESPONSE) {
            ++f.mismatches;
            break;
        }
        for (std::size_t j = b % 61; j < m::BLOCK_INTERVALS; j += 61) {
            const auto s = samples(b, j);
            const auto g = ip::golden_interp_line({{{s[0], s[1], s[2], s[3]}, 1u << M}}, M, SET, DIV);
            for (std::size_t p = 0; p < g.size(); ++p) f.mismatches += px[(j << M) + p] != static_cast<uint32_t>(g[p]);
        }
        f.expected_time += ck.burst_time(burst_pixels);
    }
    f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count();
    f.cpu_seconds = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
    f.model_time = sc_core::sc_time_stamp() - t0 + delay;
    f.pixels = bursts * burst_pixels;
    if (f.model_time != f.expected_time) ++f.mismatches;
    return f;
}

struct top : sc_core::sc_module {
    wrapper lt, pin;
    tb::tlm_initiator init_lt, init_pin;
    figures f_lt, f_pin;
    top(const sc_core::sc_module_name& name, std::size_t lt_px, std::size_t pin_px)
        : sc_module(name),
          lt("lt", tlm_timing::loosely_timed),
          pin("pin", tlm_timing::pin_accurate),
          init_lt("init_lt", nullptr),
          init_pin("init_pin", [=](tb::tlm_initiator& p) {
              f_lt = run(init_lt, lt_px, lt.clock());
              f_pin = run(p, pin_px, pin.clock());
          }) {
        init_lt.socket.bind(lt.socket);
        init_pin.socket.bind(pin.socket);
    }
};

void print(const char* what, const figures& f) {
    std::printf("%-15s %10zu px  %8.3f s  %11.4g px/s  (CPU %.3f s, %.4g px/s)  model time %s (%.2f ns/px)  "
                "mismatches %zu\n",
                what, f.pixels, f.seconds, f.pixels / f.seconds, f.cpu_seconds, f.pixels / f.cpu_seconds,
                f.model_time.to_string().c_str(),
                f.model_time.to_seconds() * 1e9 / static_cast<double>(f.pixels), f.mismatches);
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    std::size_t lt_px = 200'000'000, pin_px = 200'000;
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
    std::printf("raster-line unit TLM-2.0 wrapper (m = %u, case 1, shift-and-add /3), bursts of %zu intervals = "
                "%zu pixels per access (one core, untraced)\n",
                M, m::BLOCK_INTERVALS, burst_pixels);
    print("loosely timed", t.f_lt);
    print("pin-accurate", t.f_pin);
    std::printf("loosely timed / pin-accurate: %.0fx\n",
                (t.f_lt.pixels / t.f_lt.seconds) / (t.f_pin.pixels / t.f_pin.seconds));
    return t.f_lt.mismatches + t.f_pin.mismatches == 0 && t.f_lt.pixels > 0 && t.f_pin.pixels > 0 ? 0 : 1;
}
