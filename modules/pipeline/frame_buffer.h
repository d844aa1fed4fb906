// Frame buffer of the shading pipeline (ours; the interpolation paper leaves it open): the block
// library's RAM (blocks/ram.h), one pipeline::frame_word_width-bit word per pixel ({r, g, b}, three
// pixel_fmt codes: Q8.8 unsigned per channel), pitch x height words with the pitch the width rounded
// up to a power of two, so the word of (x, y) is at {y, x} (wiring, no multiplier). Its write port
// is the pixel stream: at a rising edge of clk where `valid` is 1 it stores r, g, b at (x, y).
// A write outside width x height is bad input: the frame check drops it (the RAM's `we` is 0) and
// sets the sticky flag `out_of_frame`, and reports it (shading/input). rtl/pipeline/frame_buffer.v
// is the twin. The testbench and the render programs read the words back through pixel() (the RAM's
// back door); written() and writes() are a monitor's counts (the RAM's write hook), not hardware.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <systemc>
#include <vector>

#include "blocks/ram.h"
#include "core/report_ids.h"
#include "core/strobe_gate.h"
#include "formats/interp_formats.h"
#include "formats/pipeline_formats.h"

namespace shading {

class frame_buffer : public sc_core::sc_module {
public:
    static constexpr unsigned coord_width = 16;
    static constexpr unsigned channel_width = pipeline::pixel_fmt.width;
    // {y, x}: any frame the coordinates can name.
    using store = ram<pipeline::frame_word_width, 2 * coord_width>;
    using coord_t = sc_dt::sc_uint<coord_width>;
    using px_t = sc_dt::sc_uint<interp::sample_fmt.width>;
    using rgb = std::array<uint16_t, 3>;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> valid{"valid"};
    sc_core::sc_in<coord_t> x{"x"}, y{"y"};
    sc_core::sc_in<px_t> r{"r"}, g{"g"}, b{"b"};

    // Nets: the RAM's write port (the frame check and the address wiring drive it), its read port
    // (unused: address 0), its overflow flag, and the frame check's flag.
    sc_core::sc_signal<bool> mem_we{"mem_we"}, mem_overflow{"mem_overflow"}, out_of_frame{"out_of_frame"};
    sc_core::sc_signal<store::addr_t> mem_wa{"mem_wa"}, mem_ra{"mem_ra"};
    sc_core::sc_signal<store::word> mem_wd{"mem_wd"}, mem_rd{"mem_rd"};
    store ram_frame;

    SC_HAS_PROCESS(frame_buffer);
    frame_buffer(const sc_core::sc_module_name& name, unsigned width, unsigned height)
        : sc_module(name), ram_frame("ram_frame", uint64_t(pipeline::frame_pitch(width)) * height), width_(width),
          height_(height), x_bits_(interp::code_width(pipeline::frame_pitch(width))),
          written_(std::size_t(width) * height, 0) {
        if (pipeline::frame_pitch(width) == 1) x_bits_ = 0;  // a one-pixel row: the address is y
        ram_frame.clk(clk); ram_frame.we(mem_we); ram_frame.wa(mem_wa); ram_frame.wd(mem_wd); ram_frame.ra(mem_ra);
        ram_frame.rd(mem_rd); ram_frame.overflow(mem_overflow);
        ram_frame.on_write([this](uint64_t a, uint64_t w) { monitor(a, w); });
        SC_METHOD(write_port);  // the frame check and {y, x}: combinational
        sensitive << valid << x << y << r << g << b;
        SC_METHOD(check);
        sensitive << clk.pos();
        dont_initialize();
    }

    unsigned width() const { return width_; }
    unsigned height() const { return height_; }
    // Words and bits of the RAM (pitch x height words of frame_word_width bits).
    uint64_t words() const { return ram_frame.depth(); }
    uint64_t bits() const { return ram_frame.depth() * pipeline::frame_word_width; }
    // The codes stored at (px, py) (0 before any write), read through the RAM's back door.
    rgb pixel(unsigned px, unsigned py) const {
        if (px >= width_ || py >= height_) throw std::out_of_range("frame_buffer::pixel outside the frame");
        return unpack(ram_frame.word_at(address(px, py)));
    }
    // How many times (x, y) was written (0: never; more than 1: an interval overlapped another).
    uint8_t written(unsigned px, unsigned py) const { return written_.at(std::size_t(py) * width_ + px); }
    std::size_t writes() const { return writes_; }
    // A write was dropped: outside the frame, or (never, by the frame check) beyond the RAM's words.
    bool overflow() const { return out_of_frame.read() || mem_overflow.read(); }
    // Called after every stored pixel (the testbench's monitor): x, y, codes, time of the write.
    void on_write(std::function<void(unsigned, unsigned, const rgb&)> f) { sink_ = std::move(f); }

private:
    uint64_t address(unsigned px, unsigned py) const { return (uint64_t(py) << x_bits_) | px; }
    static rgb unpack(uint64_t w) {
        const uint64_t mask = (uint64_t(1) << channel_width) - 1;
        return {static_cast<uint16_t>(w >> (2 * channel_width) & mask),
                static_cast<uint16_t>(w >> channel_width & mask), static_cast<uint16_t>(w & mask)};
    }
    bool in_frame() const { return x.read().to_uint() < width_ && y.read().to_uint() < height_; }

    // The RAM's write port: we = valid and (x, y) in the frame; wa = {y, x}; wd = {r, g, b}.
    void write_port() {
        const bool inside = in_frame();
        mem_we.write(valid.read() && inside);
        mem_wa.write(inside ? address(x.read().to_uint(), y.read().to_uint()) : 0);
        mem_wd.write((r.read().to_uint64() << (2 * channel_width)) | (g.read().to_uint64() << channel_width) |
                     b.read().to_uint64());
    }
    // The frame check's flag and report, at the edges the RAM would have written. Woken at rising
    // edges only while `valid` may be 1 (core/strobe_gate.h, as the RAM's own port): a Horner pixel
    // is valid one clock in six, no wake-up in the other five.
    void check() {
        if (!valid_gate_.sample(clk, valid)) return;
        if (in_frame()) return;
        out_of_frame.write(true);
        std::ostringstream os;
        os << name() << ": write to (" << x.read().to_uint() << ", " << y.read().to_uint() << ") outside the "
           << width_ << "x" << height_ << " frame at " << sc_core::sc_time_stamp() << "; dropped";
        SC_REPORT_WARNING(msg::input, os.str().c_str());
    }
    void monitor(uint64_t a, uint64_t w) {
        const unsigned px = unsigned(a & ((uint64_t(1) << x_bits_) - 1)), py = unsigned(a >> x_bits_);
        uint8_t& n = written_[std::size_t(py) * width_ + px];
        if (n < 255) ++n;
        ++writes_;
        if (sink_) sink_(px, py, unpack(w));
    }

    unsigned width_, height_, x_bits_;
    std::vector<uint8_t> written_;
    std::size_t writes_ = 0;
    strobe_gate valid_gate_;
    std::function<void(unsigned, unsigned, const rgb&)> sink_;
};

}  // namespace shading
