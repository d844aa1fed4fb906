// Pixel controller for the forward-difference evaluators (ours, like the evaluator): a clocked FSM
// on the rising edge of clk. Interval hand-over as in horner_pixel_ctrl.h (ld_e for one clock, the
// descriptor captured where it rises); where ld_e falls it sets deg_sel, len and start for the
// interval now in the interval registers (and m, for fd_eval_var). fd_ctrl takes it at a rising edge where start = 1 and
// the evaluator is idle or on its last pixel, and loads A..D at the falling edge after: from then
// on the interval registers are free, so the next hand-over starts at that same taking edge and
// an interval's set-up overlaps the previous one's pixels. Pixel k of an interval taken at edge E
// is on the output at E + (k + 1) clocks (fd_ctrl); px_x / px_y are set one clock before.
#pragma once

#include <systemc>

#include "core/timed_block.h"
#include "formats/interp_formats.h"

namespace shading {

class fd_pixel_ctrl : public sc_core::sc_module, public timed_block {
public:
    using coord_t = sc_dt::sc_uint<16>;
    using sel_t = sc_dt::sc_uint<1>;
    using len_t = sc_dt::sc_uint<interp::len_width(interp::m_max)>;
    using m_t = sc_dt::sc_uint<interp::code_width(interp::m_max + 1)>;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> samples_ready{"samples_ready"};
    sc_core::sc_in<coord_t> y{"y"}, x0{"x0"};
    sc_core::sc_in<sc_dt::sc_uint<16>> len_in{"len_in"};
    sc_core::sc_in<sc_dt::sc_uint<4>> m_in{"m_in"};
    sc_core::sc_in<sel_t> deg2_in{"deg2_in"};
    sc_core::sc_in<bool> valid{"valid"}, last{"last"};  // channel R's evaluator (the three run in step)
    sc_core::sc_out<bool> ld_e{"ld_e"}, start{"start"};
    sc_core::sc_out<sel_t> deg_sel{"deg_sel"};
    sc_core::sc_out<len_t> len{"len"};
    sc_core::sc_out<m_t> m{"m"};  // for fd_eval_var: the interval's length 2^m
    sc_core::sc_out<coord_t> px_x{"px_x"}, px_y{"px_y"};

    SC_HAS_PROCESS(fd_pixel_ctrl);
    explicit fd_pixel_ctrl(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_clock);
        sensitive << clk.pos();
        dont_initialize();
    }

    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }
    const sc_core::sc_port_base* clock_port() const override { return &clk; }
    bool switches_on_rising_edge() const override { return true; }

    bool idle() const { return !pend_.active && !ld_e_ && !start_ && left_ == 0 && !valid.read(); }
    std::size_t intervals() const { return intervals_; }

private:
    struct interval {
        bool active = false, deg2 = false;
        unsigned y = 0, x0 = 0, len = 0, m = 0;
    };

    void on_clock() {
        const bool vl = valid.read(), ls = last.read();
        if (start_ && (!vl || ls)) {  // fd_ctrl takes the pending interval here
            cur_ = pend_;
            pend_.active = false;
            start_ = false;
            px_x.write(cur_.x0);
            px_y.write(cur_.y);
            next_ = 1;
            left_ = cur_.len - 1;
            ++intervals_;
        } else if (left_ > 0) {
            px_x.write(cur_.x0 + next_);
            ++next_;
            --left_;
        }
        if (ld_e_) {
            ld_e_ = false;  // the interval registers latch now
            pend_ = captured_;
            deg_sel.write(pend_.deg2 ? 1 : 0);
            len.write(len_t(pend_.len));
            m.write(m_t(pend_.m));
            start_ = true;
        } else if (samples_ready.read() && !pend_.active) {
            ld_e_ = true;
            captured_.active = true;
            captured_.y = y.read().to_uint();
            captured_.x0 = x0.read().to_uint();
            captured_.len = len_in.read().to_uint();
            captured_.m = m_in.read().to_uint();
            captured_.deg2 = deg2_in.read() == 1;
        }
        ld_e.write(ld_e_);
        start.write(start_);
    }

    interval cur_, pend_, captured_;
    bool start_ = false, ld_e_ = false;
    unsigned next_ = 0, left_ = 0;
    std::size_t intervals_ = 0;
};

}  // namespace shading
