// Controller of the forward-difference evaluator (fd_eval.h): a clocked FSM on the rising edge.
// Handshake (decision, see the README): `start` is a level "interval pending", sampled at rising
// edges; an interval is accepted at an edge where start = 1 and the evaluator is idle (valid = 0)
// or on its last pixel (last = 1). At acceptance it reads `len` (pixels of this interval, 1..N;
// the last interval of a raster line may be shorter) and selects LOAD, so the registers take the
// set-up values at the next falling edge: A..D must be stable from the acceptance edge to that
// falling edge. Then STEP for len - 1 clocks, then HOLD. `valid` is high during each pixel's clock;
// the pixel is on the output at the rising edge that ends it: pixel k at acceptance + (k+1) clocks.
#pragma once

#include <systemc>

#include "core/timed_block.h"
#include "formats/interp_formats.h"
#include "interp/fd_count.h"

namespace shading {

template <unsigned M>
// timed_block as a clocked block: its outputs switch at the rising edge (no delay modelled), so the
// timing graph starts paths there (the evaluator's high phase) and never runs through it.
class fd_ctrl : public sc_core::sc_module, public timed_block {
public:
    static constexpr unsigned n_pixels = 1u << M;
    static constexpr unsigned sel_hold = interp::fd_count::hold, sel_load = interp::fd_count::load,
                              sel_step = interp::fd_count::step;
    static_assert(sel_step < interp::fd_mx_inputs, "select codes");
    using len_t = sc_dt::sc_uint<interp::len_width(M)>;
    using select = sc_dt::sc_uint<interp::code_width(interp::fd_mx_inputs)>;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> start{"start"};
    sc_core::sc_in<len_t> len{"len"};
    sc_core::sc_out<select> fd_sel{"fd_sel"};
    sc_core::sc_out<len_t> pixel{"pixel"};  // index k of the pixel on its way out
    sc_core::sc_out<bool> valid{"valid"}, last{"last"};

    SC_HAS_PROCESS(fd_ctrl);
    explicit fd_ctrl(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_clock);
        sensitive << clk.pos();
        dont_initialize();
    }

    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }
    const sc_core::sc_port_base* clock_port() const override { return &clk; }
    bool switches_on_rising_edge() const override { return true; }

private:
    // The FSM is fd_count.h's (the fast units step the same one); len read at acceptance only.
    void on_clock() {
        const unsigned sel = count_.rising(start.read(), [this] {
            return interp::checked_len(name(), static_cast<unsigned>(len.read().to_uint()), n_pixels);
        });
        fd_sel.write(sel);
        pixel.write(count_.pixel());
        valid.write(count_.valid());
        last.write(count_.last());
    }

    interp::fd_count count_;
};

}  // namespace shading
