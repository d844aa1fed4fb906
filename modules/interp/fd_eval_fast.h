// The fast pin-level abstraction of the forward-difference evaluator fd_eval<M> (interp/abstraction.h):
// the same pins, handshake and one pixel per clock, one process, no internal blocks or delays.
//   - Rising edges: fd_ctrl.h's controller as plain state (fd_count.h: accept on start when idle or
//     on the last pixel, LOAD, then STEP for len - 1 clocks, then HOLD; valid / last; a len of 0 or
//     above 2^M reported as fd_ctrl does and evaluated as a full interval).
//   - Falling edges: at LOAD the inputs A..D (stable from the accepting edge to this edge, the
//     handshake's rule) give every pixel through golden_fd (src/floor/arith/interp_arith.h: the Q22.34
//     set-up and recurrence, the floor to Q16.16); each STEP puts the next one on i_px. HOLD keeps it.
//   - Falling edges in HOLD are skipped, and while idle with start low the process sleeps until
//     start rises.
#pragma once

#include <systemc>
#include <vector>

#include "arith/interp_arith.h"
#include "formats/interp_formats.h"
#include "interp/fd_count.h"
#include "interp/fd_pins.h"

namespace shading {

// fd_eval<M>'s pins (fd_pins.h).
template <unsigned M>
class fd_eval_fast : public sc_core::sc_module, public fd_eval_pins<M> {
    static_assert(M >= interp::m_min && M <= interp::m_max, "interval of 2^M pixels, M in 2..6");
    static constexpr unsigned n_pixels = 1u << M;
    using coef_t = sc_dt::sc_uint<interp::coef_fmt.width>;

public:
    using len_t = typename fd_eval_pins<M>::len_t;

    SC_HAS_PROCESS(fd_eval_fast);
    explicit fd_eval_fast(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_edge);
        sensitive << this->clk;
        dont_initialize();
    }

private:
    using select = interp::fd_count::select;

    void on_edge() {
        if (woken_by_start_) {
            woken_by_start_ = false;
            if (this->clk.posedge()) {  // start rose with the clock in the same delta: this edge samples it
                rising();
                return;
            }
            next_trigger(this->clk.posedge_event());
            return;
        }
        if (this->clk.read()) rising();
        else falling();
    }

    void rising() {
        sel_ = count_.rising(this->start.read(), [this] {
            return interp::checked_len(name(), static_cast<unsigned>(this->len.read().to_uint()), n_pixels);
        });
        this->valid.write(count_.valid());
        this->last.write(count_.last());
        if (sel_ == select::hold) {
            if (this->start.read()) next_trigger(this->clk.posedge_event());  // nothing latches at the falling edge
            else {
                woken_by_start_ = true;
                next_trigger(this->start.posedge_event());
            }
        }
    }

    void falling() {
        if (sel_ == select::load) {
            const interp::cubic_coefs k{code(this->a), code(this->b), code(this->c), code(this->d)};
            px_ = interp::golden_fd(k, M, count_.length());
            k_ = 0;
        } else if (sel_ == select::step) {
            ++k_;
        } else {
            return;
        }
        this->i_px.write(coef_t(px_[k_]));
    }

    static int64_t code(const sc_core::sc_in<coef_t>& p) {
        return code_value(p.read().to_uint64(), interp::coef_fmt);
    }

    interp::fd_count count_;
    select sel_ = select::hold;
    unsigned k_ = 0;
    bool woken_by_start_ = false;
    std::vector<uint64_t> px_;
};

}  // namespace shading
