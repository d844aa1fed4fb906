// Iterative Horner unit of the interpolation paper, Fig. 4: I(t) = ((A t + B) t + C) t + D with one
// register RG, multiplexers MX1 and MX2, one multiplier MUL, adder Sm and key block BK:
//   MUL = MX1 * t,  MX1 in {A, RG};  Sm = MX2 + BK(RG),  MX2 in {0, MUL, B, C, D};  RG <- Sm.
// The controller (horner_ctrl.h) runs one micro-step per clock: 6 clocks per cubic pixel,
// 4 per quadratic one, back to back. RG is reg.h driven by the clock (latches on the falling
// edge); while idle the controller selects MX2 = 0 with BK passing, so RG recirculates (a
// load-enable built from the existing MX2 and BK instead of a gated clock).
// Formats (src/interp_formats.h): A..D, RG, MX1, MX2, BK, Sm Q16.16 signed; t Q1.8 unsigned;
// MUL Q16.16 x Q1.8 -> Q17.24, floor to Q16.16. This class only instantiates and wires.
#pragma once

#include <systemc>

#include "blocks/adder.h"
#include "blocks/constant.h"
#include "blocks/key_block.h"
#include "blocks/mul.h"
#include "blocks/mux.h"
#include "blocks/reg.h"
#include "blocks/wire.h"
#include "core/timing_graph.h"
#include "formats/interp_formats.h"
#include "interp/horner_ctrl.h"
#include "interp/horner_pins.h"
#include "interp/interp_delays.h"
#include "monitors/phase_checker.h"

namespace shading {

namespace horner_detail {
// MUL of Fig. 4 (a type alias, so the instance can carry the figure's name `mul`).
using mul_block = mul<interp::coef_fmt.width, interp::t_fmt.width, interp::coef_fmt.width,
                      interp::horner_mul_drop, true, false>;
}  // namespace horner_detail

// Pins and the RG net rg_value: horner_pins.h.
class horner_unit : public sc_core::sc_module, public horner_unit_pins {
    static constexpr unsigned WC = interp::coef_fmt.width;  // 32

public:
    // Nets, by what they carry (RG's output, rg_value, is in horner_pins.h).
    sc_core::sc_signal<coef_t> mx1_operand{"mx1_operand"};  // A or RG
    sc_core::sc_signal<coef_t> mul_product{"mul_product"};  // MX1 * t
    sc_core::sc_signal<coef_t> mx2_operand{"mx2_operand"};  // 0, MUL, B, C or D
    sc_core::sc_signal<coef_t> bk_operand{"bk_operand"};    // RG or 0
    sc_core::sc_signal<coef_t> sm_sum{"sm_sum"};            // next RG
    sc_core::sc_signal<coef_t> zero_word{"zero_word"};
    sc_core::sc_signal<bool> carry0{"carry0"};
    sc_core::sc_signal<horner_ctrl::mx1_select> mx1_sel{"mx1_sel"};
    sc_core::sc_signal<horner_ctrl::mx2_select> mx2_sel{"mx2_sel"};
    sc_core::sc_signal<bool> bk_pass{"bk_pass"};
    sc_core::sc_signal<horner_ctrl::step_code> step{"step"};

    // Blocks of Fig. 4 (names from the figure) and the controller.
    reg<WC> rg;
    mux<WC, interp::horner_mx1_inputs> mx1;
    horner_detail::mul_block mul;  // Q16.16 x Q1.8 -> Q17.24, floor to Q16.16
    mux<WC, interp::horner_mx2_inputs> mx2;
    key_block<WC> bk;
    adder<WC, WC, WC, true, true> sm;  // Q16.16 + Q16.16 -> Q16.16, wraps
    constant<coef_t> k_zero{"k_zero", coef_t(0)};
    constant<bool> k_carry0{"k_carry0", false};
    wire<coef_t> out_wire{"out_wire"};  // RG's output is the unit's output
    horner_ctrl ctrl{"ctrl"};
    // Assertion monitor (not hardware). High phase: the selects (from ctrl, at the rising edge) and
    // the inputs A..D, t (driven after the accepting rising edge, as the handshake allows) must
    // reach RG before it latches. Low phase: RG's new value must be on i_t at the rising edge where
    // done is read. The loop RG -> MX1 -> MUL -> MX2 -> Sm -> RG spans both phases. Derived from
    // the elaborated blocks at end_of_elaboration.
    phase_checker chk_clock{"chk_clock"};

    explicit horner_unit(const sc_core::sc_module_name& name, const interp_delays& dl = {})
        : sc_module(name), rg("rg", dl.reg), mx1("mx1", dl.mux), mul("mul", dl.multiplier), mx2("mx2", dl.mux),
          bk("bk", dl.gate), sm("sm", overflow_mode::wrap, 0, 0, dl.adder) {
        rg.ctl(clk); rg.d(sm_sum); rg.q(rg_value);
        mx1.in[horner_ctrl::mx1_a](a); mx1.in[horner_ctrl::mx1_rg](rg_value);
        mx1.sel(mx1_sel); mx1.y(mx1_operand);
        mul.a(mx1_operand); mul.b(t); mul.p(mul_product);
        k_zero.y(zero_word);
        mx2.in[horner_ctrl::mx2_zero](zero_word); mx2.in[horner_ctrl::mx2_mul](mul_product);
        mx2.in[horner_ctrl::mx2_b](b); mx2.in[horner_ctrl::mx2_c](c); mx2.in[horner_ctrl::mx2_d](d);
        mx2.sel(mx2_sel); mx2.y(mx2_operand);
        bk.x(rg_value); bk.pass(bk_pass); bk.y(bk_operand);
        k_carry0.y(carry0);
        sm.a(mx2_operand); sm.b(bk_operand); sm.cin(carry0); sm.s(sm_sum);
        ctrl.clk(clk); ctrl.start(start); ctrl.deg2(deg2); ctrl.t(t);
        ctrl.mx1_sel(mx1_sel); ctrl.mx2_sel(mx2_sel); ctrl.bk_pass(bk_pass); ctrl.step(step);
        ctrl.done(done); ctrl.busy(busy);
        out_wire.x(rg_value); out_wire.y(i_t);
        chk_clock.clk(clk);
    }

    void end_of_elaboration() override { chk_clock.derive(timing_graph(*this)); }
    // Shortest clock phases this unit works with (checked by chk_clock; after elaboration).
    const sc_core::sc_time& min_high() const { return chk_clock.min_high(); }
    const sc_core::sc_time& min_low() const { return chk_clock.min_low(); }
};

}  // namespace shading
