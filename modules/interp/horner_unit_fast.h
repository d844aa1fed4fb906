// The fast pin-level abstraction of seed 004's iterative Horner unit (Fig. 4; interp/abstraction.h):
// horner_unit's pins, handshake and clocks per result, one process, no internal blocks or delays.
//   - Rising edges: horner_ctrl.h's micro-sequencer as plain state (accept on start when idle or
//     done, 6 steps cubic, 4 with deg2 read entering step 4, done high in the last step, busy while
//     stepping; t > 1 reported as horner_ctrl does).
//   - Falling edges: RG latches the step's value. At step 1 the request's inputs (stable at every
//     falling edge from acceptance to done, the handshake's rule) give every step's RG at once
//     through golden_horner_steps (src/golden/interp_golden.h, the shared Q16.16 / Q1.8 formats);
//     each falling edge then puts its step's RG on i_t and rg_value, with no clock-to-output delay.
//   - Idle (no step running) with start low, the process sleeps until start rises.
// rg_value is kept as a signal (the block model's RG net) so the same monitor checks every step.
#pragma once

#include <sstream>
#include <systemc>
#include <vector>

#include "core/report_ids.h"
#include "formats/interp_formats.h"
#include "golden/interp_golden.h"

namespace shading {

class horner_unit_fast : public sc_core::sc_module {
    static constexpr unsigned WC = interp::coef_fmt.width;  // 32
    static constexpr unsigned WT = interp::t_fmt.width;     // 9
    using coef_t = sc_dt::sc_uint<WC>;
    using t_t = sc_dt::sc_uint<WT>;

public:
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> start{"start"};
    sc_core::sc_in<bool> deg2{"deg2"};
    sc_core::sc_in<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"};
    sc_core::sc_in<t_t> t{"t"};
    sc_core::sc_out<coef_t> i_t{"i_t"};
    sc_core::sc_out<bool> done{"done"}, busy{"busy"};

    sc_core::sc_signal<coef_t> rg_value{"rg_value"};  // RG: the partial Horner sum (as in horner_unit)

    SC_HAS_PROCESS(horner_unit_fast);
    explicit horner_unit_fast(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_edge);
        sensitive << clk;
        dont_initialize();
    }

private:
    void on_edge() {
        if (woken_by_start_) {
            woken_by_start_ = false;
            if (clk.posedge()) {  // start rose with the clock in the same delta: this edge samples it
                rising();
                return;
            }
            next_trigger(clk.posedge_event());  // start rose after a rising edge: the next one samples it
            return;
        }
        if (clk.read()) rising();
        else falling();
    }

    void rising() {
        const bool finishing = state_ != 0 && state_ == last_;
        unsigned next = 0;
        if (start.read() && (state_ == 0 || finishing)) next = 1;
        else if (state_ != 0 && !finishing) next = state_ + 1;
        if (next == 1) last_ = 6;
        if (next == 4 && deg2.read()) last_ = 4;
        if (next == 2) check_t();
        state_ = next;
        done.write(state_ != 0 && state_ == last_);
        busy.write(state_ != 0);
        if (state_ == 0 && !start.read()) {  // idle: nothing happens until start rises
            woken_by_start_ = true;
            next_trigger(start.posedge_event());
        }
    }

    void falling() {
        if (state_ == 0) return;  // RG recirculates
        if (state_ == 1) {
            const interp::cubic_coefs k{code(a), code(b), code(c), code(d)};
            steps_ = interp::golden_horner_steps(k, t.read().to_uint64(), deg2.read());
        }
        const coef_t rg(steps_[state_ - 1]);
        rg_value.write(rg);
        i_t.write(rg);
    }

    static int64_t code(const sc_core::sc_in<coef_t>& p) {
        return code_value(p.read().to_uint64(), interp::coef_fmt);
    }

    // horner_ctrl's assertion (not hardware): t above 1.0 is extrapolation.
    void check_t() {
        const uint64_t v = t.read().to_uint64();
        if (v <= interp::t_one) return;
        std::ostringstream os;
        os << name() << ": t = " << v << "/256 > 1 at " << sc_core::sc_time_stamp()
           << "; evaluated as given (extrapolation; RG wraps if the value leaves Q16.16)";
        SC_REPORT_WARNING(msg::input, os.str().c_str());
    }

    unsigned state_ = 0, last_ = 6;
    bool woken_by_start_ = false;
    std::vector<uint64_t> steps_;
};

}  // namespace shading
