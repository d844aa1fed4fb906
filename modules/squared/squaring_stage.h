// The squared-quadratic device's squaring stage (ours): one squarer iterated k = 9 - z times.
//   MX_SQ   hold (RG_SQ), load (ADD11: the quadratic at n'), square (MUL_SQ)   <- ctl_sq.sel
//   RG_SQ   Q1.18, latches MX_SQ at every falling edge of clk (hold = recirculate: a load enable
//           built from the multiplexer, as the Horner unit's RG, not a gated clock)
//   MUL_SQ  RG_SQ x RG_SQ: Q1.18^2 = Q2.36, 18 low wires open (floor), the 19 above kept
//   sync17  strobe 17's request into clk's domain: squared::sync_stages flip-flops (blocks/
//           synchroniser.h); ctl_sq's flip-flops on clk read only its output
//   ctl_sq  sq_ctrl.h: LOAD at the rising edge after the request crossed, k SQUAREs, then done
// The result is RG_SQ after the k-th square: brdf, read by the colour multipliers.
#pragma once

#include <systemc>

#include "blocks/mul.h"
#include "blocks/mux.h"
#include "blocks/reg.h"
#include "blocks/synchroniser.h"
#include "formats/squared_formats.h"
#include "specular/block_delays.h"
#include "squared/sq_ctrl.h"

namespace shading {

class squaring_stage : public sc_core::sc_module {
    static constexpr unsigned WQ = squared::q_fmt.width;  // 19
    using q_t = sc_dt::sc_uint<WQ>;

public:
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> ctl17{"ctl17"};
    sc_core::sc_in<sc_dt::sc_uint<squared::z_width>> z{"z"};
    sc_core::sc_in<q_t> q{"q"};          // ADD11
    sc_core::sc_out<q_t> brdf{"brdf"};   // RG_SQ
    sc_core::sc_out<bool> done{"done"};  // output 29's gate

    sc_core::sc_signal<bool> ctl_sq_req{"ctl_sq_req"};     // strobe 17's request (its domain)
    sc_core::sc_signal<bool> sync17_req{"sync17_req"};     // the same, synchronised to clk
    sc_core::sc_signal<sq_ctrl::select_t> mx_sq_sel{"mx_sq_sel"};
    sc_core::sc_signal<q_t> mx_sq_next{"mx_sq_next"};
    sc_core::sc_signal<q_t> mul_sq_square{"mul_sq_square"};

    synchroniser<1, squared::sync_stages> sync17;
    sq_ctrl ctl_sq;
    mux<WQ, 3> mx_sq;
    reg<WQ> rg_sq;
    mul<WQ, WQ, WQ, squared::q_frac> mul_sq;  // Q1.18 x Q1.18 -> Q2.36, floor to Q1.18

    squaring_stage(const sc_core::sc_module_name& name, const block_delays& t = {})
        : sc_module(name), sync17("sync17"), ctl_sq("ctl_sq"), mx_sq("mx_sq", t.mux), rg_sq("rg_sq", t.reg), mul_sq("mul_sq", t.multiplier) {
        static_assert(squared::sq_count::hold == 0 && squared::sq_count::load == 1 && squared::sq_count::square == 2,
                      "MX_SQ's inputs in the controller's select order");
        ctl_sq.clk(clk); ctl_sq.ctl17(ctl17); ctl_sq.req_s(sync17_req); ctl_sq.z(z); ctl_sq.sel(mx_sq_sel);
        ctl_sq.done(done); ctl_sq.req(ctl_sq_req);
        sync17.clk(clk); sync17.d(ctl_sq_req); sync17.q(sync17_req);
        mx_sq.in[squared::sq_count::hold](brdf);
        mx_sq.in[squared::sq_count::load](q);
        mx_sq.in[squared::sq_count::square](mul_sq_square);
        mx_sq.sel(mx_sq_sel); mx_sq.y(mx_sq_next);
        rg_sq.ctl(clk); rg_sq.d(mx_sq_next); rg_sq.q(brdf);
        mul_sq.a(brdf); mul_sq.b(brdf); mul_sq.p(mul_sq_square);
    }
};

}  // namespace shading
