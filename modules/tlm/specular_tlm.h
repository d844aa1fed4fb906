// TLM-2.0 wrapper of the specular devices (UA 60553's pins): the UA 60553 family
// (specular/specular_device.h with any generator of `a`), the squared-quadratic device (ours,
// squared/squared_device.h, with a `clk` pin) and the square-and-multiply device (ours,
// sqmul/sqmul_device.h, the same pins): a tlm_utils::simple_target_socket `socket` with
// b_transport and transport_dbg over the register map below, in one of two timing modes chosen at
// construction:
//   pin_accurate   - the wrapper owns the signal-level devices and drives UA 60553, Fig. 3's
//                    strobes from the b_transport caller's thread with wait(): an access costs the
//                    model's real time and the waveform shows it;
//   loosely_timed  - the golden function (src/floor/arith) computes the result; the access is annotated
//                    with the same delay (added to b_transport's delay argument, no wait).
// Both give bit-identical data (testbenches/tlm). One class template, specular_tlm<V>, whose V
// names the device as tlm_variant<V> describes it (a_gen_linear, a_gen_rom, a_gen_tuned: UA 60553's
// Fig. 1 with that generator; squared_device; sqmul_device); aliases at the end of the file.
//
// Register map (byte addresses; registers are 32-bit words in host byte order, little-endian on
// the supported hosts; reserved bits read 0, writes to them are ignored):
//   0x000 N        RW  bits 9:0   n, RG1 (strobe 15). Clears READY, invalidates the result window.
//   0x004 KSI_R    RW  bits 7:0   k_s*I red, RG3 (strobe 20). Same side effects as N.
//   0x008 KSI_G    RW  bits 7:0   k_s*I green, RG4 (strobe 22).
//   0x00C KSI_B    RW  bits 7:0   k_s*I blue, RG5 (strobe 24).
//   0x010 COS      RW  bits 15:0  cos gamma, Q1.15 (0x8000 = 1.0). A write shades one pixel
//                                 (strobe 17 falls and rises) into RESULT_R..B and sets READY.
//   0x014 RESULT_R RO  bits 16:0  output 25, Q9.8 \  valid while STATUS.READY; a read before
//   0x018 RESULT_G RO  bits 16:0  output 26, Q9.8  > that is a TLM_GENERIC_ERROR_RESPONSE
//   0x01C RESULT_B RO  bits 16:0  output 27, Q9.8 /   (nothing to return yet)
//   0x020 STATUS   RO  bit 0 READY; bits 5:1 sticky bus-error log (bit 1 address, 2 size or
//                      alignment, 3 byte enables, 4 command, 5 read before ready), cleared by
//                      CONTROL.CLEAR_ERR. The log is the wrapper's, not the device's state.
//   0x024 CONTROL  RW  bit 0 OVF: 0 saturate, 1 wrap (ADD11's overflow mode; a change clears
//                      READY and invalidates the result window); bits 6:4 VARIANT, read-only
//                      (0 UA 60553, 1 UA 22802 ROM, 2 tuned UA 60553, 3 squared-quadratic,
//                      4 square-and-multiply);
//                      bit 8 TIMING, read-only
//                      (0 loosely timed, 1 pin-accurate); bit 31 CLEAR_ERR, write 1 to clear
//                      STATUS bits 5:1, reads 0.
//   0x1000-0x17FF COS_BLOCK    RW  1024 cos codes, 16 bits each (pixel i at 0x1000 + 2i). A write
//                      of L bytes at offset 2i shades pixels i .. i+L/2-1 (a raster line per
//                      access) into RESULT_BLOCK; a read returns the codes last written.
//   0x2000-0x5FFF RESULT_BLOCK RO  1024 pixels x 16 bytes: words R, G, B (Q9.8) and the cos code
//                      they were shaded from, pixel i at 0x2000 + 16i. Any 4-aligned read of a
//                      multiple of 4 bytes; every pixel it touches must have been shaded since
//                      the last change of N, KSI_* or OVF, else TLM_GENERIC_ERROR_RESPONSE.
// Access rules and errors (each also an SC_REPORT_WARNING with id shading/tlm; the device's
// registers, results and the windows are unchanged):
//   byte-enable pointer set                             -> TLM_BYTE_ENABLE_ERROR_RESPONSE
//   start address outside the map                       -> TLM_ADDRESS_ERROR_RESPONSE
//   register access not exactly 4 bytes at a 4-aligned address, a window access misaligned, of a
//   bad length, running past the window's end, or streaming width != length
//                                                       -> TLM_BURST_ERROR_RESPONSE
//   write to a read-only register or window             -> TLM_COMMAND_ERROR_RESPONSE
//   read of RESULT_* or RESULT_BLOCK before it is ready -> TLM_GENERIC_ERROR_RESPONSE
// TLM_IGNORE_COMMAND completes with TLM_OK_RESPONSE and does nothing.
// Access time (both modes): a write of N or KSI_* costs one load pulse pair, 2 x load_pulse
// (8 ns by default); each pixel of a COS write or a COS_BLOCK burst one period of strobe 17:
//   UA 60553 family  t_high + t_low (20 ns), as Fig. 3;
//   squared device   until output 29 rises: cos is set up t_high / 2, strobe 17 falls at the next
//                    falling edge of the device clock (`clk`, clk_period, rising at 0, P, 2P, ...),
//                    the synchroniser sync17 samples its request at the next rising edge and
//                    output 29 rises k + 3 clocks later (two more edges through sync17 and the
//                    taking edge, k squares, the done edge; k = 9 - leading zeros of n) plus the
//                    AND gate's delay; so it depends on n and, for a burst's first pixel, on the
//                    clock's phase at the access's local time (back-to-back pixels take (k + 4)
//                    clocks each);
//   sqmul device     the same with floor(log2 n) + popcount(n) + 2 clocks in place of k + 3 (its
//                    walk over n's bits; back-to-back pixels take floor(log2 n) + popcount(n) + 3
//                    clocks each);
// everything else 0. In pin-accurate mode an access that drives strobes first waits the incoming
// delay (and returns it as 0); the others return at once with the delay untouched.
// Debug transport: reads of any byte range within one region (registers 0x000-0x027, COS_BLOCK,
// RESULT_BLOCK) without side effects, readiness checks or time; debug writes are not supported
// (0 bytes transferred).
#pragma once

#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <systemc>

#include "arith/specular_arith.h"
#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "arith/ua60553_tuned_arith.h"
#include "formats/specular_formats.h"
#include "formats/sqmul_formats.h"
#include "formats/squared_formats.h"
#include "specular/specular_device.h"
#include "sqmul/sqmul_device.h"
#include "squared/squared_device.h"
#include "tlm/tlm_target_base.h"
#include "tuned/a_gen_tuned.h"
#include "ua22802/a_gen_rom.h"
#include "ua60553/a_gen_linear.h"

namespace shading {

namespace tlm_map {
inline constexpr uint64_t N = 0x000, KSI_R = 0x004, KSI_G = 0x008, KSI_B = 0x00C, COS = 0x010;
inline constexpr uint64_t RESULT_R = 0x014, RESULT_G = 0x018, RESULT_B = 0x01C;
inline constexpr uint64_t STATUS = 0x020, CONTROL = 0x024, REG_END = 0x028;
inline constexpr uint64_t COS_BLOCK = 0x1000, RESULT_BLOCK = 0x2000;
inline constexpr std::size_t BLOCK_PIXELS = 1024;
inline constexpr uint64_t COS_BLOCK_END = COS_BLOCK + 2 * BLOCK_PIXELS;
inline constexpr uint64_t RESULT_STRIDE = 16;
inline constexpr uint64_t RESULT_BLOCK_END = RESULT_BLOCK + RESULT_STRIDE * BLOCK_PIXELS;
inline constexpr uint32_t STATUS_READY = 1u << 0;
inline constexpr uint32_t ERR_ADDRESS = tlm_err::address, ERR_SIZE = tlm_err::size,
                          ERR_BYTE_ENABLE = tlm_err::byte_enable, ERR_COMMAND = tlm_err::command,
                          ERR_NOT_READY = tlm_err::not_ready;
inline constexpr uint32_t CONTROL_OVF = 1u << 0, CONTROL_VARIANT_SHIFT = 4, CONTROL_VARIANT_MASK = 7u << 4,
                          CONTROL_TIMING = 1u << 8, CONTROL_CLEAR_ERR = 1u << 31;
}  // namespace tlm_map

// Strobe timing of Fig. 3 the wrapper drives (the defaults of testbenches/specular's stimulus),
// and the clock of a device with a `clk` pin (the squared device's squaring stage).
struct tlm_strobe_timing {
    sc_core::sc_time t_low{15, sc_core::SC_NS};      // strobe 17 low: the settling phase T
    sc_core::sc_time t_high{5, sc_core::SC_NS};      // strobe 17 high; cos changes in its middle
    sc_core::sc_time load_pulse{4, sc_core::SC_NS};  // each half of a ctl15/20/22/24 pulse
    // The wrapper's own clock, pin-accurate mode: an sc_clock of this period, 50 %, rising at 0,
    // P, 2P, ... (sc_clock's defaults); the loosely-timed mode computes its edges from the period.
    sc_core::sc_time clk_period{20, sc_core::SC_NS};
    sc_core::sc_time load_time() const { return load_pulse * 2.0; }
    sc_core::sc_time pixel_time() const { return t_high + t_low; }  // the UA 60553 family's pixel
};

// What specular_tlm<V> needs to know of the device named by V (tlm_variant<V>):
//   device, config, default_config()  the signal-level device and what it is built from
//   make(name, mode, config, delays)  one build of it (pin-accurate mode owns a saturating and a
//                                     wrapping one; ADD11's mode is fixed in silicon)
//   code, n_fmt                       CONTROL.VARIANT; RG1's bus
//   law(n, config)                    what the golden path keeps per n (a(n), or n itself)
//   outputs(law, cos, ksi, mode)      outputs 25..27 from the golden model
//   clocked                           false: Fig. 3's fixed strobe; true: a `clk` pin, and
//   latency(n)                        the clocks from the first rising edge after strobe 17 fell
//                                     (where the synchroniser samples it) to the one that makes
//                                     the result valid
template <class V>
struct tlm_variant;

// UA 60553's Fig. 1 with a generator of `a`, AGen (specular_device<AGen>).
template <class AGen>
struct tlm_fig1_variant {
    using device = specular_device<AGen>;
    using config = typename AGen::config;
    static config default_config() { return AGen::default_config(); }
    static constexpr qfmt n_fmt = AGen::n_fmt;
    static constexpr bool clocked = false;
    static std::unique_ptr<device> make(const char* name, overflow_mode m, const config& g, const block_delays& d) {
        return std::make_unique<device>(name, m, g, d);
    }
    // The generator's own word for n (the fast model reads the same function): one law per device.
    static uint64_t law(uint64_t n, const config& g) { return AGen::a_word(g, n); }
    static std::array<uint64_t, 3> outputs(uint64_t a, uint64_t cos, const std::array<uint64_t, 3>& ksi,
                                           overflow_mode m) {
        return golden_datapath(a, AGen::a_fmt.frac, cos, ksi, m).out;
    }
};
template <>
struct tlm_variant<a_gen_linear> : tlm_fig1_variant<a_gen_linear> {
    static constexpr uint32_t code = 0;
};
template <>
struct tlm_variant<a_gen_rom> : tlm_fig1_variant<a_gen_rom> {
    static constexpr uint32_t code = 1;  // law: the ROM's own words (default: the generated content)
};
template <>
struct tlm_variant<a_gen_tuned> : tlm_fig1_variant<a_gen_tuned> {
    static constexpr uint32_t code = 2;
};
// The squared-quadratic device (ours): a from n alone, so nothing to configure; its latency from
// the first rising edge after the strobe is k + 3 clocks (sq_count.h: sync17's second stage, the
// taking edge with the LOAD, k SQUAREs, done).
template <>
struct tlm_variant<squared_device> {
    using device = squared_device;
    struct config {};
    static config default_config() { return {}; }
    static constexpr uint32_t code = 3;
    static constexpr qfmt n_fmt = squared::n_fmt;
    static constexpr bool clocked = true;
    static std::unique_ptr<device> make(const char* name, overflow_mode m, const config&, const block_delays& d) {
        return std::make_unique<device>(name, m, d);
    }
    static uint64_t law(uint64_t n, const config&) { return n & n_fmt.mask(); }
    static unsigned latency(uint64_t n) { return golden_squared_a(n).k + squared::sync_stages + 1; }
    static std::array<uint64_t, 3> outputs(uint64_t n, uint64_t cos, const std::array<uint64_t, 3>& ksi,
                                           overflow_mode m) {
        return golden_squared(n, cos, ksi, m).out;
    }
};
// The square-and-multiply device (ours): nothing to configure; its latency from the first rising
// edge after the strobe is floor(log2 n) + popcount(n) + 2 clocks (sqmul_count.h: sync17's second
// stage, the taking edge with the LOAD, one step per square and per multiplication, done).
template <>
struct tlm_variant<sqmul_device> {
    using device = sqmul_device;
    struct config {};
    static config default_config() { return {}; }
    static constexpr uint32_t code = 4;
    static constexpr qfmt n_fmt = sqmul::n_fmt;
    static constexpr bool clocked = true;
    static std::unique_ptr<device> make(const char* name, overflow_mode m, const config&, const block_delays& d) {
        return std::make_unique<device>(name, m, d);
    }
    static uint64_t law(uint64_t n, const config&) { return n & n_fmt.mask(); }
    static unsigned latency(uint64_t n) {
        const auto g = golden_sqmul(n, 0, {0, 0, 0}, overflow_mode::saturate);
        return g.squares + g.multiplies + sqmul::sync_stages + 1;
    }
    static std::array<uint64_t, 3> outputs(uint64_t n, uint64_t cos, const std::array<uint64_t, 3>& ksi,
                                           overflow_mode m) {
        return golden_sqmul(n, cos, ksi, m).out;
    }
};

template <class V>
class specular_tlm : public tlm_target_base {
    using variant = tlm_variant<V>;
    using device_t = typename variant::device;
    using config_t = typename variant::config;
    using n_t = sc_dt::sc_uint<variant::n_fmt.width>;
    using cos_t = sc_dt::sc_uint<spec::cos_fmt.width>;
    using ksi_t = sc_dt::sc_uint<spec::ksi_fmt.width>;
    using out_t = sc_dt::sc_uint<spec::out_fmt.width>;
    template <class T>
    using net = sc_core::sc_signal<T, sc_core::SC_MANY_WRITERS>;  // driven by whichever caller's thread

public:
    tlm_utils::simple_target_socket<specular_tlm> socket{"socket"};

    // Pin-accurate mode: the pins of Fig. 1, shared by the two builds of the device (ADD11
    // saturating or wrapping is fixed in silicon; CONTROL.OVF picks whose outputs are read).
    net<bool> ctl15{"ctl15", false}, ctl17{"ctl17", true}, ctl20{"ctl20", false}, ctl22{"ctl22", false},
        ctl24{"ctl24", false};
    net<n_t> in16_n{"in16_n"};
    net<cos_t> in18_cos{"in18_cos"};
    net<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};
    using out_net = sc_core::sc_signal<out_t>;
    std::array<std::array<out_net, 3>, 2> out{{{out_net{"sat_out25_r"}, out_net{"sat_out26_g"}, out_net{"sat_out27_b"}},
                                                {out_net{"wrap_out25_r"}, out_net{"wrap_out26_g"},
                                                 out_net{"wrap_out27_b"}}}};  // [saturate, wrap][R, G, B]
    std::array<sc_core::sc_signal<bool>, 2> out29{{sc_core::sc_signal<bool>{"sat_out29_valid"},
                                                   sc_core::sc_signal<bool>{"wrap_out29_valid"}}};
    // A clocked device's clock, pin-accurate mode only: the wrapper's own sc_clock of
    // t.clk_period, not a clock port, so the loosely-timed mode (no device, no clock) knows every
    // edge from the period alone and annotates the exact pin-accurate time; every variant is built
    // from (name, timing) alike; and a loosely-timed model pays for no clock events.
    std::unique_ptr<sc_core::sc_clock> clk;
    std::unique_ptr<device_t> dev_sat, dev_wrap;  // pin-accurate mode only

    specular_tlm(const sc_core::sc_module_name& name, tlm_timing timing, const config_t& gen = variant::default_config(),
                 const tlm_strobe_timing& t = {}, const block_delays& delays = {})
        : tlm_target_base(name, timing), gen_(gen), t_(t), gate_(delays.gate) {
        socket.register_b_transport(this, &specular_tlm::b_transport);
        socket.register_transport_dbg(this, &specular_tlm::transport_dbg);
        set_n(0);
        if (timing_ == tlm_timing::pin_accurate) {
            if constexpr (variant::clocked) clk = std::make_unique<sc_core::sc_clock>("clk", t_.clk_period);
            dev_sat = variant::make("dev_sat", overflow_mode::saturate, gen, delays);
            dev_wrap = variant::make("dev_wrap", overflow_mode::wrap, gen, delays);
            bind(*dev_sat, 0);
            bind(*dev_wrap, 1);
        }
        for (auto& p : results_) p = {0, 0, 0, 0};
    }

    tlm_timing timing() const { return timing_; }
    const tlm_strobe_timing& strobe_timing() const { return t_; }

    void b_transport(tlm::tlm_generic_payload& p, sc_core::sc_time& delay) {
        if (!check(p)) return;
        const uint64_t addr = p.get_address();
        const unsigned len = p.get_data_length();
        unsigned char* data = p.get_data_ptr();
        if (p.is_read()) {
            if (addr < tlm_map::REG_END) {
                put32(data, reg_read(addr));
            } else if (addr < tlm_map::COS_BLOCK_END) {
                std::memcpy(data, reinterpret_cast<const unsigned char*>(cos_.data()) + (addr - tlm_map::COS_BLOCK),
                            len);
            } else {
                std::memcpy(data, reinterpret_cast<const unsigned char*>(results_.data()) +
                                      (addr - tlm_map::RESULT_BLOCK), len);
            }
            p.set_response_status(tlm::TLM_OK_RESPONSE);
            return;
        }
        // Writes: only N, KSI_*, COS and the COS window cost strobe time.
        if (timing_ == tlm_timing::pin_accurate && costs_time(addr)) {
            lock_.lock();  // one initiator at a time on the pins
            wait(delay);
            delay = sc_core::SC_ZERO_TIME;
        }
        if (addr < tlm_map::REG_END) {
            reg_write(addr, get32(data), delay);
        } else {
            const std::size_t first = (addr - tlm_map::COS_BLOCK) / 2, count = len / 2;
            std::memcpy(reinterpret_cast<unsigned char*>(cos_.data()) + (addr - tlm_map::COS_BLOCK), data, len);
            shade_block(first, count, delay);
        }
        if (timing_ == tlm_timing::pin_accurate && costs_time(addr)) lock_.unlock();
        p.set_response_status(tlm::TLM_OK_RESPONSE);
    }

    unsigned transport_dbg(tlm::tlm_generic_payload& p) {
        const uint64_t addr = p.get_address();
        const uint64_t len = p.get_data_length();
        if (!p.is_read()) return 0;
        unsigned char* data = p.get_data_ptr();
        if (debug_within(addr, len, 0, tlm_map::REG_END)) {
            unsigned char regs[tlm_map::REG_END];
            for (uint64_t a = 0; a < tlm_map::REG_END; a += 4) put32(regs + a, reg_read(a));
            std::memcpy(data, regs + addr, len);
        } else if (debug_within(addr, len, tlm_map::COS_BLOCK, tlm_map::COS_BLOCK_END)) {
            std::memcpy(data, reinterpret_cast<const unsigned char*>(cos_.data()) + (addr - tlm_map::COS_BLOCK), len);
        } else if (debug_within(addr, len, tlm_map::RESULT_BLOCK, tlm_map::RESULT_BLOCK_END)) {
            std::memcpy(data, reinterpret_cast<const unsigned char*>(results_.data()) + (addr - tlm_map::RESULT_BLOCK),
                        len);
        } else {
            return 0;
        }
        return static_cast<unsigned>(len);
    }

private:
    static bool costs_time(uint64_t addr) {
        return addr <= tlm_map::COS || (addr >= tlm_map::COS_BLOCK && addr < tlm_map::COS_BLOCK_END);
    }

    void bind(device_t& d, std::size_t i) {
        if constexpr (variant::clocked) d.clk(*clk);
        d.ctl15(ctl15); d.ctl17(ctl17); d.ctl20(ctl20); d.ctl22(ctl22); d.ctl24(ctl24);
        d.in16_n(in16_n); d.in18_cos(in18_cos);
        d.in19_ksi_r(in19_ksi_r); d.in21_ksi_g(in21_ksi_g); d.in23_ksi_b(in23_ksi_b);
        d.out25_r(out[i][0]); d.out26_g(out[i][1]); d.out27_b(out[i][2]); d.out29_valid(out29[i]);
    }
    // The map's regions for check_access(): registers, COS_BLOCK (16-bit codes), RESULT_BLOCK (words).
    static constexpr tlm_region map_[] = {{0, tlm_map::REG_END, 4, true},
                                          {tlm_map::COS_BLOCK, tlm_map::COS_BLOCK_END, 2, false},
                                          {tlm_map::RESULT_BLOCK, tlm_map::RESULT_BLOCK_END, 4, false}};

    // Rejects a bad access with its response status, a warning and the error log bit; else true.
    bool check(tlm::tlm_generic_payload& p) {
        const int region = check_access(p, map_);
        if (region < 0) return false;
        const uint64_t addr = p.get_address();
        const uint64_t len = p.get_data_length();
        const bool is_write = p.is_write();
        const bool in_regs = region == 0, in_res = region == 2;
        const bool read_only = in_res || (in_regs && addr >= tlm_map::RESULT_R && addr <= tlm_map::STATUS);
        if (is_write && read_only)
            return reject(p, tlm::TLM_COMMAND_ERROR_RESPONSE, tlm_map::ERR_COMMAND, "write to a read-only register");
        if (!is_write) {
            bool ready = true;
            if (in_regs && addr >= tlm_map::RESULT_R && addr <= tlm_map::RESULT_B) ready = ready_;
            if (in_res) {
                const std::size_t first = (addr - tlm_map::RESULT_BLOCK) / tlm_map::RESULT_STRIDE;
                const std::size_t last = (addr + len - 1 - tlm_map::RESULT_BLOCK) / tlm_map::RESULT_STRIDE;
                for (std::size_t i = first; i <= last && ready; ++i) ready = shaded_[i] == generation_;
            }
            if (!ready)
                return reject(p, tlm::TLM_GENERIC_ERROR_RESPONSE, tlm_map::ERR_NOT_READY,
                              "result read before it is ready (no pixel shaded since N, KSI or OVF changed)");
        }
        return true;
    }

    uint32_t reg_read(uint64_t addr) const {
        switch (addr) {
            case tlm_map::N: return n_;
            case tlm_map::KSI_R: return ksi_[0];
            case tlm_map::KSI_G: return ksi_[1];
            case tlm_map::KSI_B: return ksi_[2];
            case tlm_map::COS: return cos_reg_;
            case tlm_map::RESULT_R: return rgb_[0];
            case tlm_map::RESULT_G: return rgb_[1];
            case tlm_map::RESULT_B: return rgb_[2];
            case tlm_map::STATUS: return (ready_ ? tlm_map::STATUS_READY : 0u) | errors_;
            case tlm_map::CONTROL:
                return (wrap_ ? tlm_map::CONTROL_OVF : 0u) | (variant::code << tlm_map::CONTROL_VARIANT_SHIFT) |
                       (timing_ == tlm_timing::pin_accurate ? tlm_map::CONTROL_TIMING : 0u);
            default: return 0;
        }
    }

    void invalidate() {
        ready_ = false;
        ++generation_;
    }

    void set_n(uint32_t n) {
        n_ = n & static_cast<uint32_t>(variant::n_fmt.mask());
        law_ = variant::law(n_, gen_);
        if constexpr (variant::clocked) latency_ = variant::latency(n_);
    }

    void reg_write(uint64_t addr, uint32_t v, sc_core::sc_time& delay) {
        switch (addr) {
            case tlm_map::N:
                set_n(v);
                load(ctl15, in16_n, n_, delay);
                invalidate();
                break;
            case tlm_map::KSI_R: case tlm_map::KSI_G: case tlm_map::KSI_B: {
                const std::size_t c = (addr - tlm_map::KSI_R) / 4;
                ksi_[c] = v & static_cast<uint32_t>(spec::ksi_fmt.mask());
                auto& ctl = c == 0 ? ctl20 : c == 1 ? ctl22 : ctl24;
                auto& d = c == 0 ? in19_ksi_r : c == 1 ? in21_ksi_g : in23_ksi_b;
                load(ctl, d, ksi_[c], delay);
                invalidate();
                break;
            }
            case tlm_map::COS: {
                cos_reg_ = v & static_cast<uint32_t>(spec::cos_fmt.mask());
                rgb_ = shade(cos_reg_, delay);
                ready_ = true;
                break;
            }
            case tlm_map::CONTROL: {
                if (v & tlm_map::CONTROL_CLEAR_ERR) errors_ = 0;
                const bool wrap = (v & tlm_map::CONTROL_OVF) != 0;
                if (wrap != wrap_) {
                    wrap_ = wrap;
                    invalidate();
                }
                break;
            }
            default: break;
        }
    }

    // A ctl15/20/22/24 pulse (Fig. 3): data, strobe high, falling edge latches.
    template <class T>
    void load(net<bool>& ctl, net<T>& d, uint64_t value, sc_core::sc_time& delay) {
        if (timing_ == tlm_timing::loosely_timed) {
            delay += t_.load_time();
            return;
        }
        d.write(T(value));
        ctl.write(true);
        wait(t_.load_pulse);
        ctl.write(false);
        wait(t_.load_pulse);
    }

    std::array<uint32_t, 3> golden(uint32_t code) const {
        const auto o = variant::outputs(law_, code, {ksi_[0], ksi_[1], ksi_[2]},
                                        wrap_ ? overflow_mode::wrap : overflow_mode::saturate);
        return {static_cast<uint32_t>(o[0]), static_cast<uint32_t>(o[1]), static_cast<uint32_t>(o[2])};
    }

    // A clocked device's clock: the first falling edge at or after t (edges as sc_clock puts them).
    sc_core::sc_time next_fall(const sc_core::sc_time& t) const {
        const sc_core::sc_time high = t_.clk_period * 0.5;
        const uint64_t p = t_.clk_period.value();
        const uint64_t periods = t <= high ? 0 : (t.value() - high.value() + p - 1) / p;
        return sc_core::sc_time::from_value(high.value() + periods * p);
    }

    // Loosely timed: when a pixel started at local time `start` ends in pin-accurate mode.
    // UA 60553 family: Fig. 3's strobe period. Clocked: pixel_pins() worked out: strobe 17 falls
    // at the first falling edge >= start + t_high / 2, the next rising edge samples it, done rises
    // latency(n) clocks later, output 29 a gate delay after the later of done and strobe 17's rise.
    sc_core::sc_time pixel_end(const sc_core::sc_time& start) const {
        if constexpr (variant::clocked) {
            const sc_core::sc_time fall = next_fall(start + t_.t_high / 2);
            const sc_core::sc_time done =
                fall + (t_.clk_period - t_.clk_period * 0.5) + t_.clk_period * static_cast<double>(latency_);
            return std::max(done, fall + t_.t_low) + gate_;
        } else {
            return start + t_.pixel_time();
        }
    }

    // Pin-accurate: one pixel through the devices' pins (the caller's thread waits).
    std::array<uint32_t, 3> pixel_pins(uint32_t code) {
        in18_cos.write(code);  // half of strobe 17's high phase ahead of its fall: set-up time
        wait(t_.t_high / 2);
        if constexpr (variant::clocked) {  // the fall synchronous to the clock: its falling edge
            const sc_core::sc_time now = sc_core::sc_time_stamp(), fall = next_fall(now);
            if (fall > now) wait(fall - now);
        }
        ctl17.write(false);  // RG2 latches: Fig. 3
        wait(t_.t_low);
        ctl17.write(true);
        const std::size_t i = wrap_ ? 1 : 0;
        if constexpr (variant::clocked) {
            wait(out29[i].posedge_event());  // output 29 = strobe 17 AND done: outputs 25..27 valid
        } else {
            wait(t_.t_high / 2);  // output 29 (strobe 17 through a wire) rose at the strobe's rise
        }
        const auto& o = out[i];
        return {static_cast<uint32_t>(o[0].read().to_uint64()), static_cast<uint32_t>(o[1].read().to_uint64()),
                static_cast<uint32_t>(o[2].read().to_uint64())};
    }

    // One pixel: golden model and its delay (loosely timed) or strobe 17 through the device.
    std::array<uint32_t, 3> shade(uint32_t code, sc_core::sc_time& delay) {
        if (timing_ == tlm_timing::pin_accurate) return pixel_pins(code);
        const sc_core::sc_time now = sc_core::sc_time_stamp();
        delay = pixel_end(now + delay) - now;
        return golden(code);
    }

    void shade_block(std::size_t first, std::size_t count, sc_core::sc_time& delay) {
        if (timing_ == tlm_timing::loosely_timed) {
            // The hot path: the golden model per pixel, one annotation for the whole burst.
            for (std::size_t i = first; i < first + count; ++i) {
                const auto rgb = golden(cos_[i]);
                results_[i] = {rgb[0], rgb[1], rgb[2], cos_[i]};
                shaded_[i] = generation_;
            }
            if constexpr (variant::clocked) {
                // Every pixel ends a fixed time after its strobe's falling clock edge, so each one
                // after the first starts at the same phase and takes the same time as the second.
                const sc_core::sc_time now = sc_core::sc_time_stamp();
                sc_core::sc_time t = pixel_end(now + delay);
                if (count > 1) t += (pixel_end(t) - t) * static_cast<double>(count - 1);
                delay = t - now;
            } else {
                delay += t_.pixel_time() * static_cast<double>(count);
            }
            return;
        }
        for (std::size_t i = first; i < first + count; ++i) {
            const auto rgb = pixel_pins(cos_[i]);
            results_[i] = {rgb[0], rgb[1], rgb[2], cos_[i]};
            shaded_[i] = generation_;
        }
    }

    config_t gen_;
    tlm_strobe_timing t_;
    sc_core::sc_time gate_;  // output 29's AND gate (a clocked device's pixel ends there)

    // The model's state (registers, latched results, windows).
    uint32_t n_ = 0, cos_reg_ = 0;
    std::array<uint32_t, 3> ksi_{}, rgb_{};
    bool ready_ = false, wrap_ = false;
    uint64_t law_ = 0;      // the golden model's per-n value (a(n), or n)
    unsigned latency_ = 1;  // a clocked device's clocks from taking the strobe to done, for n_
    std::array<uint16_t, tlm_map::BLOCK_PIXELS> cos_{};
    std::array<std::array<uint32_t, 4>, tlm_map::BLOCK_PIXELS> results_{};
    std::array<uint64_t, tlm_map::BLOCK_PIXELS> shaded_{};  // generation a pixel was shaded in
    uint64_t generation_ = 1;  // (STATUS bits 5:1, the bus-error log, is tlm_target_base's errors_)
};

using specular_tlm_ua60553 = specular_tlm<a_gen_linear>;
using specular_tlm_ua22802 = specular_tlm<a_gen_rom>;
using specular_tlm_ua60553_tuned = specular_tlm<a_gen_tuned>;
using specular_tlm_squared = specular_tlm<squared_device>;
using specular_tlm_sqmul = specular_tlm<sqmul_device>;

}  // namespace shading
