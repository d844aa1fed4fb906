// Pixel controller for the Horner evaluators (ours; the interpolation paper leaves the control open): a clocked
// FSM on the rising edge of clk that takes an interval from the sample stage and issues its pixels
// to the three channels' Fig. 4 Horner units, pixel k at t = k << (8 - m) (t = k / 2^m, Q1.8).
// - Interval hand-over: with samples_ready = 1 and the interval registers free it raises ld_e for
//   one clock and captures the job's descriptor (y, x0, len, m, deg2); the interval registers latch
//   where ld_e falls, the coefficient units' registers half a clock later, so A..D are valid one
//   clock after the fall, where the Horner units may take the interval's first pixel.
// - The registers are free once the previous interval's last pixel is in its last two micro-steps
//   (the ones after the last read of A, B or C): its last read of D (cubic step 6) or C (degree 2
//   step 4) is at the falling edge where the coefficient registers latch the new samples, whose
//   values arrive a clock-to-output later. So intervals follow each other with no idle clock.
// - Pixels: `start` follows horner_ctrl's rule (taken at a rising edge where start = 1 and the unit
//   is idle or done); at the taking edge t, px_x and px_y are set for that pixel, and deg2 / deg_sel
//   at an interval's first pixel. The pixel leaves at its done edge, where the frame buffer reads
//   the px_x / px_y set at its taking edge. 6 clocks per cubic pixel, 4 per quadratic one.
#pragma once

#include <systemc>

#include "core/timed_block.h"
#include "formats/interp_formats.h"

namespace shading {

class horner_pixel_ctrl : public sc_core::sc_module, public timed_block {
public:
    using coord_t = sc_dt::sc_uint<16>;
    using t_t = sc_dt::sc_uint<interp::t_fmt.width>;
    using sel_t = sc_dt::sc_uint<1>;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> samples_ready{"samples_ready"};
    sc_core::sc_in<coord_t> y{"y"}, x0{"x0"};
    sc_core::sc_in<sc_dt::sc_uint<16>> len{"len"};
    sc_core::sc_in<sc_dt::sc_uint<4>> m{"m"};
    sc_core::sc_in<sel_t> deg2_in{"deg2_in"};
    sc_core::sc_in<bool> busy{"busy"}, done{"done"};  // channel R's Horner unit (the three run in step)
    sc_core::sc_out<bool> ld_e{"ld_e"}, start{"start"}, deg2{"deg2"};
    sc_core::sc_out<sel_t> deg_sel{"deg_sel"};
    sc_core::sc_out<t_t> t{"t"};
    sc_core::sc_out<coord_t> px_x{"px_x"}, px_y{"px_y"};

    SC_HAS_PROCESS(horner_pixel_ctrl);
    explicit horner_pixel_ctrl(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_clock);
        sensitive << clk.pos();
        dont_initialize();
    }

    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }
    const sc_core::sc_port_base* clock_port() const override { return &clk; }
    bool switches_on_rising_edge() const override { return true; }

    // No interval pending or running and no pixel in flight.
    bool idle() const { return !cur_.active && !pend_.active && !ld_e_ && !in_flight_; }
    std::size_t intervals() const { return intervals_; }

private:
    struct interval {
        bool active = false, deg2 = false;
        unsigned y = 0, x0 = 0, len = 0, m = 0, issued = 0;
    };

    void on_clock() {
        const bool dn = done.read(), bz = busy.read();
        if (dn) in_flight_ = false;
        // A pixel is taken here (horner_ctrl's rule, read before this edge).
        if (start_ && (!bz || dn)) {
            if (cur_.issued == cur_.len && pend_.active) {
                cur_ = pend_;
                pend_.active = false;
                deg2.write(cur_.deg2);
                deg_sel.write(cur_.deg2 ? 1 : 0);
                ++intervals_;
            }
            t.write(t_t(cur_.issued << (interp::t_fmt.frac - cur_.m)));
            px_x.write(cur_.x0 + cur_.issued);
            px_y.write(cur_.y);
            ++cur_.issued;
            in_flight_ = true;
            if (cur_.issued == cur_.len) {
                cur_.active = false;
                free_in_ = (cur_.deg2 ? 4 : 6) - 2;  // clocks until the interval registers are free
            }
            start_ = cur_.active || pend_.active;
        } else if (free_in_ > 0) {
            --free_in_;
        }
        // Interval hand-over.
        if (ld_e_) {
            ld_e_ = false;  // the interval registers latch now
            pend_ = captured_;
            start_ = true;
        } else if (samples_ready.read() && !pend_.active && !cur_.active && free_in_ == 0) {
            ld_e_ = true;
            captured_.active = true;
            captured_.y = y.read().to_uint();
            captured_.x0 = x0.read().to_uint();
            captured_.len = len.read().to_uint();
            captured_.m = m.read().to_uint();
            captured_.deg2 = deg2_in.read() == 1;
            captured_.issued = 0;
        }
        ld_e.write(ld_e_);
        start.write(start_);
    }

    interval cur_, pend_, captured_;
    bool start_ = false, ld_e_ = false, in_flight_ = false;
    unsigned free_in_ = 0;
    std::size_t intervals_ = 0;
};

}  // namespace shading
