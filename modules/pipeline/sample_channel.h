// One colour channel of the shading pipeline's sample stage and coefficient units (the interpolation paper's
// system; the sample stage's formats are this model's decisions, src/floor/formats/pipeline_formats.h):
//   diffuse  mul_diffuse  k_d*I (8.0) x N.L (Q1.15) -> Q9.8, 7 low wires dropped (floor)
//   colour   add_ambient  ambient (Q8.8) + diffuse (Q9.8) -> Q10.8 (never overflows)
//            add_colour   + the device's specular out25/26/27 (Q9.8), saturated to Q8.8 (0xFFFF)
//   mx_carry      the colour bus (ours): the colour just formed, or with carry_sel the last
//                 sample's colour from rg_last (a job whose first point is the last sample's point)
//   rg_last       the last sample's colour (strobe ld_last, at every sample's latch)
//   rg_i1..rg_i4  the sample registers I1..I4 on the colour bus, each latched by its own strobe
//                 ld_i1..ld_i4 (an exact pixel's one sample is latched into all four at once)
//   rg_e1..rg_e4  the interval registers: the four samples handed to the coefficient units by the
//                 pixel controller's strobe ld_e, so the next interval's samples can be formed
//                 while this interval's pixels are evaluated
//   coef_cubic    the interpolation paper's cubic coefficient unit (A..D; sample set and /3 chosen at construction)
//   coef_quad     the quadratic unit (a, b, c through rg_e1..rg_e3 at t = 0, 1/2, 1)
// Only instantiates and wires.
#pragma once

#include <memory>
#include <sstream>
#include <systemc>

#include "blocks/adder.h"
#include "blocks/constant.h"
#include "blocks/mul.h"
#include "blocks/mux.h"
#include "blocks/reg.h"
#include "core/report_ids.h"
#include "formats/interp_formats.h"
#include "formats/pipeline_formats.h"
#include "formats/specular_formats.h"
#include "interp/coef_unit_cubic.h"
#include "interp/coef_unit_quad.h"
#include "interp/interp_delays.h"
#include "pipeline/pipeline_pins.h"

namespace shading {

class sample_channel : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> ld_i1{"ld_i1"}, ld_i2{"ld_i2"}, ld_i3{"ld_i3"}, ld_i4{"ld_i4"}, ld_e{"ld_e"};
    sc_core::sc_in<pipeline::kdi_t> kdi{"kdi"};              // frame constant k_d * I_l
    sc_core::sc_in<pipeline::sample_t> ambient{"ambient"};   // frame constant 255 * ambient, Q8.8
    sc_core::sc_in<pipeline::cos_t> cos_nl{"cos_nl"};        // this sample's N.L
    sc_core::sc_in<pipeline::spec_t> specular{"specular"};   // the device's out25 / out26 / out27
    sc_core::sc_in<sc_dt::sc_uint<1>> carry_sel{"carry_sel"};  // 1: the bus carries the last sample
    sc_core::sc_in<bool> ld_last{"ld_last"};
    sc_core::sc_out<pipeline::coef_t> ca{"ca"}, cb{"cb"}, cc{"cc"}, cd{"cd"};  // cubic A..D, Q16.16
    sc_core::sc_out<pipeline::coef_t> qa{"qa"}, qb{"qb"}, qc{"qc"};            // quadratic a..c

    // Nets.
    sc_core::sc_signal<pipeline::spec_t> mul_diffuse_p{"mul_diffuse_p"};
    sc_core::sc_signal<sc_dt::sc_uint<pipeline::ad_fmt.width>> add_ambient_s{"add_ambient_s"};
    sc_core::sc_signal<pipeline::sample_t> colour{"colour"};
    sc_core::sc_signal<pipeline::sample_t> bus{"bus"}, last{"last"};  // the colour bus, the last sample
    sc_core::sc_signal<pipeline::sample_t> i1{"i1"}, i2{"i2"}, i3{"i3"}, i4{"i4"};  // sample registers
    sc_core::sc_signal<pipeline::sample_t> e1{"e1"}, e2{"e2"}, e3{"e3"}, e4{"e4"};  // interval registers
    sc_core::sc_signal<bool> carry0{"carry0"};

    // Blocks.
    mul<pipeline::kdi_fmt.width, spec::cos_fmt.width, pipeline::diffuse_fmt.width, pipeline::diffuse_drop> mul_diffuse;
    adder<pipeline::ambient_fmt.width, pipeline::diffuse_fmt.width, pipeline::ad_fmt.width> add_ambient;
    adder<pipeline::ad_fmt.width, spec::out_fmt.width, pipeline::colour_fmt.width> add_colour;  // saturating
    constant<bool> k_carry0{"k_carry0", false};
    mux<interp::sample_fmt.width, 2> mx_carry;
    reg<interp::sample_fmt.width> rg_last;
    reg<interp::sample_fmt.width> rg_i1, rg_i2, rg_i3, rg_i4, rg_e1, rg_e2, rg_e3, rg_e4;
    std::unique_ptr<sc_core::sc_module> coef_cubic;  // coef_unit_cubic<set, div>
    coef_unit_quad coef_quad;

    sample_channel(const sc_core::sc_module_name& name, interp::sample_set set, interp::div3_mode div,
                   const interp_delays& t = {})
        : sc_module(name), mul_diffuse("mul_diffuse", t.multiplier),
          add_ambient("add_ambient", overflow_mode::wrap, 0, 0, t.adder),
          add_colour("add_colour", overflow_mode::saturate, 0, static_cast<int64_t>(pipeline::colour_fmt.mask()), t.adder),
          mx_carry("mx_carry", t.mux), rg_last("rg_last", t.reg),
          rg_i1("rg_i1", t.reg), rg_i2("rg_i2", t.reg), rg_i3("rg_i3", t.reg), rg_i4("rg_i4", t.reg),
          rg_e1("rg_e1", t.reg), rg_e2("rg_e2", t.reg), rg_e3("rg_e3", t.reg), rg_e4("rg_e4", t.reg),
          coef_quad("coef_quad", t) {
        mul_diffuse.a(kdi); mul_diffuse.b(cos_nl); mul_diffuse.p(mul_diffuse_p);
        k_carry0.y(carry0);
        add_ambient.a(ambient); add_ambient.b(mul_diffuse_p); add_ambient.cin(carry0); add_ambient.s(add_ambient_s);
        add_colour.a(add_ambient_s); add_colour.b(specular); add_colour.cin(carry0); add_colour.s(colour);
        mx_carry.in[0](colour); mx_carry.in[1](last); mx_carry.sel(carry_sel); mx_carry.y(bus);
        rg_last.ctl(ld_last); rg_last.d(bus); rg_last.q(last);
        rg_i1.ctl(ld_i1); rg_i1.d(bus); rg_i1.q(i1);
        rg_i2.ctl(ld_i2); rg_i2.d(bus); rg_i2.q(i2);
        rg_i3.ctl(ld_i3); rg_i3.d(bus); rg_i3.q(i3);
        rg_i4.ctl(ld_i4); rg_i4.d(bus); rg_i4.q(i4);
        rg_e1.ctl(ld_e); rg_e1.d(i1); rg_e1.q(e1);
        rg_e2.ctl(ld_e); rg_e2.d(i2); rg_e2.q(e2);
        rg_e3.ctl(ld_e); rg_e3.d(i3); rg_e3.q(e3);
        rg_e4.ctl(ld_e); rg_e4.d(i4); rg_e4.q(e4);
        using interp::div3_mode, interp::sample_set;
        const bool c1 = set == sample_set::case1, sa = div == div3_mode::shift_add;
        if (c1 && sa) coef_cubic = make_cubic<sample_set::case1, div3_mode::shift_add>(t);
        else if (c1) coef_cubic = make_cubic<sample_set::case1, div3_mode::exact>(t);
        else if (sa) coef_cubic = make_cubic<sample_set::case2, div3_mode::shift_add>(t);
        else coef_cubic = make_cubic<sample_set::case2, div3_mode::exact>(t);
        coef_quad.clk(clk);
        coef_quad.i1(e1); coef_quad.i2(e2); coef_quad.i3(e3);
        coef_quad.a(qa); coef_quad.b(qb); coef_quad.c(qc);
    }

private:
    template <interp::sample_set SET, interp::div3_mode DIV>
    std::unique_ptr<sc_core::sc_module> make_cubic(const interp_delays& t) {
        auto u = std::make_unique<coef_unit_cubic<SET, DIV>>("coef_cubic", t);
        u->clk(clk);
        u->i1(e1); u->i2(e2); u->i3(e3); u->i4(e4);
        u->a(ca); u->b(cb); u->c(cc); u->d(cd);
        return u;
    }
};

}  // namespace shading
