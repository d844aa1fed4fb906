// The fast pin-level abstraction of the interpolation paper's iterative Horner unit (Fig. 4; interp/abstraction.h):
// horner_unit's pins, handshake and clocks per result, one process, no internal blocks or delays.
//   - Rising edges: horner_ctrl's micro-sequencer, the same plain state (horner_steps.h: accept on
//     start when idle or done, 6 steps cubic, 4 with deg2 read entering step 4, done high in the last step, busy while
//     stepping; t > 1 reported as horner_ctrl does).
//   - Falling edges: RG latches the step's value. At step 1 the request's inputs (stable at every
//     falling edge from acceptance to done, the handshake's rule) give every step's RG at once
//     through golden_horner_into (src/floor/arith/interp_arith.h, the shared Q16.16 / Q1.8 formats);
//     each falling edge then puts its step's RG on i_t and rg_value, with no clock-to-output delay.
//   - Speed: the process wakes only at edges that switch a pin or sample start; done and
//     busy are written only when they change. Idle with start low, it sleeps until start rises.
// rg_value is kept as a signal (the block model's RG net) so the same monitor checks every step.
#pragma once

#include <systemc>

#include "arith/interp_arith.h"
#include "core/report_ids.h"
#include "formats/interp_formats.h"
#include "interp/horner_pins.h"
#include "interp/horner_steps.h"

namespace shading {

// horner_unit's pins and RG net (horner_pins.h).
class horner_unit_fast : public sc_core::sc_module, public horner_unit_pins {
public:
    SC_HAS_PROCESS(horner_unit_fast);
    explicit horner_unit_fast(const sc_core::sc_module_name& name) : sc_module(name) {
        // Statically on the falling edges (RG latches at each one while stepping, the usual case);
        // rising edges and start are waited for dynamically, only when they matter.
        SC_METHOD(on_edge);
        sensitive << clk.neg();
    }

private:
    // Wakes only at the edges where something happens at the pins or must be sampled: the
    // acceptance edge (start sampled; busy / done switch), every falling edge of a step (RG), the
    // rising edge entering the last step (done rises) and, only when t > 1, the one entering step 2
    // (the controller's report). The other rising edges of a step switch nothing: passing them
    // costs no wakeup (the state advances at the falling edge before them).
    void on_edge() {
        switch (wake_) {
            case wake::init:  // initialisation: the first rising edge samples start
                wake_ = wake::rise;
                next_trigger(clk.posedge_event());
                return;
            case wake::start_rose:
                if (clk.posedge()) {  // start rose with the clock in the same delta: this edge samples it
                    rising();
                    return;
                }
                wake_ = wake::rise;  // start rose after a rising edge: the next one samples it
                next_trigger(clk.posedge_event());
                return;
            case wake::rise: rising(); return;
            case wake::fall: falling(); return;
        }
    }

    // horner_ctrl's rising edge (horner_steps.h, the same sequencer).
    void rising() {
        step_edge(start.read());
        put(done, done_, fsm_.done());
        put(busy, busy_, fsm_.busy());
        if (fsm_.busy()) {
            wake_ = wake::fall;  // the static sensitivity: the next falling edge
        } else {  // idle (start was low): nothing happens until start rises
            wake_ = wake::start_rose;
            next_trigger(start.posedge_event());
        }
    }

    // RG latches the running step's value. At step 1 the request's inputs (stable at every falling edge
    // from acceptance to done) give every step's RG and the step count (deg2 read here as at step 4:
    // the handshake holds it).
    void falling() {
        const unsigned state = fsm_.step();
        if (state == 1) {
            const interp::cubic_coefs k{code(a), code(b), code(c), code(d)};
            t_code_ = t.read().to_uint64();
            last_ = static_cast<unsigned>(interp::golden_horner_into(k, t_code_, deg2.read(), steps_));
        }
        const coef_t rg(steps_[state - 1]);
        rg_value.write(rg);
        i_t.write(rg);
        // The next rising edge matters when it ends the request (acceptance), enters the last step
        // (done rises) or enters step 2 with t > 1 (report); otherwise pass it and latch again.
        const unsigned next = state + 1;
        if (state == last_ || next == last_ || (next == 2 && t_code_ > interp::t_one)) {
            wake_ = wake::rise;
            next_trigger(clk.posedge_event());
        } else {
            // That edge is passed: mid-request start is not read. Next: the static sensitivity (fall).
            step_edge(false);
        }
    }

    // One rising edge of the sequencer; t is checked entering step 2 as horner_ctrl does.
    void step_edge(bool start_now) {
        fsm_.rising(
            start_now, [this] { return deg2.read(); },
            [this] { interp::check_horner_t(name(), t.read().to_uint64()); });
    }

    static void put(sc_core::sc_out<bool>& port, bool& now, bool v) {
        if (v == now) return;
        now = v;
        port.write(v);
    }

    static int64_t code(const sc_core::sc_in<coef_t>& p) {
        return code_value(p.read().to_uint64(), interp::coef_fmt);
    }

    enum class wake { init, rise, fall, start_rose };
    wake wake_ = wake::init;  // what the edge that wakes the process next is
    interp::horner_steps fsm_;  // horner_ctrl's sequencer (horner_steps.h)
    unsigned last_ = 6;          // the request's last step, from the golden steps (the look-ahead)
    bool done_ = false, busy_ = false;  // what done and busy were last written
    uint64_t t_code_ = 0;
    uint64_t steps_[6] = {};
};

}  // namespace shading
