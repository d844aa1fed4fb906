// The fast pin-level abstraction of the raster-line interpolator interp_line_unit<M, SET, DIV, G>
// (interp/abstraction.h): its pins and the timing at them (interp_line_unit.h's handshake: ready =
// NOT valid OR last, accepted at a rising edge with start = 1 and ready = 1, pixel k on i_px k + 1
// clocks after acceptance, one pixel per clock with no bubble), one process, no internal blocks or
// delays:
//   - rising edges: fd_ctrl.h's controller as plain state (fd_count.h: LOAD / STEP / HOLD, valid,
//     last, ready; a len of 0 or above 2^M reported as fd_ctrl does and evaluated as a full interval);
//   - falling edges: first the evaluator's registers (LOAD: every pixel of the interval through
//     golden_fd from the A..D the coefficient unit holds; STEP: the next pixel on i_px), then the
//     coefficient unit's sample registers latch I1..I4 and A..D follow through golden_cubic_coefs
//     (sample set, /3 mode and grouping G; src/floor/arith/interp_arith.h).
#pragma once

#include <array>
#include <systemc>
#include <vector>

#include "arith/interp_arith.h"
#include "formats/interp_formats.h"
#include "interp/fd_count.h"
#include "interp/fd_pins.h"

namespace shading {

// interp_line_unit's pins (fd_pins.h).
template <unsigned M, interp::sample_set SET, interp::div3_mode DIV,
          interp::div3_grouping G = interp::div3_grouping::whole_sum>
class interp_line_unit_fast : public sc_core::sc_module, public interp_line_pins<M> {
    static_assert(M >= interp::m_min && M <= interp::m_max, "interval of 2^M pixels, M in 2..6");
    using coef_t = sc_dt::sc_uint<interp::coef_fmt.width>;

public:
    using len_t = typename interp_line_pins<M>::len_t;
    static constexpr unsigned n_pixels = 1u << M;

    SC_HAS_PROCESS(interp_line_unit_fast);
    explicit interp_line_unit_fast(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_edge);
        sensitive << this->clk;
        dont_initialize();
        // ready starts 0 and rises at the first rising edge, as the block unit's gate settles only
        // after its first evaluation (at the first edge it reads 0 there too).
    }

private:
    using select = interp::fd_count::select;

    void on_edge() {
        if (this->clk.read()) rising();
        else falling();
    }

    void rising() {
        sel_ = count_.rising(this->start.read(), [this] {
            return interp::checked_len(name(), static_cast<unsigned>(this->len.read().to_uint()), n_pixels);
        });
        this->valid.write(count_.valid());
        this->last.write(count_.last());
        this->ready.write(count_.ready());
    }

    void falling() {
        // The evaluator's registers, from the coefficients of the samples latched a clock ago.
        if (sel_ == select::load) {
            px_ = interp::golden_fd(k_, M, count_.length());
            at_ = 0;
            this->i_px.write(coef_t(px_[0]));
        } else if (sel_ == select::step) {
            this->i_px.write(coef_t(px_[++at_]));
        }
        // The coefficient unit's sample registers (every falling edge).
        const std::array<uint64_t, 4> s{this->i1.read().to_uint64(), this->i2.read().to_uint64(),
                                         this->i3.read().to_uint64(), this->i4.read().to_uint64()};
        if (!latched_ || s != held_) {
            held_ = s;
            latched_ = true;
            k_ = interp::golden_cubic_coefs(s, SET, DIV, G);
        }
    }

    interp::fd_count count_;
    select sel_ = select::hold;
    unsigned at_ = 0;
    std::array<uint64_t, 4> held_{};
    bool latched_ = false;
    interp::cubic_coefs k_{};
    std::vector<uint64_t> px_;
};

}  // namespace shading
