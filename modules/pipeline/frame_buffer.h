// Frame buffer of the shading pipeline (ours; the interpolation paper leaves it open): a memory of width x height
// pixels, three pixel_fmt codes each (Q8.8 unsigned per channel). A synchronous write port: at a
// rising edge of clk where `valid` is 1 it stores r, g, b at (x, y). Not hardware we model in
// detail: the testbench and the render program read it back through pixel()/written().
// A write outside the frame is bad input: reported (shading/input) and dropped.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <sstream>
#include <systemc>
#include <vector>

#include "core/report_ids.h"
#include "formats/interp_formats.h"

namespace shading {

class frame_buffer : public sc_core::sc_module {
public:
    static constexpr unsigned coord_width = 16;
    using coord_t = sc_dt::sc_uint<coord_width>;
    using px_t = sc_dt::sc_uint<interp::sample_fmt.width>;
    using rgb = std::array<uint16_t, 3>;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> valid{"valid"};
    sc_core::sc_in<coord_t> x{"x"}, y{"y"};
    sc_core::sc_in<px_t> r{"r"}, g{"g"}, b{"b"};

    SC_HAS_PROCESS(frame_buffer);
    frame_buffer(const sc_core::sc_module_name& name, unsigned width, unsigned height)
        : sc_module(name), width_(width), height_(height), px_(std::size_t(width) * height),
          written_(std::size_t(width) * height, 0) {
        SC_METHOD(on_clock);
        sensitive << clk.pos();
        dont_initialize();
    }

    unsigned width() const { return width_; }
    unsigned height() const { return height_; }
    const rgb& pixel(unsigned px, unsigned py) const { return px_.at(std::size_t(py) * width_ + px); }
    // How many times (x, y) was written (0: never; more than 1: an interval overlapped another).
    uint8_t written(unsigned px, unsigned py) const { return written_.at(std::size_t(py) * width_ + px); }
    std::size_t writes() const { return writes_; }
    // Called after every stored pixel (the testbench's monitor): x, y, codes, time of the write.
    void on_write(std::function<void(unsigned, unsigned, const rgb&)> f) { sink_ = std::move(f); }

private:
    // Woken at rising edges only while `valid` may be 1: at an edge where it is 0 the process sleeps
    // until `valid` rises (just after some rising edge) and samples again from the next rising edge
    // (a Horner pixel is valid one clock in six: no wake-up in the other five).
    void on_clock() {
        if (waiting_) {  // `valid` has just risen: its first sampling edge is the next one
            waiting_ = false;
            next_trigger(clk.posedge_event());
            return;
        }
        if (!valid.read()) {
            waiting_ = true;
            next_trigger(valid.posedge_event());
            return;
        }
        const unsigned px = x.read().to_uint(), py = y.read().to_uint();
        if (px >= width_ || py >= height_) {
            std::ostringstream os;
            os << name() << ": write to (" << px << ", " << py << ") outside the " << width_ << "x" << height_
               << " frame at " << sc_core::sc_time_stamp() << "; dropped";
            SC_REPORT_WARNING(msg::input, os.str().c_str());
            return;
        }
        const std::size_t i = std::size_t(py) * width_ + px;
        px_[i] = {static_cast<uint16_t>(r.read().to_uint()), static_cast<uint16_t>(g.read().to_uint()),
                  static_cast<uint16_t>(b.read().to_uint())};
        if (written_[i] < 255) ++written_[i];
        ++writes_;
        if (sink_) sink_(px, py, px_[i]);
    }

    unsigned width_, height_;
    std::vector<rgb> px_;
    std::vector<uint8_t> written_;
    std::size_t writes_ = 0;
    bool waiting_ = false;
    std::function<void(unsigned, unsigned, const rgb&)> sink_;
};

}  // namespace shading
