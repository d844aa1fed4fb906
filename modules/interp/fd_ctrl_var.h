// Controller of the forward-difference evaluator with a per-interval length (fd_eval_var.h): fd_ctrl
// (fd_ctrl.h) plus the interval's m. Same handshake and timing: `start` is a level sampled at rising
// edges; an interval is accepted where start = 1 and the evaluator is idle (valid = 0) or on its last
// pixel (last = 1). At acceptance it reads `len` and `m` (both need only be stable at that edge),
// selects LOAD and drives setup_sel = m - MMIN, the set-up multiplexers' select, held until the next
// acceptance: the registers take that m's set-up at the falling edge after. Then STEP for len - 1
// clocks, then HOLD; pixel k of the interval is on the output at acceptance + (k + 1) clocks.
// m = 0 is the pipeline's exact pixel (pipeline.h: len 1, A = B = C = 0): P(0) = D whatever the
// set-up, so it takes MMIN's. Bad input (shading/input warning, a defined result): m neither 0 nor
// MMIN..MMAX -> m = MMAX; then len outside 1..2^m -> a full interval of 2^m pixels (as fd_ctrl).
#pragma once

#include <sstream>
#include <string>
#include <systemc>

#include "core/report_ids.h"
#include "core/timed_block.h"
#include "formats/interp_formats.h"
#include "interp/fd_count.h"
#include "interp/fd_ctrl.h"

namespace shading {

// timed_block as a clocked block: its outputs switch at the rising edge (no delay modelled), so the
// timing graph starts paths there (the evaluator's high phase) and never runs through it.
template <unsigned MMIN, unsigned MMAX>
class fd_ctrl_var : public sc_core::sc_module, public timed_block {
    static_assert(MMIN < MMAX, "two or more interval lengths (one length: fd_ctrl<M>)");

public:
    static constexpr unsigned lengths = MMAX - MMIN + 1;  // set-up networks per difference
    static constexpr unsigned sel_hold = fd_ctrl<MMAX>::sel_hold, sel_load = fd_ctrl<MMAX>::sel_load,
                              sel_step = fd_ctrl<MMAX>::sel_step;
    using len_t = sc_dt::sc_uint<interp::len_width(MMAX)>;
    using m_t = sc_dt::sc_uint<interp::code_width(MMAX + 1)>;  // codes 0..MMAX
    using select = typename fd_ctrl<MMAX>::select;
    using setup_select = sc_dt::sc_uint<interp::code_width(lengths)>;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> start{"start"};
    sc_core::sc_in<len_t> len{"len"};
    sc_core::sc_in<m_t> m{"m"};
    sc_core::sc_out<select> fd_sel{"fd_sel"};
    sc_core::sc_out<setup_select> setup_sel{"setup_sel"};  // m - MMIN of the interval last accepted
    sc_core::sc_out<len_t> pixel{"pixel"};                 // index k of the pixel on its way out
    sc_core::sc_out<bool> valid{"valid"}, last{"last"};

    SC_HAS_PROCESS(fd_ctrl_var);
    explicit fd_ctrl_var(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_clock);
        sensitive << clk.pos();
        dont_initialize();
    }

    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }
    const sc_core::sc_port_base* clock_port() const override { return &clk; }
    bool switches_on_rising_edge() const override { return true; }

private:
    // fd_ctrl's FSM (fd_count.h); at acceptance m and len are read and checked.
    void on_clock() {
        const unsigned sel = count_.rising(start.read(), [this] { return accept(); });
        fd_sel.write(sel);
        setup_sel.write(setup_);
        pixel.write(count_.pixel());
        valid.write(count_.valid());
        last.write(count_.last());
    }

    // The interval's m (setup_) and the length to evaluate.
    unsigned accept() {
        unsigned mm = m.read().to_uint();
        if (mm != 0 && (mm < MMIN || mm > MMAX)) {
            std::ostringstream os;
            os << name() << ": m = " << mm << " at " << sc_core::sc_time_stamp() << " is neither 0 (exact pixel) nor "
               << MMIN << ".." << MMAX << "; evaluated as m = " << MMAX;
            SC_REPORT_WARNING(msg::input, os.str().c_str());
            mm = MMAX;
        }
        const unsigned length = interp::checked_len(name(), static_cast<unsigned>(len.read().to_uint()), 1u << mm,
                                                    " for m = " + std::to_string(mm));
        setup_ = mm == 0 ? 0 : mm - MMIN;
        return length;
    }

    interp::fd_count count_;
    unsigned setup_ = 0;
};

}  // namespace shading
