// The iterative Horner unit's pins (the interpolation paper, Fig. 4), their names and widths written once
// for the block model (horner_unit.h) and its fast pin-level model (horner_unit_fast.h). Each derives
// from horner_unit_pins after sc_module, so the ports are the module's children, named as here.
#pragma once

#include <systemc>

#include "formats/interp_formats.h"

namespace shading {

struct horner_unit_pins {
    using coef_t = sc_dt::sc_uint<interp::coef_fmt.width>;  // A..D and I(t), Q16.16 signed
    using t_t = sc_dt::sc_uint<interp::t_fmt.width>;        // t, Q1.8 unsigned

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> start{"start"};
    sc_core::sc_in<bool> deg2{"deg2"};
    sc_core::sc_in<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"};
    sc_core::sc_in<t_t> t{"t"};
    sc_core::sc_out<coef_t> i_t{"i_t"};
    sc_core::sc_out<bool> done{"done"}, busy{"busy"};

    // RG, the partial Horner sum: a net of both models (the block model's register output, the fast
    // model's value per step), so the benches' monitor checks every micro-step of either.
    sc_core::sc_signal<coef_t> rg_value{"rg_value"};
};

}  // namespace shading
