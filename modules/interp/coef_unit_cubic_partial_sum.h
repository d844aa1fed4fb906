// Cubic coefficient unit with the interpolation paper's grouping of the division by 3 (the paper's
// printed formulas): /3 only on the part of A and C whose weights are not multiples of 3, the rest
// added as an integer,
//   case 1:  A = 8(8I2 + I4)/3 - 8(I1 + 2I3),   C = (32I2 + I4)/3 - 7I1 - 4I3,
//   case 2:  A = 8(2I2 + I4) - 8(I1 + 8I3)/3,   C = 3(4I2 + I4) - (13I1 + 32I3)/3,
// B and D as in coef_unit_cubic.h. coef_unit_cubic.h divides the whole weighted sum instead; the
// two are selectable (coef_unit_cubic_t below) and measured side by side (interp_study). Per
// coefficient: a network for the divided part -> /3 (Fig. 2 shift-and-add or exact) onto Q.16; a
// network for the integer part -> aligned onto Q.16; one subtractor (inverter bank + adder with
// carry-in 1). Same registers, formats and timing as coef_unit_cubic: samples latched on the
// falling edge, A..D valid at the next rising edge. This class only instantiates and wires.
#pragma once

#include <systemc>
#include <type_traits>
#include <vector>

#include "blocks/adder.h"
#include "blocks/const_div.h"
#include "blocks/constant.h"
#include "blocks/div3_shift_add.h"
#include "blocks/inverter_bank.h"
#include "blocks/reg.h"
#include "blocks/shift_add_network.h"
#include "blocks/shifter.h"
#include "core/timing_graph.h"
#include "formats/interp_formats.h"
#include "interp/coef_unit_cubic.h"
#include "interp/interp_delays.h"
#include "monitors/phase_checker.h"

namespace shading {

namespace coef_terms {
// {input (0 = I1 .. 3 = I4), shift, negative}. "div": the part divided by 3; "int": the integer part.
// Case 1: A = div/3 - int, C = div/3 - int.
inline const std::vector<sa_term> a_div_case1{{1, 6, false}, {3, 3, false}};                  // 64 I2 + 8 I4
inline const std::vector<sa_term> a_int_case1{{0, 3, false}, {2, 4, false}};                  // 8 I1 + 16 I3
inline const std::vector<sa_term> c_div_case1{{1, 5, false}, {3, 0, false}};                  // 32 I2 + I4
inline const std::vector<sa_term> c_int_case1{{0, 3, false}, {2, 2, false}, {0, 0, true}};    // 7 = 8 - 1; 4 I3
// Case 2: A = int - div/3, C = int - div/3.
inline const std::vector<sa_term> a_div_case2{{0, 3, false}, {2, 6, false}};                  // 8 I1 + 64 I3
inline const std::vector<sa_term> a_int_case2{{1, 4, false}, {3, 3, false}};                  // 16 I2 + 8 I4
inline const std::vector<sa_term> c_div_case2{{0, 3, false}, {0, 2, false}, {0, 0, false},
                                              {2, 5, false}};                                 // 13 = 8 + 4 + 1; 32 I3
inline const std::vector<sa_term> c_int_case2{{1, 3, false}, {1, 2, false}, {3, 1, false},
                                              {3, 0, false}};                                 // 12 = 8 + 4, 3 = 2 + 1
}  // namespace coef_terms

template <interp::sample_set SET, interp::div3_mode DIV>
class coef_unit_cubic_partial_sum : public sc_core::sc_module {
    static constexpr unsigned WI = interp::sample_fmt.width;
    static constexpr unsigned WS = interp::sum_fmt.width;
    static constexpr unsigned WC = interp::coef_fmt.width;
    static constexpr bool case1 = SET == interp::sample_set::case1;
    using sample_t = sc_dt::sc_uint<WI>;
    using sum_t = sc_dt::sc_uint<WS>;
    using coef_t = sc_dt::sc_uint<WC>;
    using div3_t = std::conditional_t<DIV == interp::div3_mode::shift_add,
                                      div3_shift_add<WS, WC, interp::div3_shift>,
                                      const_div<WS, WC, 3, interp::div3_shift>>;

public:
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<sample_t> i1{"i1"}, i2{"i2"}, i3{"i3"}, i4{"i4"};
    sc_core::sc_out<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"};

    // Nets.
    sc_core::sc_signal<sample_t> held_i1{"held_i1"}, held_i2{"held_i2"}, held_i3{"held_i3"}, held_i4{"held_i4"};
    sc_core::sc_signal<sum_t> a_div_sum{"a_div_sum"}, a_int_sum{"a_int_sum"}, b_sum{"b_sum"};
    sc_core::sc_signal<sum_t> c_div_sum{"c_div_sum"}, c_int_sum{"c_int_sum"};
    sc_core::sc_signal<coef_t> a_third{"a_third"}, a_int{"a_int"}, a_subtrahend_inv{"a_subtrahend_inv"};
    sc_core::sc_signal<coef_t> c_third{"c_third"}, c_int{"c_int"}, c_subtrahend_inv{"c_subtrahend_inv"};
    sc_core::sc_signal<bool> carry1{"carry1"};

    // Blocks.
    reg<WI> rg_i1, rg_i2, rg_i3, rg_i4;
    shift_add_network<WI, WS> net_a_div, net_a_int;  // Q8.8 -> Q16.8
    shift_add_network<WI, WS> net_b;                 // Q8.8 -> Q16.8: B
    shift_add_network<WI, WS> net_c_div, net_c_int;  // Q8.8 -> Q16.8
    div3_t div3_a{"div3_a"};                         // Q16.8 / 3 -> Q16.16
    div3_t div3_c{"div3_c"};                         // Q16.8 / 3 -> Q16.16
    shifter<WS, WC, true> align_a_int{"align_a_int", interp::div3_shift};  // Q16.8 -> Q16.16, wiring
    shifter<WS, WC, true> align_c_int{"align_c_int", interp::div3_shift};  // Q16.8 -> Q16.16, wiring
    shifter<WS, WC, true> align_b{"align_b", interp::div3_shift};          // Q16.8 -> Q16.16, wiring
    shifter<WI, WC, false> align_d{"align_d", interp::div3_shift};         // Q8.8 -> Q16.16, wiring
    inverter_bank<WC> inv_a, inv_c;         // ~subtrahend (case 1: the integer part)
    adder<WC, WC, WC, true, true> sub_a;    // minuend + ~subtrahend + 1, Q16.16
    adder<WC, WC, WC, true, true> sub_c;
    constant<bool> k_carry1{"k_carry1", true};
    // Assertion monitor (not hardware). High: I1..I4 straight into rg_i1..4 (their setup time);
    // low: rg_i clock-to-output -> networks -> /3 -> subtractors -> A..D before the rising edge.
    // Derived from the elaborated blocks at end_of_elaboration.
    phase_checker chk_clock{"chk_clock"};

    explicit coef_unit_cubic_partial_sum(const sc_core::sc_module_name& name, const interp_delays& t = {})
        : sc_module(name),
          rg_i1("rg_i1", t.reg), rg_i2("rg_i2", t.reg), rg_i3("rg_i3", t.reg), rg_i4("rg_i4", t.reg),
          net_a_div("net_a_div", 4, case1 ? coef_terms::a_div_case1 : coef_terms::a_div_case2),
          net_a_int("net_a_int", 4, case1 ? coef_terms::a_int_case1 : coef_terms::a_int_case2),
          net_b("net_b", 4, case1 ? coef_terms::b_case1 : coef_terms::b_case2),
          net_c_div("net_c_div", 4, case1 ? coef_terms::c_div_case1 : coef_terms::c_div_case2),
          net_c_int("net_c_int", 4, case1 ? coef_terms::c_int_case1 : coef_terms::c_int_case2),
          inv_a("inv_a", t.inverter), inv_c("inv_c", t.inverter),
          sub_a("sub_a", overflow_mode::wrap, 0, 0, t.adder), sub_c("sub_c", overflow_mode::wrap, 0, 0, t.adder) {
        rg_i1.ctl(clk); rg_i1.d(i1); rg_i1.q(held_i1);
        rg_i2.ctl(clk); rg_i2.d(i2); rg_i2.q(held_i2);
        rg_i3.ctl(clk); rg_i3.d(i3); rg_i3.q(held_i3);
        rg_i4.ctl(clk); rg_i4.d(i4); rg_i4.q(held_i4);
        for (auto* n : {&net_a_div, &net_a_int, &net_b, &net_c_div, &net_c_int}) {
            n->in[0](held_i1); n->in[1](held_i2); n->in[2](held_i3); n->in[3](held_i4);
        }
        net_a_div.y(a_div_sum); net_a_int.y(a_int_sum);
        net_b.y(b_sum);
        net_c_div.y(c_div_sum); net_c_int.y(c_int_sum);
        div3_a.x(a_div_sum); div3_a.y(a_third);
        div3_c.x(c_div_sum); div3_c.y(c_third);
        align_a_int.x(a_int_sum); align_a_int.y(a_int);
        align_c_int.x(c_int_sum); align_c_int.y(c_int);
        k_carry1.y(carry1);
        // Case 1 subtracts the integer part from the quotient, case 2 the quotient from it.
        wire_subtract(sub_a, inv_a, case1 ? a_third : a_int, case1 ? a_int : a_third, a_subtrahend_inv, a);
        wire_subtract(sub_c, inv_c, case1 ? c_third : c_int, case1 ? c_int : c_third, c_subtrahend_inv, c);
        align_b.x(b_sum); align_b.y(b);
        align_d.x(held_i1); align_d.y(d);
        chk_clock.clk(clk);
    }

    void end_of_elaboration() override { chk_clock.derive(timing_graph(*this)); }
    // Shortest clock phases this unit works with (checked by chk_clock; after elaboration).
    const sc_core::sc_time& min_high() const { return chk_clock.min_high(); }
    const sc_core::sc_time& min_low() const { return chk_clock.min_low(); }

private:
    void wire_subtract(adder<WC, WC, WC, true, true>& sub, inverter_bank<WC>& inv,
                              sc_core::sc_signal<coef_t>& minuend, sc_core::sc_signal<coef_t>& subtrahend,
                              sc_core::sc_signal<coef_t>& inverted, sc_core::sc_out<coef_t>& out) {
        inv.x(subtrahend); inv.y(inverted);
        sub.a(minuend); sub.b(inverted); sub.cin(carry1); sub.s(out);
    }
};

// The coefficient unit by grouping of the /3: today's whole weighted sum or the interpolation paper's partial sum.
template <interp::sample_set SET, interp::div3_mode DIV, interp::div3_grouping G>
using coef_unit_cubic_t = std::conditional_t<G == interp::div3_grouping::whole_sum, coef_unit_cubic<SET, DIV>,
                                             coef_unit_cubic_partial_sum<SET, DIV>>;

}  // namespace shading
