// One colour channel's evaluator with the interpolation paper's Fig. 4 Horner unit: the degree-select pin picks
// the coefficient unit (mx_a, mx_b, mx_c: 0 the cubic's A, B, C, 1 the quadratic's a, b, c; D is
// the cubic's, unused at degree 2), horner evaluates I(t) at the t the pixel controller issues, and
// out_clamp turns the Q16.16 signed result into the pixel's Q8.8 unsigned code (floor, saturated
// to [0, 0xFFFF]; golden_output_clamp). Only instantiates and wires.
#pragma once

#include <systemc>

#include "blocks/clamp.h"
#include "blocks/mux.h"
#include "formats/interp_formats.h"
#include "interp/horner_unit.h"
#include "interp/interp_delays.h"
#include "pipeline/sample_channel.h"

namespace shading {

class horner_channel : public sc_core::sc_module {
public:
    using sel_t = sc_dt::sc_uint<1>;
    using t_t = sc_dt::sc_uint<interp::t_fmt.width>;

    sc_core::sc_in<bool> clk{"clk"}, start{"start"}, deg2{"deg2"};
    sc_core::sc_in<sel_t> deg_sel{"deg_sel"};  // deg2 as the multiplexers' select code
    sc_core::sc_in<t_t> t{"t"};
    sc_core::sc_in<pipeline::coef_t> ca{"ca"}, cb{"cb"}, cc{"cc"}, cd{"cd"}, qa{"qa"}, qb{"qb"}, qc{"qc"};
    sc_core::sc_out<pipeline::sample_t> px{"px"};
    sc_core::sc_out<bool> done{"done"}, busy{"busy"};

    sc_core::sc_signal<pipeline::coef_t> a{"a"}, b{"b"}, c{"c"}, i_t{"i_t"};

    mux<interp::coef_fmt.width, 2> mx_a, mx_b, mx_c;
    horner_unit horner;
    clamp<interp::coef_fmt.width, interp::sample_fmt.width, interp::coef_fmt.frac - interp::sample_fmt.frac> out_clamp;

    horner_channel(const sc_core::sc_module_name& name, const interp_delays& dl = {})
        : sc_module(name), mx_a("mx_a", dl.mux), mx_b("mx_b", dl.mux), mx_c("mx_c", dl.mux), horner("horner", dl),
          out_clamp("out_clamp", dl.adder) {
        mx_a.in[0](ca); mx_a.in[1](qa); mx_a.sel(deg_sel); mx_a.y(a);
        mx_b.in[0](cb); mx_b.in[1](qb); mx_b.sel(deg_sel); mx_b.y(b);
        mx_c.in[0](cc); mx_c.in[1](qc); mx_c.sel(deg_sel); mx_c.y(c);
        horner.clk(clk); horner.start(start); horner.deg2(deg2);
        horner.a(a); horner.b(b); horner.c(c); horner.d(cd); horner.t(t);
        horner.i_t(i_t); horner.done(done); horner.busy(busy);
        out_clamp.x(i_t); out_clamp.y(px);
    }
    // The Horner unit takes any interval length: fd_channel's constructor, the length ignored.
    horner_channel(const sc_core::sc_module_name& name, unsigned /*m*/, const interp_delays& dl)
        : horner_channel(name, dl) {}
};

}  // namespace shading
