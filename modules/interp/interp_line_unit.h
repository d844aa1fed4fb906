// Raster-line interpolator of the interpolation paper: per interval of N = 2^M pixels the exact
// intensities I1..I4 go in, the cubic coefficient unit forms A..D with shifts and adds, and the
// forward-difference evaluator emits one pixel per clock. A device top: it only instantiates and
// wires the coefficient unit (coef_unit_cubic_t<SET, DIV, G>: /3 on the whole weighted sum or on
// the interpolation paper's partial sum) -> fd_eval<M> and the ready gate; no arithmetic here.
//
// Handshake and timing (decisions; the interpolation paper leaves them open). Clock period T; the source
// changes i1..i4, len and start only just after rising edges.
// - start is a level, "interval pending": I1..I4 and len (1..N pixels; the last interval of a line
//   may be shorter) are on the inputs. It is accepted at a rising edge where start = 1 and
//   ready = 1 (ready = NOT valid OR last: the evaluator is idle or on its last pixel); the source
//   may present the next interval right after that edge.
// - Samples: coef.rg_i1..4 latch the inputs at every falling edge (no enable: they are the
//   pipeline register between the source and the evaluator). The samples on the inputs at the
//   accepting edge E have been there since a rising edge before it, so they were latched at
//   E - T/2; A..D settle within that low phase and stay until rg_i change after E + T/2, the falling
//   edge where the evaluator's registers load their set-up values (rg_i's clock-to-output is the
//   hold margin: the set-up inputs move only after that edge).
// - Latency: samples presented just after edge E0 to an idle unit are accepted at E0 + T; pixel 0 is
//   on i_px with valid = 1 at E0 + 2T, pixel k at E0 + (k + 2) T (k + 1 clocks after acceptance).
// - Throughput: the next interval's samples are latched at E + T/2 while the current interval's
//   pixels go out, and it is accepted at the edge of the current last pixel: one pixel per clock,
//   no bubble between intervals. A line of W pixels: W + 1 clocks from its first samples to its
//   last pixel.
// Formats (src/interp_formats.h): I1..I4 Q8.8 unsigned; A..D Q16.16 signed; pixels Q16.16 signed.
#pragma once

#include <algorithm>
#include <systemc>

#include "blocks/interval_ready.h"
#include "core/timing_graph.h"
#include "formats/interp_formats.h"
#include "interp/coef_unit_cubic_partial_sum.h"
#include "interp/fd_eval.h"
#include "interp/fd_pins.h"
#include "interp/interp_delays.h"

namespace shading {

// Pins: fd_pins.h (interp_line_pins: clk, start, len, I1..I4 in; i_px, valid, last, ready out).
template <unsigned M, interp::sample_set SET, interp::div3_mode DIV,
          interp::div3_grouping G = interp::div3_grouping::whole_sum>
class interp_line_unit : public sc_core::sc_module, public interp_line_pins<M> {
    using coef_t = sc_dt::sc_uint<interp::coef_fmt.width>;

public:
    using len_t = typename interp_line_pins<M>::len_t;
    static constexpr unsigned n_pixels = 1u << M;

    // Nets between the units: the coefficients, Q16.16 signed.
    sc_core::sc_signal<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"};

    coef_unit_cubic_t<SET, DIV, G> coef;  // I1..I4 (Q8.8) -> A..D (Q16.16), latency 1 clock
    fd_eval<M> fd;                        // A..D (Q16.16) -> one Q16.16 pixel per clock
    interval_ready rdy;                   // NOT valid OR last

    explicit interp_line_unit(const sc_core::sc_module_name& name, const interp_delays& t = {})
        : sc_module(name), coef("coef", t), fd("fd", t), rdy("rdy", t.gate) {
        coef.clk(this->clk);
        coef.i1(this->i1); coef.i2(this->i2); coef.i3(this->i3); coef.i4(this->i4);
        coef.a(a); coef.b(b); coef.c(c); coef.d(d);
        fd.clk(this->clk); fd.start(this->start); fd.len(this->len);
        fd.a(a); fd.b(b); fd.c(c); fd.d(d);
        fd.i_px(this->i_px); fd.valid(this->valid); fd.last(this->last);
        rdy.valid(this->valid); rdy.last(this->last); rdy.ready(this->ready);
    }

    // The path that crosses the units: launched by the falling edge that latches the samples
    // (rg_i clock-to-output -> networks -> /3 -> A..D) and captured by the next falling edge in the
    // evaluator's registers (-> set-up network -> MX). It spans the low phase and then the high
    // phase, so no phase holds it alone: coef's chk_clock holds its first part in the low phase
    // (A..D before the rising edge) and fd's chk_clock the rest in the high phase (set-up from A..D
    // settling as late as the accepting edge). Those two checks cover it (sample_to_load() <=
    // min_low() + min_high(), tested), so the top needs no checker of its own. Derived from the
    // elaborated blocks at end_of_elaboration.
    void end_of_elaboration() override {
        const timing_graph g(*this);
        sample_to_load_ = g.longest_from_registers({&coef.rg_i1, &coef.rg_i2, &coef.rg_i3, &coef.rg_i4},
                                                   {g.d_of(fd.rg_p), g.d_of(fd.rg_d1), g.d_of(fd.rg_d2),
                                                    g.d_of(fd.rg_d3)});
    }
    const timing_path& sample_to_load() const { return sample_to_load_; }
    // Shortest clock phases the joined unit works with: each unit's own requirement (their
    // chk_clock monitors check them; see sample_to_load() for the path between them).
    sc_core::sc_time min_high() const { return std::max(coef.min_high(), fd.min_high()); }
    sc_core::sc_time min_low() const { return std::max(coef.min_low(), fd.min_low()); }
    unsigned phase_violations() const { return coef.chk_clock.violations() + fd.chk_clock.violations(); }

private:
    timing_path sample_to_load_;
};

}  // namespace shading
