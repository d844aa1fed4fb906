// TLM-2.0 wrapper of the interpolation paper's raster-line interpolator (interp/interp_line_unit.h, cubic: the
// degree is fixed for this unit): a tlm_utils::simple_target_socket `socket` with b_transport and
// transport_dbg over the register map below, in one of two timing modes chosen at construction
// (tlm_timing, tlm_target_base.h):
//   pin_accurate   - the wrapper owns the signal-level unit and drives its clock and its
//                    start/ready handshake from the b_transport caller's thread with wait(): a
//                    burst costs the unit's real clocks and the waveform shows them;
//   loosely_timed  - the golden chain (golden_interp_line) computes the pixels; the access is
//                    annotated with the same delay (added to b_transport's delay argument).
// Both give bit-identical data (testbenches/tlm/test_line_tlm.cpp).
//
// Register map (byte addresses; registers are 32-bit words in host byte order, little-endian on
// the supported hosts; reserved bits read 0, writes to them are ignored):
//   0x000 STATUS   RO  bit 0 READY (a burst has run: PIXEL_BLOCK holds its pixels); bits 6:1
//                      sticky bus-error log (1 address, 2 size or alignment, 3 byte enables,
//                      4 command, 5 read before ready, 6 interval length outside 1..2^M), cleared
//                      by CONTROL.CLEAR_ERR; bits 31:16 pixels of the last burst.
//   0x004 CONTROL  RW  read-only fields: bits 3:0 M (intervals of 2^M pixels), bit 4 sample set
//                      (0 case 1, 1 case 2), bit 5 /3 (0 shift-and-add, 1 exact), bit 6 grouping
//                      (1 the interpolation paper's partial sum), bit 8 TIMING (0 loosely timed, 1 pin-accurate),
//                      bits 13:12 DEGREE (3, cubic); bit 31 CLEAR_ERR, write 1 to clear STATUS
//                      bits 6:1, reads 0.
//   0x1000-0x1FFF INTERVAL_BLOCK RW  256 intervals x 16 bytes, interval j at 0x1000 + 16j:
//                      +0 I1, +2 I2, +4 I3, +6 I4 (16-bit Q8.8 sample codes), +8 LEN (32-bit,
//                      pixels 1..2^M), +12 reserved. A write of 16K bytes at interval j runs
//                      intervals j .. j+K-1 back to back through the unit (one burst) and puts
//                      their pixels, in order, at PIXEL_BLOCK pixel 0 onwards; a read returns the
//                      intervals last written.
//   0x10000-0x1FFFF PIXEL_BLOCK RO  16384 pixels (256 x 2^6) x 4 bytes: the Q16.16 signed pixels
//                      (i_px bus bits) of the last burst, pixel p at 0x10000 + 4p. Any 4-aligned
//                      read of a multiple of 4 bytes within the last burst's pixels.
// Access rules and errors (each also an SC_REPORT_WARNING with id shading/tlm; the windows, the
// unit and STATUS's READY and pixel count are unchanged; no time is charged):
//   byte-enable pointer set                             -> TLM_BYTE_ENABLE_ERROR_RESPONSE
//   start address outside the map                       -> TLM_ADDRESS_ERROR_RESPONSE
//   register access not exactly 4 bytes at a 4-aligned address, an INTERVAL_BLOCK access not
//   16-aligned or not a multiple of 16 bytes, a PIXEL_BLOCK read not 4-aligned or not a multiple
//   of 4 bytes, running past the window's end, or streaming width != length
//                                                       -> TLM_BURST_ERROR_RESPONSE
//   write to STATUS or PIXEL_BLOCK                      -> TLM_COMMAND_ERROR_RESPONSE
//   read of PIXEL_BLOCK before a burst, or past its pixels -> TLM_GENERIC_ERROR_RESPONSE
//   an interval of a burst with LEN outside 1..2^M      -> TLM_GENERIC_ERROR_RESPONSE (bit 6)
// TLM_IGNORE_COMMAND completes with TLM_OK_RESPONSE and does nothing.
// Access time (both modes): an INTERVAL_BLOCK write of P pixels in all costs P + 1 clocks of the
// unit (interp_line_unit.h: "a line of W pixels: W + 1 clocks from its first samples to its last
// pixel"; each burst starts from an idle unit); everything else 0. In pin-accurate mode a burst
// first waits the incoming delay (and returns it as 0); other accesses return at once.
// Debug transport: reads of any byte range within one region (registers 0x000-0x007,
// INTERVAL_BLOCK, PIXEL_BLOCK) without side effects, readiness checks or time; debug writes are
// not supported (0 bytes transferred).
#pragma once

#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <systemc>
#include <vector>

#include "arith/interp_arith.h"
#include "formats/interp_formats.h"
#include "interp/interp_line_unit.h"
#include "tlm/tlm_target_base.h"

namespace shading {

namespace line_tlm_map {
inline constexpr uint64_t STATUS = 0x000, CONTROL = 0x004, REG_END = 0x008;
inline constexpr uint64_t INTERVAL_BLOCK = 0x1000, INTERVAL_STRIDE = 16;
inline constexpr std::size_t BLOCK_INTERVALS = 256;
inline constexpr uint64_t INTERVAL_BLOCK_END = INTERVAL_BLOCK + INTERVAL_STRIDE * BLOCK_INTERVALS;
inline constexpr uint64_t IV_I1 = 0, IV_LEN = 8;  // offsets within an interval (I_k at 2(k - 1))
inline constexpr uint64_t PIXEL_BLOCK = 0x10000;
inline constexpr std::size_t BLOCK_PIXELS = BLOCK_INTERVALS << interp::m_max;  // 16384
inline constexpr uint64_t PIXEL_BLOCK_END = PIXEL_BLOCK + 4 * BLOCK_PIXELS;
inline constexpr uint32_t STATUS_READY = 1u << 0;
inline constexpr uint32_t ERR_ADDRESS = tlm_err::address, ERR_SIZE = tlm_err::size,
                          ERR_BYTE_ENABLE = tlm_err::byte_enable, ERR_COMMAND = tlm_err::command,
                          ERR_NOT_READY = tlm_err::not_ready, ERR_LENGTH = 1u << 6;
inline constexpr uint32_t ERR_MASK = 0x7Eu;
inline constexpr unsigned STATUS_PIXELS_SHIFT = 16;
inline constexpr uint32_t CONTROL_M_MASK = 0xFu, CONTROL_SET = 1u << 4, CONTROL_DIV3_EXACT = 1u << 5,
                          CONTROL_PARTIAL_SUM = 1u << 6, CONTROL_TIMING = 1u << 8,
                          CONTROL_DEGREE_SHIFT = 12, CONTROL_CLEAR_ERR = 1u << 31;
}  // namespace line_tlm_map

// The unit's clock as the pin-accurate wrapper drives it (20 ns, 50 %: the interpolation paper's benches).
struct line_tlm_clock {
    sc_core::sc_time high{10, sc_core::SC_NS};
    sc_core::sc_time low{10, sc_core::SC_NS};
    sc_core::sc_time period() const { return high + low; }
    // A burst of `pixels` pixels: pixels + 1 clocks (interp_line_unit.h's latency).
    sc_core::sc_time burst_time(std::size_t pixels) const { return period() * static_cast<double>(pixels + 1); }
};

template <unsigned M, interp::sample_set SET, interp::div3_mode DIV,
          interp::div3_grouping G = interp::div3_grouping::whole_sum>
class line_tlm : public tlm_target_base {
    using unit_t = interp_line_unit<M, SET, DIV, G>;
    using sample_t = sc_dt::sc_uint<interp::sample_fmt.width>;
    using coef_t = sc_dt::sc_uint<interp::coef_fmt.width>;
    using len_t = typename unit_t::len_t;
    template <class T>
    using net = sc_core::sc_signal<T, sc_core::SC_MANY_WRITERS>;  // driven by whichever caller's thread

public:
    static constexpr unsigned n_pixels = 1u << M;
    tlm_utils::simple_target_socket<line_tlm> socket{"socket"};

    // Pin-accurate mode: the unit's pins. The clock rests high between bursts (as after the rising
    // edge of a burst's last pixel); the wrapper drives it only while a burst runs.
    net<bool> clk{"clk", true}, start{"start", false};
    net<len_t> len{"len"};
    net<sample_t> i1{"i1"}, i2{"i2"}, i3{"i3"}, i4{"i4"};
    sc_core::sc_signal<coef_t> i_px{"i_px"};
    sc_core::sc_signal<bool> valid{"valid"}, last{"last"}, ready{"ready"};
    std::unique_ptr<unit_t> unit;  // pin-accurate mode only

    line_tlm(const sc_core::sc_module_name& name, tlm_timing timing, const line_tlm_clock& ck = {},
             const interp_delays& delays = {})
        : tlm_target_base(name, timing), ck_(ck) {
        socket.register_b_transport(this, &line_tlm::b_transport);
        socket.register_transport_dbg(this, &line_tlm::transport_dbg);
        if (timing_ == tlm_timing::pin_accurate) {
            unit = std::make_unique<unit_t>("unit", delays);
            unit->clk(clk); unit->start(start); unit->len(len);
            unit->i1(i1); unit->i2(i2); unit->i3(i3); unit->i4(i4);
            unit->i_px(i_px); unit->valid(valid); unit->last(last); unit->ready(ready);
        }
    }

    tlm_timing timing() const { return timing_; }
    const line_tlm_clock& clock() const { return ck_; }

    void b_transport(tlm::tlm_generic_payload& p, sc_core::sc_time& delay) {
        namespace m = line_tlm_map;
        if (!check(p)) return;
        const uint64_t addr = p.get_address();
        const unsigned len_b = p.get_data_length();
        unsigned char* data = p.get_data_ptr();
        if (p.is_read()) {
            if (addr < m::REG_END) put32(data, reg_read(addr));
            else if (addr < m::INTERVAL_BLOCK_END) std::memcpy(data, intervals_.data() + (addr - m::INTERVAL_BLOCK), len_b);
            else std::memcpy(data, reinterpret_cast<const unsigned char*>(pixels_.data()) + (addr - m::PIXEL_BLOCK), len_b);
            p.set_response_status(tlm::TLM_OK_RESPONSE);
            return;
        }
        if (addr < m::REG_END) {  // CONTROL: only CLEAR_ERR is writable
            if (get32(data) & m::CONTROL_CLEAR_ERR) errors_ = 0;
            p.set_response_status(tlm::TLM_OK_RESPONSE);
            return;
        }
        // An INTERVAL_BLOCK burst: store the intervals (reserved word 0), run them, keep the pixels.
        const std::size_t first = (addr - m::INTERVAL_BLOCK) / m::INTERVAL_STRIDE, count = len_b / m::INTERVAL_STRIDE;
        if (timing_ == tlm_timing::loosely_timed) {
            // The hot path: per interval the golden chain (golden_interp_line's steps) writes its
            // pixels straight into the window; no allocation, one annotation for the burst.
            std::size_t px = 0;
            for (std::size_t k = 0; k < count; ++k) {
                const interp::interval_samples iv = store_interval(data + k * m::INTERVAL_STRIDE, first + k);
                interp::golden_fd_to(interp::golden_cubic_coefs(iv.i, SET, DIV, G), M, iv.len, pixels_.data() + px);
                px += iv.len;
            }
            pixel_count_ = px;
            delay += ck_.burst_time(px);
        } else {
            std::vector<interp::interval_samples> ivs(count);
            for (std::size_t k = 0; k < count; ++k) ivs[k] = store_interval(data + k * m::INTERVAL_STRIDE, first + k);
            lock_.lock();  // one initiator at a time on the pins
            wait(delay);
            delay = sc_core::SC_ZERO_TIME;
            pixel_count_ = run_unit(ivs);
            lock_.unlock();
        }
        ready_ = true;
        p.set_response_status(tlm::TLM_OK_RESPONSE);
    }

    unsigned transport_dbg(tlm::tlm_generic_payload& p) {
        namespace m = line_tlm_map;
        const uint64_t addr = p.get_address();
        const uint64_t n = p.get_data_length();
        if (!p.is_read()) return 0;
        unsigned char* data = p.get_data_ptr();
        if (debug_within(addr, n, 0, m::REG_END)) {
            unsigned char regs[m::REG_END];
            for (uint64_t a = 0; a < m::REG_END; a += 4) put32(regs + a, reg_read(a));
            std::memcpy(data, regs + addr, n);
        } else if (debug_within(addr, n, m::INTERVAL_BLOCK, m::INTERVAL_BLOCK_END)) {
            std::memcpy(data, intervals_.data() + (addr - m::INTERVAL_BLOCK), n);
        } else if (debug_within(addr, n, m::PIXEL_BLOCK, m::PIXEL_BLOCK_END)) {
            std::memcpy(data, reinterpret_cast<const unsigned char*>(pixels_.data()) + (addr - m::PIXEL_BLOCK), n);
        } else {
            return 0;
        }
        return static_cast<unsigned>(n);
    }

private:

    // Copies one interval of a burst into INTERVAL_BLOCK slot j (reserved word 0) and decodes it
    // (check() has already refused a LEN outside 1..2^M).
    interp::interval_samples store_interval(const unsigned char* src, std::size_t j) {
        namespace m = line_tlm_map;
        unsigned char* dst = intervals_.data() + j * m::INTERVAL_STRIDE;
        std::memcpy(dst, src, 12);
        std::memset(dst + 12, 0, 4);
        interp::interval_samples iv;
        for (unsigned s = 0; s < 4; ++s) iv.i[s] = get16(src + 2 * s);
        iv.len = get32(src + m::IV_LEN);
        return iv;
    }

    // The map's regions for check_access(): registers, INTERVAL_BLOCK (16-byte intervals), PIXEL_BLOCK.
    static constexpr tlm_region map_[] = {
        {0, line_tlm_map::REG_END, 4, true},
        {line_tlm_map::INTERVAL_BLOCK, line_tlm_map::INTERVAL_BLOCK_END, line_tlm_map::INTERVAL_STRIDE, false},
        {line_tlm_map::PIXEL_BLOCK, line_tlm_map::PIXEL_BLOCK_END, 4, false}};

    // Rejects a bad access with its response status, a warning and the error log bit; else true.
    bool check(tlm::tlm_generic_payload& p) {
        namespace m = line_tlm_map;
        const int region = check_access(p, map_);
        if (region < 0) return false;
        const uint64_t addr = p.get_address();
        const uint64_t n = p.get_data_length();
        const bool in_regs = region == 0, in_iv = region == 1, in_px = region == 2;
        const bool read_only = in_px || (in_regs && addr == m::STATUS);
        if (p.is_write() && read_only)
            return reject(p, tlm::TLM_COMMAND_ERROR_RESPONSE, m::ERR_COMMAND, "write to a read-only register");
        if (p.is_read() && in_px && (!ready_ || (addr + n - m::PIXEL_BLOCK) / 4 > pixel_count_))
            return reject(p, tlm::TLM_GENERIC_ERROR_RESPONSE, m::ERR_NOT_READY,
                          "pixel read before it is ready (past the last burst's pixels, or no burst yet)");
        if (p.is_write() && in_iv) {
            for (uint64_t k = 0; k < n; k += m::INTERVAL_STRIDE) {
                const uint32_t l = get32(p.get_data_ptr() + k + m::IV_LEN);
                if (l == 0 || l > n_pixels)
                    return reject(p, tlm::TLM_GENERIC_ERROR_RESPONSE, m::ERR_LENGTH,
                                  "interval length outside 1..2^M pixels");
            }
        }
        return true;
    }

    uint32_t reg_read(uint64_t addr) const {
        namespace m = line_tlm_map;
        if (addr == m::STATUS)
            return (ready_ ? m::STATUS_READY : 0u) | errors_ | static_cast<uint32_t>(pixel_count_ << m::STATUS_PIXELS_SHIFT);
        if (addr == m::CONTROL)
            return M | (SET == interp::sample_set::case2 ? m::CONTROL_SET : 0u) |
                   (DIV == interp::div3_mode::exact ? m::CONTROL_DIV3_EXACT : 0u) |
                   (G == interp::div3_grouping::partial_sum ? m::CONTROL_PARTIAL_SUM : 0u) |
                   (timing_ == tlm_timing::pin_accurate ? m::CONTROL_TIMING : 0u) | (3u << m::CONTROL_DEGREE_SHIFT);
        return 0;
    }

    void present(const interp::interval_samples& iv) {
        i1.write(iv.i[0]); i2.write(iv.i[1]); i3.write(iv.i[2]); i4.write(iv.i[3]);
        len.write(len_t(iv.len));
        start.write(true);
    }

    // The handshake of interp_line_unit.h from the caller's thread: the samples go on the inputs
    // (clock high, the unit idle), then one clock after another; at each rising edge, in its delta,
    // the unit's outputs of the clock that just ended are read (a pixel where valid = 1) and the
    // next interval is presented if start and ready took this one. The burst ends at the edge of
    // its last pixel: pixels + 1 clocks after the first samples.
    std::size_t run_unit(const std::vector<interp::interval_samples>& ivs) {
        std::size_t total = 0, got = 0, accepted = 0;
        for (const auto& iv : ivs) total += iv.len;
        present(ivs[0]);
        while (got < total) {
            wait(ck_.high);
            clk.write(false);  // rg_i latch the samples
            wait(ck_.low);
            clk.write(true);
            wait(clk.posedge_event());  // the edge's delta: reads give the values before it
            if (valid.read()) pixels_[got++] = static_cast<uint32_t>(i_px.read().to_uint64());
            if (start.read() && ready.read()) {
                if (++accepted < ivs.size()) present(ivs[accepted]);
                else start.write(false);
            }
        }
        return total;
    }

    line_tlm_clock ck_;

    // The model's state: the windows, READY, the last burst's pixel count, the bus-error log.
    std::array<unsigned char, line_tlm_map::INTERVAL_BLOCK_END - line_tlm_map::INTERVAL_BLOCK> intervals_{};
    std::array<uint32_t, line_tlm_map::BLOCK_PIXELS> pixels_{};
    std::size_t pixel_count_ = 0;
    bool ready_ = false;  // (the bus-error log is tlm_target_base's errors_)
};

}  // namespace shading
