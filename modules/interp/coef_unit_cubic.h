// Cubic coefficient unit of the interpolation paper: A, B, C, D of I(t) = A t^3 + B t^2 + C t + D from
// four exact intensities I1..I4, with shifts, adds and subtracts only (no multiplier). The samples
// are latched in rg_i1..rg_i4 on the falling edge of clk; the networks settle within the half
// period, so A..D are valid at the next rising edge: latency 1 clock, one interval per clock.
// Formats (src/interp_formats.h): I Q8.8 unsigned -> network sums Q16.8 signed -> A..D Q16.16
// signed. Division by 3: the interpolation paper, Fig. 2 shift-and-add (div3_mode::shift_add) or an exact
// constant divider (div3_mode::exact). This class only instantiates and wires.
#pragma once

#include <systemc>
#include <type_traits>
#include <vector>

#include "blocks/const_div.h"
#include "blocks/div3_shift_add.h"
#include "blocks/reg.h"
#include "blocks/shift_add_network.h"
#include "blocks/shifter.h"
#include "core/timing_graph.h"
#include "formats/interp_formats.h"
#include "interp/interp_delays.h"
#include "monitors/phase_checker.h"

namespace shading {

namespace coef_terms {
// Each weight written as shifts (CSD): {input (0 = I1 .. 3 = I4), shift, negative}.
// Case 1, t = 0, 1/4, 1/2, 1.
// 8 * (-(3I1 - 8I2 + 6I3 - I4)) = -24 I1 + 64 I2 - 48 I3 + 8 I4; A = that / 3.
inline const std::vector<sa_term> a8_case1{{1, 6, false}, {3, 3, false}, {0, 3, false}, {2, 4, false},
                                           {0, 5, true}, {2, 6, true}};  // -24 = 8 - 32, -48 = 16 - 64
// B = 2(7I1 - 16I2 + 10I3 - I4) = 14 I1 - 32 I2 + 20 I3 - 2 I4.
inline const std::vector<sa_term> b_case1{{0, 4, false}, {2, 4, false}, {2, 2, false}, {0, 1, true},
                                          {1, 5, true}, {3, 1, true}};  // 14 = 16 - 2, 20 = 16 + 4
// -(21I1 - 32I2 + 12I3 - I4) = -21 I1 + 32 I2 - 12 I3 + I4; C = that / 3.
inline const std::vector<sa_term> c3_case1{{1, 5, false}, {3, 0, false}, {2, 2, false}, {0, 4, true},
                                           {0, 2, true}, {0, 0, true}, {2, 4, true}};  // -12 = 4 - 16
// Case 2, t = 0, 1/2, 3/4, 1.
// 8 * (-(I1 - 6I2 + 8I3 - 3I4)) = -8 I1 + 48 I2 - 64 I3 + 24 I4.
inline const std::vector<sa_term> a8_case2{{1, 6, false}, {3, 5, false}, {1, 4, true}, {3, 3, true},
                                           {0, 3, true}, {2, 6, true}};  // 48 = 64 - 16, 24 = 32 - 8
// B = 2(3I1 - 14I2 + 16I3 - 5I4) = 6 I1 - 28 I2 + 32 I3 - 10 I4.
inline const std::vector<sa_term> b_case2{{2, 5, false}, {0, 3, false}, {1, 2, false}, {0, 1, true},
                                          {1, 5, true}, {3, 3, true}, {3, 1, true}};  // 6 = 8 - 2, -28 = 4 - 32
// -(13I1 - 36I2 + 32I3 - 9I4) = -13 I1 + 36 I2 - 32 I3 + 9 I4.
inline const std::vector<sa_term> c3_case2{{1, 5, false}, {1, 2, false}, {3, 3, false}, {3, 0, false},
                                           {0, 1, false}, {0, 0, false}, {0, 4, true},
                                           {2, 5, true}};  // -13 = 2 + 1 - 16, 36 = 32 + 4, 9 = 8 + 1
}  // namespace coef_terms

template <interp::sample_set SET, interp::div3_mode DIV>
class coef_unit_cubic : public sc_core::sc_module {
    static constexpr unsigned WI = interp::sample_fmt.width;  // 16
    static constexpr unsigned WS = interp::sum_fmt.width;     // 24
    static constexpr unsigned WC = interp::coef_fmt.width;    // 32
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
    sc_core::sc_signal<sum_t> a8_sum{"a8_sum"}, b_sum{"b_sum"}, c3_sum{"c3_sum"};

    // Blocks.
    reg<WI> rg_i1, rg_i2, rg_i3, rg_i4;
    shift_add_network<WI, WS> net_a;  // Q8.8 -> Q16.8: 8 * (-S_A)
    shift_add_network<WI, WS> net_b;  // Q8.8 -> Q16.8: B
    shift_add_network<WI, WS> net_c;  // Q8.8 -> Q16.8: -S_C
    div3_t div3_a{"div3_a"};          // Q16.8 / 3 -> Q16.16
    div3_t div3_c{"div3_c"};          // Q16.8 / 3 -> Q16.16
    shifter<WS, WC, true> align_b{"align_b", interp::div3_shift};    // Q16.8 -> Q16.16, wiring
    shifter<WI, WC, false> align_d{"align_d", interp::div3_shift};   // Q8.8 -> Q16.16, wiring
    // Assertion monitor (not hardware). High: I1..I4 straight into rg_i1..4 (their setup time);
    // low: rg_i clock-to-output -> networks -> /3 -> A..D before the rising edge. Derived from the
    // elaborated blocks at end_of_elaboration.
    phase_checker chk_clock{"chk_clock"};

    explicit coef_unit_cubic(const sc_core::sc_module_name& name, const interp_delays& t = {})
        : sc_module(name),
          rg_i1("rg_i1", t.reg), rg_i2("rg_i2", t.reg), rg_i3("rg_i3", t.reg), rg_i4("rg_i4", t.reg),
          net_a("net_a", 4, SET == interp::sample_set::case1 ? coef_terms::a8_case1 : coef_terms::a8_case2),
          net_b("net_b", 4, SET == interp::sample_set::case1 ? coef_terms::b_case1 : coef_terms::b_case2),
          net_c("net_c", 4, SET == interp::sample_set::case1 ? coef_terms::c3_case1 : coef_terms::c3_case2) {
        rg_i1.ctl(clk); rg_i1.d(i1); rg_i1.q(held_i1);
        rg_i2.ctl(clk); rg_i2.d(i2); rg_i2.q(held_i2);
        rg_i3.ctl(clk); rg_i3.d(i3); rg_i3.q(held_i3);
        rg_i4.ctl(clk); rg_i4.d(i4); rg_i4.q(held_i4);
        for (auto* n : {&net_a, &net_b, &net_c}) {
            n->in[0](held_i1); n->in[1](held_i2); n->in[2](held_i3); n->in[3](held_i4);
        }
        net_a.y(a8_sum);
        net_b.y(b_sum);
        net_c.y(c3_sum);
        div3_a.x(a8_sum); div3_a.y(a);
        div3_c.x(c3_sum); div3_c.y(c);
        align_b.x(b_sum); align_b.y(b);
        align_d.x(held_i1); align_d.y(d);
        chk_clock.clk(clk);
    }

    void end_of_elaboration() override { chk_clock.derive(timing_graph(*this)); }
    // Shortest clock phases this unit works with (checked by chk_clock; after elaboration).
    const sc_core::sc_time& min_high() const { return chk_clock.min_high(); }
    const sc_core::sc_time& min_low() const { return chk_clock.min_low(); }
};

}  // namespace shading
