// The square-and-multiply specular device (ours; RTL twin rtl/sqmul/sqmul_device.v, instance for
// instance): cos^n over the bits of n with one Q1.18 multiplier, on the squared-quadratic device's
// pins (UA 60553's plus clk) and handshake (formats/sqmul_formats.h; the device in
// modules/sqmul/README.md).
//   RG1..RG5     UA 60553's registers, written on the falling edges of strobes 15, 17, 20, 22, 24
//   lzc_n, bsh1  z = leading zeros of n, n << z: its 9 low wires f (f_wires) are the bits to walk
//   cos_align    RG2's Q1.15 onto Q1.18;  sat_cos: clamped to 1.0 (saturate mode) or not (wrap)
//   stage        MX_B, MUL_P, MX_P, RG_P, the controller (sqmul_stage.h, sqmul_ctrl.h) and sync17,
//                the synchroniser that brings strobe 17's request into clk's domain
//   MUL12..14    UA 60553's colour multipliers on RG_P's 16 high wires
//   out29        strobe 17 AND the stage's done: output 29 rises when the result is valid
// Pins: UA 60553's, plus `clk`, the stage's clock. The timing: the strobe's falling edge latches
// cos and closes output 29's gate; its request crosses sync17 (two rising edges), the third rising
// edge takes it, and output 29 rises floor(log2 n) + popcount(n) + 3 rising edges after the strobe
// at the earliest, or at strobe 17's rise if that comes later; a platform that waits for output
// 29's rising edge, as Fig. 3 says, needs no other change.
// This class only instantiates and wires; widths from the format table, paths from the elaborated
// design (core/timing_graph.h), read by the monitors.
#pragma once

#include <string>
#include <systemc>

#include "blocks/and_gate.h"
#include "blocks/barrel_shifter.h"
#include "blocks/lzc.h"
#include "blocks/mul.h"
#include "blocks/reg.h"
#include "blocks/saturator.h"
#include "blocks/shifter.h"
#include "core/report_ids.h"
#include "core/timing_graph.h"
#include "formats/specular_formats.h"
#include "formats/sqmul_formats.h"
#include "monitors/load_checker.h"
#include "monitors/phase_checker.h"
#include "monitors/range_checker.h"
#include "monitors/timing_checker.h"
#include "specular/block_delays.h"
#include "sqmul/sqmul_stage.h"

namespace shading {

class sqmul_device : public sc_core::sc_module {
    static constexpr unsigned WN = sqmul::n_fmt.width;
    static constexpr unsigned WZ = sqmul::z_width;
    static constexpr unsigned WP = sqmul::p_fmt.width;
    static_assert(lzc<WN>::z_width == WZ, "the LZC's output is the z bus");
    using cos_t = sc_dt::sc_uint<spec::cos_fmt.width>;
    using ksi_t = sc_dt::sc_uint<spec::ksi_fmt.width>;
    using out_t = sc_dt::sc_uint<spec::out_fmt.width>;
    using p_t = sc_dt::sc_uint<WP>;

public:
    // A generator-like face for tops that take a specular unit by its generator of `a`
    // (pipeline/pipe_device.h): the device has no constants to choose, so its config is empty.
    struct config {};
    static config default_config() { return {}; }
    static constexpr qfmt n_fmt = sqmul::n_fmt;
    static constexpr const char* n_out_of_range =
        "n = 0 is read as n = 1 (the LZC counts 10 zeros: no square, outputs cos * k_s*I); "
        "n > 1000 is walked as any other n (up to 9 squares and 9 multiplications)";
    static constexpr const char* cos_out_of_range_saturate = "cos > 1.0: the loaded cos is clamped to 1.0 (outputs = k_s*I)";
    static constexpr const char* cos_out_of_range_wrap =
        "cos > 1.0: wrap mode loads it as it is and every product keeps its 19 low wires";

    // Device pins, numbered as in UA 60553, Fig. 1, and the stage's clock.
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_in<sc_dt::sc_uint<WN>> in16_n{"in16_n"};
    sc_core::sc_in<cos_t> in18_cos{"in18_cos"};
    sc_core::sc_in<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};
    sc_core::sc_out<out_t> out25_r{"out25_r"}, out26_g{"out26_g"}, out27_b{"out27_b"};
    sc_core::sc_out<bool> out29_valid{"out29_valid"};

    // Nets, named by the block that drives them and what they carry (as in sqmul_device.v).
    sc_core::sc_signal<sc_dt::sc_uint<WN>> rg1_n{"rg1_n"};
    sc_core::sc_signal<cos_t> rg2_cos{"rg2_cos"};
    sc_core::sc_signal<ksi_t> rg3_ksi_r{"rg3_ksi_r"}, rg4_ksi_g{"rg4_ksi_g"}, rg5_ksi_b{"rg5_ksi_b"};
    sc_core::sc_signal<sc_dt::sc_uint<WZ>> z_lead{"z_lead"};
    sc_core::sc_signal<sc_dt::sc_uint<sqmul::mant_fmt.width>> bsh1_mant{"bsh1_mant"};
    sc_core::sc_signal<sc_dt::sc_uint<sqmul::f_fmt.width>> f_frac{"f_frac"};
    sc_core::sc_signal<p_t> cos_aligned{"cos_aligned"};
    sc_core::sc_signal<p_t> cos_p{"cos_p"};
    sc_core::sc_signal<p_t> p_brdf{"p_brdf"};  // RG_P: cos^n
    sc_core::sc_signal<sc_dt::sc_uint<spec::brdf_fmt.width>> brdf_q15{"brdf_q15"};
    sc_core::sc_signal<bool> p_done{"p_done"};

    reg<WN> rg1;
    reg<spec::cos_fmt.width> rg2;
    reg<spec::ksi_fmt.width> rg3, rg4, rg5;
    lzc<WN> lzc_n;
    barrel_shifter<WN, sqmul::mant_fmt.width, WZ> bsh1;
    shifter<sqmul::mant_fmt.width, sqmul::f_fmt.width> f_wires;  // the 9 low wires
    shifter<spec::cos_fmt.width, WP> cos_align;                    // Q1.15 onto Q1.18
    saturator<WP> sat_cos;
    sqmul_stage stage;
    shifter<WP, spec::brdf_fmt.width> brdf_wires;                  // 16 high wires
    mul<spec::brdf_fmt.width, spec::ksi_fmt.width, spec::out_fmt.width, spec::out_drop> mul12, mul13, mul14;
    and_gate out29;

    // Assertion monitors (not hardware).
    range_checker<WN> chk_in16_n;
    range_checker<spec::cos_fmt.width> chk_in18_cos;
    timing_checker chk_timing;  // strobes 20, 22, 24 -> outputs, at output 29's rise
    load_checker<2> chk_load;   // at each LOAD: strobe 15 -> the controller's z, f; strobe 17 -> RG_P.d
    phase_checker chk_clk;      // the stage's clock phases

    explicit sqmul_device(const sc_core::sc_module_name& name, overflow_mode mode = overflow_mode::saturate,
                          const block_delays& t = {})
        : sc_module(name),
          rg1("rg1", t.reg), rg2("rg2", t.reg), rg3("rg3", t.reg), rg4("rg4", t.reg), rg5("rg5", t.reg),
          lzc_n("lzc_n", t.mux), bsh1("bsh1", WZ * t.mux), f_wires("f_wires", 0),
          cos_align("cos_align", sqmul::cos_align), sat_cos("sat_cos", mode, sqmul::p_one, t.adder),
          stage("stage", t),
          brdf_wires("brdf_wires", -static_cast<int>(sqmul::p_to_brdf_drop)),
          mul12("mul12", t.multiplier), mul13("mul13", t.multiplier), mul14("mul14", t.multiplier),
          out29("out29", t.gate),
          chk_in16_n("chk_in16_n", sqmul::n_min, sqmul::n_max, n_out_of_range),
          chk_in18_cos("chk_in18_cos", 0, spec::cos_one,
                       mode == overflow_mode::saturate ? cos_out_of_range_saturate : cos_out_of_range_wrap),
          chk_timing("chk_timing", 3, {&rg1, &rg2, &stage.rg_p, &stage.ctl, &stage.sync17}),
          chk_load("chk_load", 2, stage.rg_p, sqmul::p_load),
          chk_clk("chk_clk") {
        if (t.reg + t.multiplier + t.mux == sc_core::SC_ZERO_TIME)
            SC_REPORT_ERROR(msg::config, (std::string(this->name()) +
                                          ": the loop RG_P -> MUL_P -> MX_P -> RG_P needs a delay: "
                                          "with none, RG_P's own product reaches its input at the latching edge")
                                             .c_str());
        rg1.ctl(ctl15); rg1.d(in16_n); rg1.q(rg1_n);
        rg2.ctl(ctl17); rg2.d(in18_cos); rg2.q(rg2_cos);
        rg3.ctl(ctl20); rg3.d(in19_ksi_r); rg3.q(rg3_ksi_r);
        rg4.ctl(ctl22); rg4.d(in21_ksi_g); rg4.q(rg4_ksi_g);
        rg5.ctl(ctl24); rg5.d(in23_ksi_b); rg5.q(rg5_ksi_b);

        lzc_n.x(rg1_n); lzc_n.z(z_lead);
        bsh1.x(rg1_n); bsh1.s(z_lead); bsh1.y(bsh1_mant);
        f_wires.x(bsh1_mant); f_wires.y(f_frac);
        cos_align.x(rg2_cos); cos_align.y(cos_aligned);
        sat_cos.x(cos_aligned); sat_cos.y(cos_p);
        stage.clk(clk); stage.ctl17(ctl17); stage.z(z_lead); stage.f(f_frac); stage.c(cos_p);
        stage.brdf(p_brdf); stage.done(p_done);
        brdf_wires.x(p_brdf); brdf_wires.y(brdf_q15);
        mul12.a(brdf_q15); mul12.b(rg3_ksi_r); mul12.p(out25_r);
        mul13.a(brdf_q15); mul13.b(rg4_ksi_g); mul13.p(out26_g);
        mul14.a(brdf_q15); mul14.b(rg5_ksi_b); mul14.p(out27_b);
        out29.a(ctl17); out29.b(p_done); out29.y(out29_valid);

        chk_in16_n.ctl(ctl15); chk_in16_n.d(in16_n);
        chk_in18_cos.ctl(ctl17); chk_in18_cos.d(in18_cos);
        chk_timing.ctl[0](ctl20); chk_timing.ctl[1](ctl22); chk_timing.ctl[2](ctl24);
        chk_timing.valid(out29_valid);
        chk_load.clk(clk); chk_load.sel(stage.mx_p_sel); chk_load.ctl[0](ctl15); chk_load.ctl[1](ctl17);
        chk_load.sampled_by(0, stage.ctl, {&stage.ctl.z, &stage.ctl.f});
        chk_clk.clk(clk);
    }

    // The constructor of specular_device<AGen> (name, mode, generator config, delays).
    sqmul_device(const sc_core::sc_module_name& name, overflow_mode mode, const config&, const block_delays& t)
        : sqmul_device(name, mode, t) {}

    // Derived paths (valid from end of elaboration): RG1's into the controller (checked against
    // the edge that takes each LOAD), RG2's into RG_P (checked at each LOAD; the longest, through
    // MX_B and MUL_P, is a multiplication's, which follows the LOAD), and the clock's phase
    // requirements (the controller's selects through MUL_P, the loop, RG_P to the outputs).
    const timing_path& rg1_to_ctrl() const { return chk_load.path(0); }
    const timing_path& rg2_to_load() const { return chk_load.path(1); }
    const sc_core::sc_time& min_high() const { return chk_clk.min_high(); }
    const sc_core::sc_time& min_low() const { return chk_clk.min_low(); }

private:
    void end_of_elaboration() override {
        const timing_graph g(*this);
        const auto d_p = g.d_of(stage.rg_p);
        chk_clk.require(g.longest_from_registers({&stage.ctl}, {d_p}), g.longest_from_registers({&stage.rg_p}, g.outputs()),
                        g.longest_from_registers({&stage.rg_p}, {d_p}), stage.rg_p.setup_time());
    }
};

}  // namespace shading
