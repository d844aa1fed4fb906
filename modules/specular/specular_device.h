// A specular-colour device of UA 60553, Fig. 1, built by composition: the datapath the patent
// shares with its prototype UA 22802 (registers 1-5, the squaring multiplier 7, inverter bank 8,
// subtracting adder 9 with carry node 28 = 1, the a-multiplier 10, adder 11 with carry node
// 30 = 0, the colour multipliers 12-14, the wire from strobe 17 to output 29) and one generator
// of `a`, a unit AGen with the interface n (RG1's output) -> a (MUL10's operand):
//   a_gen_linear (ua60553/)  UA 60553: MUL6 + ADD15, formula 10      -> device_ua60553
//   a_gen_rom    (ua22802/)  UA 22802: a ROM holding a(n)            -> device_ua22802
//   a_gen_tuned  (tuned/)    the tuned line: MUL6 + ADD15 + OR + key -> device_ua60553_tuned
// AGen provides n_fmt and a_fmt (its bus formats), a `config` with default_config(), and the
// note the range checker prints for n outside 1..1000. This class only instantiates and wires;
// every width comes from the format tables (src/floor/formats), every path from the elaborated design
// (core/timing_graph.h, read by the timing checker).
#pragma once

#include <systemc>

#include "blocks/adder.h"
#include "blocks/constant.h"
#include "blocks/inverter_bank.h"
#include "blocks/mul.h"
#include "blocks/reg.h"
#include "blocks/wire.h"
#include "formats/specular_formats.h"
#include "formats/ua60553_formats.h"
#include "monitors/range_checker.h"
#include "monitors/timing_checker.h"
#include "specular/block_delays.h"

namespace shading {

template <class AGen>
class specular_device : public sc_core::sc_module {
    static constexpr unsigned WN = AGen::n_fmt.width;
    static constexpr unsigned WA = AGen::a_fmt.width;
    using cos_t = sc_dt::sc_uint<spec::cos_fmt.width>;
    using ksi_t = sc_dt::sc_uint<spec::ksi_fmt.width>;
    using out_t = sc_dt::sc_uint<spec::out_fmt.width>;

public:
    using generator = AGen;

    // Device pins, numbered as in UA 60553, Fig. 1.
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
    sc_core::sc_signal<sc_dt::sc_uint<WA>> a_coef{"a_coef"};
    sc_core::sc_signal<sc_dt::sc_uint<spec::cos2_fmt.width>> mul7_cos2{"mul7_cos2"};
    sc_core::sc_signal<sc_dt::sc_uint<spec::inv8_fmt.width>> inv8_not_cos{"inv8_not_cos"};
    sc_core::sc_signal<bool> node28_carry1{"node28_carry1"}, node30_carry0{"node30_carry0"};
    sc_core::sc_signal<sc_dt::sc_uint<spec::d_fmt.width>> add9_cos2_minus_cos{"add9_cos2_minus_cos"};
    sc_core::sc_signal<sc_dt::sc_uint<spec::mul10_fmt.width>> mul10_a_x_diff{"mul10_a_x_diff"};
    sc_core::sc_signal<sc_dt::sc_uint<spec::brdf_fmt.width>> add11_brdf{"add11_brdf"};

    // Blocks of Fig. 1.
    reg<WN> rg1;
    reg<spec::cos_fmt.width> rg2;
    reg<spec::ksi_fmt.width> rg3, rg4, rg5;
    AGen a_gen;                                                        // n -> a
    mul<spec::cos_fmt.width, spec::cos_fmt.width, spec::cos2_fmt.width> mul7;  // Q1.15^2 -> Q2.30
    inverter_bank<spec::cos_fmt.width, spec::inv8_fmt.width, spec::inv8_align> inv8;  // ~(cos << 15)
    constant<bool> node28, node30;
    adder<spec::cos2_fmt.width, spec::inv8_fmt.width, spec::d_fmt.width> add9;  // cos^2 + ~cos + 1
    mul<WA, spec::d_fmt.width, spec::mul10_fmt.width, spec::mul10_drop(AGen::a_fmt.frac), false, true>
        mul10;                                                         // a x Q2.30s -> Q12.15s floor
    adder<spec::mul10_fmt.width, spec::cos_fmt.width, spec::brdf_fmt.width, true, false>
        add11;                                                         // Q12.15s + Q1.15 -> Q1.15
    mul<spec::brdf_fmt.width, spec::ksi_fmt.width, spec::out_fmt.width, spec::out_drop> mul12, mul13,
        mul14;                                                         // Q1.15 x 8.0 -> Q9.8 floor
    wire<bool> out29;  // Fig. 3: output 29 is RG2's write strobe itself

    // Assertion monitors (not hardware): input ranges and strobe timing.
    range_checker<WN> chk_in16_n;
    range_checker<spec::cos_fmt.width> chk_in18_cos;
    timing_checker chk_timing;

    explicit specular_device(const sc_core::sc_module_name& name, overflow_mode mode = overflow_mode::saturate,
                             const typename AGen::config& gen = AGen::default_config(),
                             const block_delays& t = {})
        : sc_module(name),
          rg1("rg1", t.reg), rg2("rg2", t.reg), rg3("rg3", t.reg), rg4("rg4", t.reg), rg5("rg5", t.reg),
          a_gen("a_gen", gen, t),
          mul7("mul7", t.multiplier), inv8("inv8", t.inverter),
          node28("node28", true), node30("node30", false),
          add9("add9", overflow_mode::wrap, 0, 0, t.adder),
          mul10("mul10", t.multiplier),
          add11("add11", mode, spec::brdf_sat_lo, spec::brdf_sat_hi, t.adder),
          mul12("mul12", t.multiplier), mul13("mul13", t.multiplier), mul14("mul14", t.multiplier),
          out29("out29"),
          chk_in16_n("chk_in16_n", ua60553::n_min, ua60553::n_max, AGen::n_out_of_range),
          chk_in18_cos("chk_in18_cos", 0, spec::cos_one,
                       mode == overflow_mode::saturate
                           ? "cos > 1.0: ADD11 saturates the BRDF to 1.0 (outputs = k_s*I)"
                           : "cos > 1.0: wrap mode passes the overflowed BRDF bits on unchanged"),
          chk_timing("chk_timing", 5) {
        rg1.ctl(ctl15); rg1.d(in16_n); rg1.q(rg1_n);
        rg2.ctl(ctl17); rg2.d(in18_cos); rg2.q(rg2_cos);
        rg3.ctl(ctl20); rg3.d(in19_ksi_r); rg3.q(rg3_ksi_r);
        rg4.ctl(ctl22); rg4.d(in21_ksi_g); rg4.q(rg4_ksi_g);
        rg5.ctl(ctl24); rg5.d(in23_ksi_b); rg5.q(rg5_ksi_b);

        a_gen.n(rg1_n); a_gen.a(a_coef);
        mul7.a(rg2_cos); mul7.b(rg2_cos); mul7.p(mul7_cos2);
        inv8.x(rg2_cos); inv8.y(inv8_not_cos);
        node28.y(node28_carry1);
        add9.a(mul7_cos2); add9.b(inv8_not_cos); add9.cin(node28_carry1); add9.s(add9_cos2_minus_cos);
        mul10.a(a_coef); mul10.b(add9_cos2_minus_cos); mul10.p(mul10_a_x_diff);
        node30.y(node30_carry0);
        add11.a(mul10_a_x_diff); add11.b(rg2_cos); add11.cin(node30_carry0); add11.s(add11_brdf);
        mul12.a(add11_brdf); mul12.b(rg3_ksi_r); mul12.p(out25_r);
        mul13.a(add11_brdf); mul13.b(rg4_ksi_g); mul13.p(out26_g);
        mul14.a(add11_brdf); mul14.b(rg5_ksi_b); mul14.p(out27_b);
        out29.x(ctl17); out29.y(out29_valid);

        chk_in16_n.ctl(ctl15); chk_in16_n.d(in16_n);
        chk_in18_cos.ctl(ctl17); chk_in18_cos.d(in18_cos);
        // Strobe i latches RG(i+1); the checker derives each strobe's path at end of elaboration.
        sc_core::sc_in<bool>* strobes[] = {&ctl15, &ctl17, &ctl20, &ctl22, &ctl24};
        for (std::size_t i = 0; i < 5; ++i) chk_timing.ctl[i](*strobes[i]);
        chk_timing.valid(ctl17);
    }

    // Derived paths (valid from end of elaboration): RG1 through the generator of `a`, and RG2's,
    // the critical path of Fig. 3.
    const sc_core::sc_time& rg1_to_outputs() const { return chk_timing.path(0); }
    const sc_core::sc_time& rg2_to_outputs() const { return chk_timing.path(1); }
};

}  // namespace shading
