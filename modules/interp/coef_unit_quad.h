// Quadratic coefficient unit of the interpolation paper: a, b, c of I(t) = a t^2 + b t + c through
// I1, I2, I3 at t = 0, 1/2, 1 -- only shifts and adds, no division:
//   a = 2 I1 - 4 I2 + 2 I3,  b = -3 I1 + 4 I2 - I3,  c = I1.
// Same timing and formats as coef_unit_cubic: samples latched on the falling edge of clk, a..c
// valid at the next rising edge; Q8.8 in, Q16.16 out (exact). Only instantiates and wires.
#pragma once

#include <systemc>
#include <vector>

#include "blocks/reg.h"
#include "blocks/shift_add_network.h"
#include "blocks/shifter.h"
#include "core/timing_graph.h"
#include "formats/interp_formats.h"
#include "interp/interp_delays.h"
#include "monitors/phase_checker.h"

namespace shading {

namespace coef_terms {
inline const std::vector<sa_term> a_quad{{0, 1, false}, {2, 1, false}, {1, 2, true}};
inline const std::vector<sa_term> b_quad{{1, 2, false}, {0, 1, true}, {0, 0, true}, {2, 0, true}};  // -3 = -2 - 1
}  // namespace coef_terms

class coef_unit_quad : public sc_core::sc_module {
    static constexpr unsigned WI = interp::sample_fmt.width;
    static constexpr unsigned WS = interp::sum_fmt.width;
    static constexpr unsigned WC = interp::coef_fmt.width;
    using sample_t = sc_dt::sc_uint<WI>;
    using sum_t = sc_dt::sc_uint<WS>;
    using coef_t = sc_dt::sc_uint<WC>;

public:
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<sample_t> i1{"i1"}, i2{"i2"}, i3{"i3"};
    sc_core::sc_out<coef_t> a{"a"}, b{"b"}, c{"c"};

    sc_core::sc_signal<sample_t> held_i1{"held_i1"}, held_i2{"held_i2"}, held_i3{"held_i3"};
    sc_core::sc_signal<sum_t> a_sum{"a_sum"}, b_sum{"b_sum"};

    reg<WI> rg_i1, rg_i2, rg_i3;
    shift_add_network<WI, WS> net_a{"net_a", 3, coef_terms::a_quad};  // Q8.8 -> Q16.8
    shift_add_network<WI, WS> net_b{"net_b", 3, coef_terms::b_quad};  // Q8.8 -> Q16.8
    shifter<WS, WC, true> align_a{"align_a", interp::div3_shift};     // Q16.8 -> Q16.16
    shifter<WS, WC, true> align_b{"align_b", interp::div3_shift};     // Q16.8 -> Q16.16
    shifter<WI, WC, false> align_c{"align_c", interp::div3_shift};    // Q8.8 -> Q16.16
    // Assertion monitor (not hardware). High: I1..I3 straight into rg_i1..3 (their setup time);
    // low: rg_i clock-to-output -> networks -> a..c before the rising edge. Derived from the
    // elaborated blocks at end_of_elaboration.
    phase_checker chk_clock{"chk_clock"};

    explicit coef_unit_quad(const sc_core::sc_module_name& name, const interp_delays& t = {})
        : sc_module(name), rg_i1("rg_i1", t.reg), rg_i2("rg_i2", t.reg), rg_i3("rg_i3", t.reg) {
        rg_i1.ctl(clk); rg_i1.d(i1); rg_i1.q(held_i1);
        rg_i2.ctl(clk); rg_i2.d(i2); rg_i2.q(held_i2);
        rg_i3.ctl(clk); rg_i3.d(i3); rg_i3.q(held_i3);
        for (auto* n : {&net_a, &net_b}) {
            n->in[0](held_i1); n->in[1](held_i2); n->in[2](held_i3);
        }
        net_a.y(a_sum);
        net_b.y(b_sum);
        align_a.x(a_sum); align_a.y(a);
        align_b.x(b_sum); align_b.y(b);
        align_c.x(held_i1); align_c.y(c);
        chk_clock.clk(clk);
    }

    void end_of_elaboration() override { chk_clock.derive(timing_graph(*this)); }
    // Shortest clock phases this unit works with (checked by chk_clock; after elaboration).
    const sc_core::sc_time& min_high() const { return chk_clock.min_high(); }
    const sc_core::sc_time& min_low() const { return chk_clock.min_low(); }
};

}  // namespace shading
