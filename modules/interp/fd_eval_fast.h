// The fast pin-level abstraction of the forward-difference evaluator fd_eval<M> (interp/abstraction.h):
// the same pins, handshake and one pixel per clock, one process, no internal blocks or delays.
//   - Rising edges: fd_ctrl.h's controller as plain state (accept on start when idle or on the last
//     pixel, LOAD, then STEP for len - 1 clocks, then HOLD; valid / last; a len of 0 or above 2^M
//     reported as fd_ctrl does and evaluated as a full interval).
//   - Falling edges: at LOAD the inputs A..D (stable from the accepting edge to this edge, the
//     handshake's rule) give every pixel through golden_fd (src/golden/interp_golden.h: the Q22.34
//     set-up and recurrence, the floor to Q16.16); each STEP puts the next one on i_px. HOLD keeps it.
//   - Falling edges in HOLD are skipped, and while idle with start low the process sleeps until
//     start rises.
#pragma once

#include <sstream>
#include <systemc>
#include <vector>

#include "core/report_ids.h"
#include "formats/interp_formats.h"
#include "golden/interp_golden.h"

namespace shading {

template <unsigned M>
class fd_eval_fast : public sc_core::sc_module {
    static_assert(M >= interp::m_min && M <= interp::m_max, "interval of 2^M pixels, M in 2..6");
    static constexpr unsigned n_pixels = 1u << M;
    using coef_t = sc_dt::sc_uint<interp::coef_fmt.width>;

public:
    using len_t = sc_dt::sc_uint<interp::len_width(M)>;  // fd_ctrl<M>::len_t

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> start{"start"};
    sc_core::sc_in<len_t> len{"len"};
    sc_core::sc_in<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"};
    sc_core::sc_out<coef_t> i_px{"i_px"};
    sc_core::sc_out<bool> valid{"valid"}, last{"last"};

    SC_HAS_PROCESS(fd_eval_fast);
    explicit fd_eval_fast(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_edge);
        sensitive << clk;
        dont_initialize();
    }

private:
    enum select { hold, load, step };

    void on_edge() {
        if (woken_by_start_) {
            woken_by_start_ = false;
            if (clk.posedge()) {  // start rose with the clock in the same delta: this edge samples it
                rising();
                return;
            }
            next_trigger(clk.posedge_event());
            return;
        }
        if (clk.read()) rising();
        else falling();
    }

    void rising() {
        sel_ = hold;
        if (start.read() && remaining_ <= 1) {
            length_ = static_cast<unsigned>(len.read().to_uint());
            if (length_ == 0 || length_ > n_pixels) {
                std::ostringstream os;
                os << name() << ": len = " << length_ << " at " << sc_core::sc_time_stamp() << " is outside 1.."
                   << n_pixels << "; a full interval of " << n_pixels << " pixels is evaluated";
                SC_REPORT_WARNING(msg::input, os.str().c_str());
                length_ = n_pixels;
            }
            remaining_ = length_;
            sel_ = load;
        } else if (remaining_ > 1) {
            --remaining_;
            sel_ = step;
        } else {
            remaining_ = 0;
        }
        valid.write(remaining_ != 0);
        last.write(remaining_ == 1);
        if (sel_ == hold) {
            if (start.read()) next_trigger(clk.posedge_event());  // nothing latches at the falling edge
            else {
                woken_by_start_ = true;
                next_trigger(start.posedge_event());
            }
        }
    }

    void falling() {
        if (sel_ == load) {
            const interp::cubic_coefs k{code(a), code(b), code(c), code(d)};
            px_ = interp::golden_fd(k, M, length_);
            k_ = 0;
        } else if (sel_ == step) {
            ++k_;
        } else {
            return;
        }
        i_px.write(coef_t(px_[k_]));
    }

    static int64_t code(const sc_core::sc_in<coef_t>& p) {
        return code_value(p.read().to_uint64(), interp::coef_fmt);
    }

    select sel_ = hold;
    unsigned remaining_ = 0, length_ = 0, k_ = 0;
    bool woken_by_start_ = false;
    std::vector<uint64_t> px_;
};

}  // namespace shading
