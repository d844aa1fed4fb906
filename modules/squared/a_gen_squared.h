// Generator of the squared-quadratic device (ours): from RG1's n, the leading-zero count z (the
// squaring stage does k = 9 - z squarings) and the coefficient a of the quadratic at n' = 1 + f,
//     a = f + f (1 - f - 2^-9) / 2^(k + 2)        (formats/squared_formats.h)
// with n = 2^k (1 + f). No ROM and no constant multiplier: LZC, two barrel shifts by z, an
// inverter bank, one 9 x 9 multiplier and an adder; the rest is wiring.
//   LZC   z = leading zeros of n                           10 wires -> 0..10
//   BSH1  n << z = 1.f (Q1.9); its 9 low wires are f (Q0.9)
//   INV_F ~f = 1 - f - 2^-9
//   MUL_E e = f x ~f (Q0.18, exact)
//   BSH2  e << z on 27 wires, read as Q0.29 = e / 2^(k+2); 17 low wires open -> bend, Q0.12
//   ADD_A a = (f aligned by 3 wires) + bend, Q0.12
#pragma once

#include <systemc>

#include "blocks/adder.h"
#include "blocks/barrel_shifter.h"
#include "blocks/constant.h"
#include "blocks/inverter_bank.h"
#include "blocks/lzc.h"
#include "blocks/mul.h"
#include "blocks/shifter.h"
#include "formats/squared_formats.h"
#include "specular/block_delays.h"

namespace shading {

class a_gen_squared : public sc_core::sc_module {
    static constexpr unsigned WN = squared::n_fmt.width;  // 10
    static constexpr unsigned WZ = squared::z_width;      // 4
    static_assert(lzc<WN>::z_width == WZ, "the LZC's output is the z bus");

public:
    static constexpr qfmt n_fmt = squared::n_fmt;
    static constexpr qfmt a_fmt = squared::a_fmt;

    sc_core::sc_in<sc_dt::sc_uint<WN>> n{"n"};
    sc_core::sc_out<sc_dt::sc_uint<a_fmt.width>> a{"a"};
    sc_core::sc_out<sc_dt::sc_uint<WZ>> z{"z"};

    // Nets, by what they carry.
    sc_core::sc_signal<sc_dt::sc_uint<squared::mant_fmt.width>> bsh1_mant{"bsh1_mant"};
    sc_core::sc_signal<sc_dt::sc_uint<squared::f_fmt.width>> f_frac{"f_frac"};
    sc_core::sc_signal<sc_dt::sc_uint<squared::f_fmt.width>> inv_f_not_f{"inv_f_not_f"};
    sc_core::sc_signal<sc_dt::sc_uint<squared::e_fmt.width>> mul_e_f_x_not_f{"mul_e_f_x_not_f"};
    sc_core::sc_signal<sc_dt::sc_uint<squared::esh_width>> bsh2_e_shifted{"bsh2_e_shifted"};
    sc_core::sc_signal<sc_dt::sc_uint<squared::bend_fmt.width>> bend{"bend"};
    sc_core::sc_signal<sc_dt::sc_uint<a_fmt.width>> f_aligned{"f_aligned"};
    sc_core::sc_signal<bool> add_a_carry0{"add_a_carry0"};

    lzc<WN> lzc_n;
    barrel_shifter<WN, squared::mant_fmt.width, WZ> bsh1;
    shifter<squared::mant_fmt.width, squared::f_fmt.width> f_wires;       // the 9 low wires
    inverter_bank<squared::f_fmt.width> inv_f;
    mul<squared::f_fmt.width, squared::f_fmt.width, squared::e_fmt.width> mul_e;  // 0.9 x 0.9 -> 0.18
    barrel_shifter<squared::e_fmt.width, squared::esh_width, WZ> bsh2;
    shifter<squared::esh_width, squared::bend_fmt.width> bend_wires;      // 17 low wires open
    shifter<squared::f_fmt.width, a_fmt.width> f_align;                    // Q0.9 onto Q0.12
    constant<bool> add_a_cin;
    adder<a_fmt.width, squared::bend_fmt.width, a_fmt.width> add_a;        // 0.12 + 0.12 -> 0.12

    a_gen_squared(const sc_core::sc_module_name& name, const block_delays& t = {})
        : sc_module(name),
          lzc_n("lzc_n", t.mux),
          bsh1("bsh1", WZ * t.mux),
          f_wires("f_wires", 0),
          inv_f("inv_f", t.inverter),
          mul_e("mul_e", t.multiplier),
          bsh2("bsh2", WZ * t.mux),
          bend_wires("bend_wires", -(squared::esh_frac - squared::bend_fmt.frac)),
          f_align("f_align", a_fmt.frac - squared::f_fmt.frac),
          add_a_cin("add_a_cin", false),
          add_a("add_a", overflow_mode::wrap, 0, 0, t.adder) {
        lzc_n.x(n); lzc_n.z(z);
        bsh1.x(n); bsh1.s(z); bsh1.y(bsh1_mant);
        f_wires.x(bsh1_mant); f_wires.y(f_frac);
        inv_f.x(f_frac); inv_f.y(inv_f_not_f);
        mul_e.a(f_frac); mul_e.b(inv_f_not_f); mul_e.p(mul_e_f_x_not_f);
        bsh2.x(mul_e_f_x_not_f); bsh2.s(z); bsh2.y(bsh2_e_shifted);
        bend_wires.x(bsh2_e_shifted); bend_wires.y(bend);
        f_align.x(f_frac); f_align.y(f_aligned);
        add_a_cin.y(add_a_carry0);
        add_a.a(f_aligned); add_a.b(bend); add_a.cin(add_a_carry0); add_a.s(a);
    }
};

}  // namespace shading
