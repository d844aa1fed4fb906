// Forward-difference evaluator: the classic alternative to Horner for a cubic at equally spaced
// t = k/N (N = 2^M pixels): after a set-up of shifts and adds,
//   P <- P + D1,  D1 <- D1 + D2,  D2 <- D2 + D3        (three additions per pixel, no multiplier)
// with P(0) = D, D1 = A/N^3 + B/N^2 + C/N, D2 = 6A/N^3 + 2B/N^2, D3 = 6A/N^3.
// One pixel per clock. Set-up networks: shift_add_network (N = 2^M makes every /N^k a shift).
// Registers rg_p, rg_d1, rg_d2, rg_d3 (reg.h, clocked by clk, latch on the falling edge), each fed
// by a 3-input multiplexer: 0 hold (own output), 1 load (set-up), 2 step (the adder).
// Formats (src/interp_formats.h): A..D Q16.16 signed in; set-up, registers and adders Q22.34
// signed (fd_fmt): 34 = 16 + 3*6 fraction bits make the set-up exact for M <= 6, so P(k) is the
// polynomial of the coefficient codes, exactly; the output drops 18 low wires (floor) -> Q16.16.
// This class only instantiates and wires.
#pragma once

#include <systemc>
#include <vector>

#include "blocks/adder.h"
#include "blocks/constant.h"
#include "blocks/mux.h"
#include "blocks/reg.h"
#include "blocks/shift_add_network.h"
#include "blocks/shifter.h"
#include "core/timing_graph.h"
#include "formats/interp_formats.h"
#include "interp/fd_ctrl.h"
#include "interp/fd_pins.h"
#include "interp/fd_setup.h"
#include "interp/interp_delays.h"
#include "monitors/phase_checker.h"

namespace shading {

// The recurrence's wiring, the same in fd_eval and fd_eval_var (E: either; the same block and net
// names): the adders P + D1, D1 + D2, D2 + D3 (carry-in 0), each register's hold / load / step
// multiplexer (load: init_*, the set-up) on fd_sel, the registers on clk, RG_P onto i_px.
template <class E>
void wire_fd_recurrence(E& e) {
    using ctrl_t = decltype(e.ctrl);
    e.k_carry0.y(e.carry0);
    e.add_p.a(e.p_value); e.add_p.b(e.d1_value); e.add_p.cin(e.carry0); e.add_p.s(e.p_sum);
    e.add_d1.a(e.d1_value); e.add_d1.b(e.d2_value); e.add_d1.cin(e.carry0); e.add_d1.s(e.d1_sum);
    e.add_d2.a(e.d2_value); e.add_d2.b(e.d3_value); e.add_d2.cin(e.carry0); e.add_d2.s(e.d2_sum);

    const auto wire_mux = [&e](auto& mx, auto& hold, auto& load, auto& step, auto& out) {
        mx.in[ctrl_t::sel_hold](hold);
        mx.in[ctrl_t::sel_load](load);
        mx.in[ctrl_t::sel_step](step);
        mx.sel(e.fd_sel);
        mx.y(out);
    };
    wire_mux(e.mx_p, e.p_value, e.init_p, e.p_sum, e.p_next);
    wire_mux(e.mx_d1, e.d1_value, e.init_d1, e.d1_sum, e.d1_next);
    wire_mux(e.mx_d2, e.d2_value, e.init_d2, e.d2_sum, e.d2_next);
    wire_mux(e.mx_d3, e.d3_value, e.init_d3, e.d3_value, e.d3_keep);  // D3 is constant while stepping

    e.rg_p.ctl(e.clk); e.rg_p.d(e.p_next); e.rg_p.q(e.p_value);
    e.rg_d1.ctl(e.clk); e.rg_d1.d(e.d1_next); e.rg_d1.q(e.d1_value);
    e.rg_d2.ctl(e.clk); e.rg_d2.d(e.d2_next); e.rg_d2.q(e.d2_value);
    e.rg_d3.ctl(e.clk); e.rg_d3.d(e.d3_keep); e.rg_d3.q(e.d3_value);

    e.out_align.x(e.p_value); e.out_align.y(e.i_px);
}

// Pins: fd_pins.h (fd_eval_pins).
template <unsigned M>
class fd_eval : public sc_core::sc_module, public fd_eval_pins<M> {
    static_assert(M >= interp::m_min && M <= interp::m_max, "interval of 2^M pixels, M in 2..6");
    static constexpr unsigned WC = interp::coef_fmt.width;  // 32
    static constexpr unsigned WF = interp::fd_fmt.width;    // 56
    static constexpr int S = fd_setup::align;  // 18: Q.16 -> Q.34
    using fd_t = sc_dt::sc_uint<WF>;

public:
    using len_t = typename fd_eval_pins<M>::len_t;

    // Nets.
    sc_core::sc_signal<fd_t> init_p{"init_p"}, init_d1{"init_d1"}, init_d2{"init_d2"}, init_d3{"init_d3"};
    sc_core::sc_signal<fd_t> p_value{"p_value"}, d1_value{"d1_value"}, d2_value{"d2_value"}, d3_value{"d3_value"};
    sc_core::sc_signal<fd_t> p_next{"p_next"}, d1_next{"d1_next"}, d2_next{"d2_next"};
    sc_core::sc_signal<fd_t> p_sum{"p_sum"}, d1_sum{"d1_sum"}, d2_sum{"d2_sum"}, d3_keep{"d3_keep"};
    sc_core::sc_signal<typename fd_ctrl<M>::select> fd_sel{"fd_sel"};
    sc_core::sc_signal<len_t> pixel{"pixel"};
    sc_core::sc_signal<bool> carry0{"carry0"};

    // Set-up: shifts and adds of the Q16.16 coefficients onto Q22.34 (inputs: 0 = A, 1 = B, 2 = C).
    shifter<WC, WF, true> setup_p{"setup_p", S};  // D: Q16.16 -> Q22.34
    shift_add_network<WC, WF, true> setup_d1{"setup_d1", 3, fd_setup::d1_terms(M)};  // A/N^3 + B/N^2 + C/N
    shift_add_network<WC, WF, true> setup_d2{"setup_d2", 2, fd_setup::d2_terms(M)};  // (4A + 2A)/N^3 + 2B/N^2
    shift_add_network<WC, WF, true> setup_d3{"setup_d3", 1, fd_setup::d3_terms(M)};  // (4A + 2A)/N^3

    mux<WF, interp::fd_mx_inputs> mx_p, mx_d1, mx_d2, mx_d3;
    reg<WF> rg_p, rg_d1, rg_d2, rg_d3;
    adder<WF, WF, WF, true, true> add_p, add_d1, add_d2;  // Q22.34 + Q22.34 -> Q22.34
    shifter<WF, WC, true> out_align{"out_align", -S};  // Q22.34 -> Q16.16, 18 low wires dropped (floor)
    constant<bool> k_carry0{"k_carry0", false};
    fd_ctrl<M> ctrl{"ctrl"};
    // Assertion monitor (not hardware). High: at the accepting rising edge the controller selects
    // LOAD and A..D may settle as late as that edge (fd_ctrl: stable from it to the falling edge), so
    // A..D -> set-up network -> MX and fd_sel -> MX must reach the registers before the falling
    // edge. Low: RG_P's new value on i_px (out_align is wiring) before the rising edge where valid
    // says the pixel is there; the recurrence RG -> ADD -> MX -> RG, launched and captured by falling
    // edges, may use both phases. Derived from the elaborated blocks at end_of_elaboration.
    phase_checker chk_clock{"chk_clock"};

    explicit fd_eval(const sc_core::sc_module_name& name, const interp_delays& t = {})
        : sc_module(name), mx_p("mx_p", t.mux), mx_d1("mx_d1", t.mux), mx_d2("mx_d2", t.mux),
          mx_d3("mx_d3", t.mux), rg_p("rg_p", t.reg), rg_d1("rg_d1", t.reg), rg_d2("rg_d2", t.reg),
          rg_d3("rg_d3", t.reg), add_p("add_p", overflow_mode::wrap, 0, 0, t.adder),
          add_d1("add_d1", overflow_mode::wrap, 0, 0, t.adder), add_d2("add_d2", overflow_mode::wrap, 0, 0, t.adder) {
        setup_p.x(this->d); setup_p.y(init_p);
        setup_d1.in[0](this->a); setup_d1.in[1](this->b); setup_d1.in[2](this->c); setup_d1.y(init_d1);
        setup_d2.in[0](this->a); setup_d2.in[1](this->b); setup_d2.y(init_d2);
        setup_d3.in[0](this->a); setup_d3.y(init_d3);

        wire_fd_recurrence(*this);
        ctrl.clk(this->clk); ctrl.start(this->start); ctrl.len(this->len);
        ctrl.fd_sel(fd_sel); ctrl.pixel(pixel); ctrl.valid(this->valid); ctrl.last(this->last);
        chk_clock.clk(this->clk);
    }

    void end_of_elaboration() override { chk_clock.derive(timing_graph(*this)); }
    // Shortest clock phases this unit works with (checked by chk_clock; after elaboration).
    const sc_core::sc_time& min_high() const { return chk_clock.min_high(); }
    const sc_core::sc_time& min_low() const { return chk_clock.min_low(); }
};

}  // namespace shading
