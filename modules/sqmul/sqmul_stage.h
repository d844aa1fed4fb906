// The square-and-multiply device's iterative stage (ours; RTL twin rtl/sqmul/sqmul_stage.v): one
// Q1.18 multiplier whose second operand is RG_P or cos.
//   MX_B    RG_P (a square) or cos (a multiplication)             <- ctl.mx_b_sel
//   MUL_P   RG_P x MX_B: Q1.18^2 = Q2.36, 18 low wires open (floor), the 19 above kept
//   MX_P    hold (RG_P), load (cos), product (MUL_P)              <- ctl.mx_p_sel
//   RG_P    Q1.18, latches MX_P at every falling edge of clk (hold = recirculate: a load enable
//           built from the multiplexer, not a gated clock)
//   sync17  strobe 17's request into clk's domain: sqmul::sync_stages flip-flops (blocks/
//           synchroniser.h); ctl's flip-flops on clk read only its output
//   ctl     sqmul_ctrl.h: LOAD at the rising edge after the request crossed, the walk over n's bits,
//           then done
// The result is RG_P after the walk: brdf, read by the colour multipliers.
#pragma once

#include <systemc>

#include "blocks/mul.h"
#include "blocks/mux.h"
#include "blocks/reg.h"
#include "blocks/synchroniser.h"
#include "formats/sqmul_formats.h"
#include "specular/block_delays.h"
#include "sqmul/sqmul_ctrl.h"

namespace shading {

class sqmul_stage : public sc_core::sc_module {
    static constexpr unsigned WP = sqmul::p_fmt.width;  // 19
    using p_t = sc_dt::sc_uint<WP>;

public:
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> ctl17{"ctl17"};
    sc_core::sc_in<sqmul_ctrl::z_t> z{"z"};
    sc_core::sc_in<sqmul_ctrl::f_t> f{"f"};
    sc_core::sc_in<p_t> c{"c"};          // cos, Q1.18
    sc_core::sc_out<p_t> brdf{"brdf"};   // RG_P
    sc_core::sc_out<bool> done{"done"};  // output 29's gate

    sc_core::sc_signal<bool> ctl_req{"ctl_req"};        // strobe 17's request (its domain)
    sc_core::sc_signal<bool> sync17_req{"sync17_req"};  // the same, synchronised to clk
    sc_core::sc_signal<sqmul_ctrl::p_select_t> mx_p_sel{"mx_p_sel"};
    sc_core::sc_signal<sqmul_ctrl::b_select_t> mx_b_sel{"mx_b_sel"};
    sc_core::sc_signal<p_t> mx_b_operand{"mx_b_operand"};
    sc_core::sc_signal<p_t> mul_p_product{"mul_p_product"};
    sc_core::sc_signal<p_t> mx_p_next{"mx_p_next"};

    synchroniser<1, sqmul::sync_stages> sync17;
    sqmul_ctrl ctl;
    mux<WP, sqmul::b_inputs> mx_b;
    mul<WP, WP, WP, sqmul::p_frac> mul_p;  // Q1.18 x Q1.18 -> Q2.36, floor to Q1.18
    mux<WP, sqmul::p_inputs> mx_p;
    reg<WP> rg_p;

    sqmul_stage(const sc_core::sc_module_name& name, const block_delays& t = {})
        : sc_module(name), sync17("sync17"), ctl("ctl"),
          mx_b("mx_b", t.mux), mul_p("mul_p", t.multiplier), mx_p("mx_p", t.mux),
          rg_p("rg_p", t.reg) {
        ctl.clk(clk); ctl.ctl17(ctl17); ctl.req_s(sync17_req); ctl.z(z); ctl.f(f);
        ctl.mx_p_sel(mx_p_sel); ctl.mx_b_sel(mx_b_sel); ctl.done(done); ctl.req(ctl_req);
        sync17.clk(clk); sync17.d(ctl_req); sync17.q(sync17_req);
        mx_b.in[sqmul::b_p](brdf);
        mx_b.in[sqmul::b_cos](c);
        mx_b.sel(mx_b_sel); mx_b.y(mx_b_operand);
        mul_p.a(brdf); mul_p.b(mx_b_operand); mul_p.p(mul_p_product);
        mx_p.in[sqmul::p_hold](brdf);
        mx_p.in[sqmul::p_load](c);
        mx_p.in[sqmul::p_product](mul_p_product);
        mx_p.sel(mx_p_sel); mx_p.y(mx_p_next);
        rg_p.ctl(clk); rg_p.d(mx_p_next); rg_p.q(brdf);
    }
};

}  // namespace shading
