// The squared-quadratic specular device (ours, built from UA 60553's Fig. 1): the patent's datapath
// evaluates the quadratic at the small exponent n' = n / 2^k in [1, 2), a squaring stage squares
// the result k times, and the colour multipliers take it, so the device approximates cos^n with its
// tail (formats/squared_formats.h; the device in modules/squared/README.md, the fit in studies/accuracy/README.md).
//   RG1..RG5     UA 60553's registers, written on the falling edges of strobes 15, 17, 20, 22, 24
//   a_gen        n -> a, z (a_gen_squared.h): LZC, barrel shifts, a 9 x 9 multiplier, an adder
//   MUL7, INV8, node 28, ADD9, MUL10, node 30, ADD11   Fig. 1 at n' (MUL10: Q0.12 a; ADD11: Q1.18)
//   sq           the squaring stage (squaring_stage.h): MX_SQ, RG_SQ, MUL_SQ, its controller and
//                sync17, the synchroniser that brings strobe 17's request into clk's domain
//   MUL12..14    Fig. 1's colour multipliers on RG_SQ's 16 high wires
//   out29        strobe 17 AND the stage's done: output 29 rises when the result is valid
// Pins: UA 60553's, plus `clk`, the squaring stage's clock. The timing (Fig. 3 with a clock): the
// strobe's falling edge latches cos and closes output 29's gate; its request crosses sync17 (two
// rising edges), the third rising edge takes it, and output 29 rises k + 4 rising edges after the
// strobe at the earliest (at strobe 17's rise if that comes later); a platform that waits for
// output 29's rising edge, as Fig. 3 says, needs no other change.
// This class only instantiates and wires; widths from the format table, paths from the elaborated
// design (core/timing_graph.h), read by the monitors.
#pragma once

#include <systemc>

#include "blocks/adder.h"
#include "blocks/and_gate.h"
#include "blocks/constant.h"
#include "blocks/inverter_bank.h"
#include "blocks/mul.h"
#include "blocks/reg.h"
#include "blocks/shifter.h"
#include "core/report_ids.h"
#include "core/timing_graph.h"
#include "formats/specular_formats.h"
#include "formats/squared_formats.h"
#include "monitors/load_checker.h"
#include "monitors/phase_checker.h"
#include "monitors/range_checker.h"
#include "monitors/timing_checker.h"
#include "specular/block_delays.h"
#include "squared/a_gen_squared.h"
#include "squared/squaring_stage.h"

namespace shading {

class squared_device : public sc_core::sc_module {
    static constexpr unsigned WN = squared::n_fmt.width;
    static constexpr unsigned WQ = squared::q_fmt.width;
    using cos_t = sc_dt::sc_uint<spec::cos_fmt.width>;
    using ksi_t = sc_dt::sc_uint<spec::ksi_fmt.width>;
    using out_t = sc_dt::sc_uint<spec::out_fmt.width>;
    using q_t = sc_dt::sc_uint<WQ>;

public:
    // A generator-like face for tops that take a specular unit by its generator of `a`
    // (pipeline/pipe_device.h): the law has no constants to choose, so its config is empty.
    struct config {};
    static config default_config() { return {}; }
    static constexpr qfmt n_fmt = squared::n_fmt;
    static constexpr const char* n_out_of_range =
        "n = 0 is read as n = 1 (the LZC counts 10 zeros: a = 0, no squaring, outputs cos * k_s*I); "
        "n > 1000 extends the law (k = 9, f up to 511/512)";

    // Device pins, numbered as in UA 60553, Fig. 1, and the squaring stage's clock.
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_in<sc_dt::sc_uint<WN>> in16_n{"in16_n"};
    sc_core::sc_in<cos_t> in18_cos{"in18_cos"};
    sc_core::sc_in<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};
    sc_core::sc_out<out_t> out25_r{"out25_r"}, out26_g{"out26_g"}, out27_b{"out27_b"};
    sc_core::sc_out<bool> out29_valid{"out29_valid"};

    // Nets, named by the block that drives them and what they carry.
    sc_core::sc_signal<sc_dt::sc_uint<WN>> rg1_n{"rg1_n"};
    sc_core::sc_signal<cos_t> rg2_cos{"rg2_cos"};
    sc_core::sc_signal<ksi_t> rg3_ksi_r{"rg3_ksi_r"}, rg4_ksi_g{"rg4_ksi_g"}, rg5_ksi_b{"rg5_ksi_b"};
    sc_core::sc_signal<sc_dt::sc_uint<squared::a_fmt.width>> a_coef{"a_coef"};
    sc_core::sc_signal<sc_dt::sc_uint<squared::z_width>> z_lead{"z_lead"};
    sc_core::sc_signal<sc_dt::sc_uint<spec::cos2_fmt.width>> mul7_cos2{"mul7_cos2"};
    sc_core::sc_signal<sc_dt::sc_uint<spec::inv8_fmt.width>> inv8_not_cos{"inv8_not_cos"};
    sc_core::sc_signal<bool> node28_carry1{"node28_carry1"}, node30_carry0{"node30_carry0"};
    sc_core::sc_signal<sc_dt::sc_uint<spec::d_fmt.width>> add9_cos2_minus_cos{"add9_cos2_minus_cos"};
    sc_core::sc_signal<sc_dt::sc_uint<squared::mul10_fmt.width>> mul10_a_x_diff{"mul10_a_x_diff"};
    sc_core::sc_signal<q_t> cos_aligned{"cos_aligned"};
    sc_core::sc_signal<q_t> add11_q{"add11_q"};            // the quadratic at n'
    sc_core::sc_signal<q_t> sq_brdf{"sq_brdf"};            // RG_SQ: after k squares, cos^n
    sc_core::sc_signal<sc_dt::sc_uint<spec::brdf_fmt.width>> brdf_q15{"brdf_q15"};
    sc_core::sc_signal<bool> sq_done{"sq_done"};

    // Blocks of Fig. 1, the generator and the squaring stage.
    reg<WN> rg1;
    reg<spec::cos_fmt.width> rg2;
    reg<spec::ksi_fmt.width> rg3, rg4, rg5;
    a_gen_squared a_gen;
    mul<spec::cos_fmt.width, spec::cos_fmt.width, spec::cos2_fmt.width> mul7;             // Q1.15^2 -> Q2.30
    inverter_bank<spec::cos_fmt.width, spec::inv8_fmt.width, spec::inv8_align> inv8;      // ~(cos << 15)
    constant<bool> node28, node30;
    adder<spec::cos2_fmt.width, spec::inv8_fmt.width, spec::d_fmt.width> add9;           // cos^2 + ~cos + 1
    mul<squared::a_fmt.width, spec::d_fmt.width, squared::mul10_fmt.width, squared::mul10_drop, false, true>
        mul10;                                                                            // 0.12 x 2.30s -> 2.18s
    shifter<spec::cos_fmt.width, WQ> cos_align;                                           // Q1.15 onto Q1.18
    adder<squared::mul10_fmt.width, WQ, WQ, true, false> add11;                           // 2.18s + 1.18 -> 1.18
    squaring_stage sq;
    shifter<WQ, spec::brdf_fmt.width> brdf_wires;                                         // 16 high wires
    mul<spec::brdf_fmt.width, spec::ksi_fmt.width, spec::out_fmt.width, spec::out_drop> mul12, mul13, mul14;
    and_gate out29;

    // Assertion monitors (not hardware).
    range_checker<WN> chk_in16_n;
    range_checker<spec::cos_fmt.width> chk_in18_cos;
    timing_checker chk_timing;           // strobes 20, 22, 24 -> outputs, at output 29's rise
    load_checker<2> chk_load;            // strobes 15, 17 -> RG_SQ.d, at each LOAD
    phase_checker chk_clk;               // the squaring stage's clock phases

    explicit squared_device(const sc_core::sc_module_name& name, overflow_mode mode = overflow_mode::saturate,
                            const block_delays& t = {})
        : sc_module(name),
          rg1("rg1", t.reg), rg2("rg2", t.reg), rg3("rg3", t.reg), rg4("rg4", t.reg), rg5("rg5", t.reg),
          a_gen("a_gen", t),
          mul7("mul7", t.multiplier), inv8("inv8", t.inverter),
          node28("node28", true), node30("node30", false),
          add9("add9", overflow_mode::wrap, 0, 0, t.adder),
          mul10("mul10", t.multiplier),
          cos_align("cos_align", squared::cos_align),
          add11("add11", mode, squared::q_sat_lo, squared::q_sat_hi, t.adder),
          sq("sq", t),
          brdf_wires("brdf_wires", -static_cast<int>(squared::sq_to_brdf_drop)),
          mul12("mul12", t.multiplier), mul13("mul13", t.multiplier), mul14("mul14", t.multiplier),
          out29("out29", t.gate),
          chk_in16_n("chk_in16_n", squared::n_min, squared::n_max, n_out_of_range),
          chk_in18_cos("chk_in18_cos", 0, spec::cos_one,
                       mode == overflow_mode::saturate
                           ? "cos > 1.0: ADD11 saturates the quadratic to 1.0 (outputs = k_s*I)"
                           : "cos > 1.0: wrap mode passes ADD11's and the squarer's low wires on unchanged"),
          chk_timing("chk_timing", 3, {&rg1, &rg2, &sq.rg_sq, &sq.ctl_sq, &sq.sync17}),
          chk_load("chk_load", 2, sq.rg_sq, squared::sq_count::load),
          chk_clk("chk_clk") {
        if (t.reg + t.multiplier + t.mux == sc_core::SC_ZERO_TIME)
            SC_REPORT_ERROR(msg::config, (std::string(this->name()) +
                                          ": the squaring loop RG_SQ -> MUL_SQ -> MX_SQ -> RG_SQ needs a delay: "
                                          "with none, RG_SQ's own square reaches its input at the latching edge")
                                             .c_str());
        rg1.ctl(ctl15); rg1.d(in16_n); rg1.q(rg1_n);
        rg2.ctl(ctl17); rg2.d(in18_cos); rg2.q(rg2_cos);
        rg3.ctl(ctl20); rg3.d(in19_ksi_r); rg3.q(rg3_ksi_r);
        rg4.ctl(ctl22); rg4.d(in21_ksi_g); rg4.q(rg4_ksi_g);
        rg5.ctl(ctl24); rg5.d(in23_ksi_b); rg5.q(rg5_ksi_b);

        a_gen.n(rg1_n); a_gen.a(a_coef); a_gen.z(z_lead);
        mul7.a(rg2_cos); mul7.b(rg2_cos); mul7.p(mul7_cos2);
        inv8.x(rg2_cos); inv8.y(inv8_not_cos);
        node28.y(node28_carry1);
        add9.a(mul7_cos2); add9.b(inv8_not_cos); add9.cin(node28_carry1); add9.s(add9_cos2_minus_cos);
        mul10.a(a_coef); mul10.b(add9_cos2_minus_cos); mul10.p(mul10_a_x_diff);
        cos_align.x(rg2_cos); cos_align.y(cos_aligned);
        node30.y(node30_carry0);
        add11.a(mul10_a_x_diff); add11.b(cos_aligned); add11.cin(node30_carry0); add11.s(add11_q);
        sq.clk(clk); sq.ctl17(ctl17); sq.z(z_lead); sq.q(add11_q); sq.brdf(sq_brdf); sq.done(sq_done);
        brdf_wires.x(sq_brdf); brdf_wires.y(brdf_q15);
        mul12.a(brdf_q15); mul12.b(rg3_ksi_r); mul12.p(out25_r);
        mul13.a(brdf_q15); mul13.b(rg4_ksi_g); mul13.p(out26_g);
        mul14.a(brdf_q15); mul14.b(rg5_ksi_b); mul14.p(out27_b);
        out29.a(ctl17); out29.b(sq_done); out29.y(out29_valid);

        chk_in16_n.ctl(ctl15); chk_in16_n.d(in16_n);
        chk_in18_cos.ctl(ctl17); chk_in18_cos.d(in18_cos);
        chk_timing.ctl[0](ctl20); chk_timing.ctl[1](ctl22); chk_timing.ctl[2](ctl24);
        chk_timing.valid(out29_valid);
        chk_load.clk(clk); chk_load.sel(sq.mx_sq_sel); chk_load.ctl[0](ctl15); chk_load.ctl[1](ctl17);
        chk_clk.clk(clk);
    }

    // The constructor of specular_device<AGen> (name, mode, generator config, delays).
    squared_device(const sc_core::sc_module_name& name, overflow_mode mode, const config&, const block_delays& t)
        : squared_device(name, mode, t) {}

    // Derived paths (valid from end of elaboration): RG1's and RG2's into RG_SQ (checked at each
    // load), and the clock's phase requirements (the squaring loop, RG_SQ to the outputs).
    const timing_path& rg1_to_load() const { return chk_load.path(0); }
    const timing_path& rg2_to_load() const { return chk_load.path(1); }
    const sc_core::sc_time& min_high() const { return chk_clk.min_high(); }
    const sc_core::sc_time& min_low() const { return chk_clk.min_low(); }
    const squaring_stage& stage() const { return sq; }

private:
    void end_of_elaboration() override {
        const timing_graph g(*this);
        const auto d_sq = g.d_of(sq.rg_sq);
        chk_clk.require(g.longest_from_registers({&sq.ctl_sq}, {d_sq}), g.longest_from_registers({&sq.rg_sq}, g.outputs()),
                        g.longest_from_registers({&sq.rg_sq}, {d_sq}), sq.rg_sq.setup_time());
    }
};

}  // namespace shading
