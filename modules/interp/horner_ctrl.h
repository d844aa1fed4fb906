// Controller of the iterative Horner unit (the interpolation paper, Fig. 4): runs the paper's micro-sequence one
// step per clock, driving MX1, MX2 and BK. A clocked FSM on the rising edge of clk; RG latches on
// the falling edge, so every step's selects settle for half a period before RG takes the sum.
//
// Handshake (decision, see the README): `start` is a level "request pending", sampled at rising
// edges. A request is accepted at an edge where start = 1 and the unit is idle (busy = 0) or
// finishing (done = 1), so back-to-back requests cost no extra cycle. The request's inputs
// (A..D, t, deg2) must be stable at every falling edge from the acceptance edge to the done edge;
// a source may change them right after its acceptance edge. `done` is high during the last step;
// I(t) is on the output at the rising edge that ends that step, i.e. 6 clocks (cubic) or 4 clocks
// (deg2 = 1) after the acceptance edge, and stays there until the falling edge after the next
// acceptance (idle: RG recirculates through MX2 = 0, BK pass).
//
// Micro-steps, with this model's MX2 codes 0 = 0 (hold), 1 = MUL, 2 = B, 3 = C, 4 = D
// and MX1 codes 0 = A, 1 = RG:
//   1 RG <- B            MX2 = B,   BK zero       (the paper loads RG with B; done here via MX2)
//   2 RG <- A t + B      MX1 = A,   MX2 = MUL, BK pass
//   3 RG <- RG t         MX1 = RG,  MX2 = MUL, BK zero
//   4 RG <- RG + C       MX2 = C,   BK pass         (last step when deg2: I = (a t + b) t + c)
//   5 RG <- RG t         MX1 = RG,  MX2 = MUL, BK zero
//   6 RG <- RG + D       MX2 = D,   BK pass
#pragma once

#include <systemc>

#include "core/report_ids.h"
#include "core/timed_block.h"
#include "formats/interp_formats.h"
#include "interp/horner_steps.h"

namespace shading {

// timed_block as a clocked block: its outputs switch at the rising edge (no delay modelled), so the
// timing graph starts paths there (the units' high phase) and never runs through it.
class horner_ctrl : public sc_core::sc_module, public timed_block {
public:
    static constexpr unsigned mx2_zero = 0, mx2_mul = 1, mx2_b = 2, mx2_c = 3, mx2_d = 4;
    static constexpr unsigned mx1_a = 0, mx1_rg = 1;
    static_assert(mx2_d < interp::horner_mx2_inputs && mx1_rg < interp::horner_mx1_inputs, "select codes");
    using t_t = sc_dt::sc_uint<interp::t_fmt.width>;
    using mx1_select = sc_dt::sc_uint<interp::code_width(interp::horner_mx1_inputs)>;
    using mx2_select = sc_dt::sc_uint<interp::code_width(interp::horner_mx2_inputs)>;
    using step_code = sc_dt::sc_uint<interp::code_width(interp::horner_step_codes)>;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> start{"start"};
    sc_core::sc_in<bool> deg2{"deg2"};
    sc_core::sc_in<t_t> t{"t"};  // read only by the range assertion (not hardware)
    sc_core::sc_out<mx1_select> mx1_sel{"mx1_sel"};
    sc_core::sc_out<mx2_select> mx2_sel{"mx2_sel"};
    sc_core::sc_out<bool> bk_pass{"bk_pass"};
    sc_core::sc_out<step_code> step{"step"};  // 0 idle, 1..6: the micro-step running
    sc_core::sc_out<bool> done{"done"}, busy{"busy"};

    SC_HAS_PROCESS(horner_ctrl);
    explicit horner_ctrl(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_clock);
        sensitive << clk.pos();
        dont_initialize();
        bk_pass.initialize(true);  // idle: MX2 = 0 and BK pass make RG hold its value
    }

    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }
    const sc_core::sc_port_base* clock_port() const override { return &clk; }
    bool switches_on_rising_edge() const override { return true; }

private:
    void on_clock() {
        const unsigned s = fsm_.rising(
            start.read(), [this] { return deg2.read(); },
            [this] { interp::check_horner_t(name(), t.read().to_uint64()); });

        unsigned m1 = mx1_a, m2 = mx2_zero;
        bool pass = true;
        switch (s) {
            case 1: m2 = mx2_b; pass = false; break;
            case 2: m1 = mx1_a; m2 = mx2_mul; pass = true; break;
            case 3: m1 = mx1_rg; m2 = mx2_mul; pass = false; break;
            case 4: m2 = mx2_c; pass = true; break;
            case 5: m1 = mx1_rg; m2 = mx2_mul; pass = false; break;
            case 6: m2 = mx2_d; pass = true; break;
            default: break;  // idle: hold
        }
        mx1_sel.write(m1);
        mx2_sel.write(m2);
        bk_pass.write(pass);
        step.write(s);
        done.write(fsm_.done());
        busy.write(fsm_.busy());
    }

    interp::horner_steps fsm_;  // the sequence (horner_steps.h, shared with horner_unit_fast)
};

}  // namespace shading
