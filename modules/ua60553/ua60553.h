// UA 60553 (Fig. 1): the shared specular datapath plus the ROM-free generator of `a`,
// a = n * K31 + K32 (formula 10): MUL6 with the hardwired constant at node 31 and ADD15 with the
// hardwired constant at node 32. The constants come from a shading::ua60553::linear_generator;
// the default is the patent's 0.1100101b and 0.1b.
#pragma once

#include <systemc>

#include "formats/ua60553_formats.h"
#include "specular/specular_datapath.h"

namespace shading {

class device_ua60553
    : public specular_datapath<ua60553::n_fmt.width, ua60553::a_fmt.width, ua60553::a_fmt.frac> {
    using k_t = sc_dt::sc_uint<ua60553::k_fmt.width>;

public:
    sc_core::sc_signal<k_t> node31_k{"node31_k"}, node32_k{"node32_k"};
    sc_core::sc_signal<sc_dt::sc_uint<ua60553::mul6_fmt.width>> mul6_n_x_k{"mul6_n_x_k"};

    constant<k_t> node31, node32;
    mul<ua60553::n_fmt.width, ua60553::k_fmt.width, ua60553::mul6_fmt.width> mul6;  // 10.0 x 0.7 -> 10.7
    adder<ua60553::mul6_fmt.width, ua60553::k_fmt.width, ua60553::a_fmt.width> add15;  // 10.7 + 0.7 -> 11.7

    device_ua60553(const sc_core::sc_module_name& name, overflow_mode mode = overflow_mode::saturate,
            const ua60553::linear_generator& gen = ua60553::patent, const block_delays& t = {})
        : specular_datapath(name, mode, t, ua60553::n_min, ua60553::n_max,
                            "n = 0 gives a = K32 (0.5 with the patent's constants); n > 1000 extends "
                            "the linear law a = K31*n + K32"),
          node31("node31", k_t(bits_from_string(gen.k31_bits))),
          node32("node32", k_t(bits_from_string(gen.k32_bits))),
          mul6("mul6", t.multiplier),
          add15("add15", overflow_mode::wrap, 0, 0, t.adder) {
        node31.y(node31_k);
        node32.y(node32_k);
        mul6.a(rg1_n); mul6.b(node31_k); mul6.p(mul6_n_x_k);
        // The patent names no carry input for ADD15: it shares node 30's logic 0.
        add15.a(mul6_n_x_k); add15.b(node32_k); add15.cin(node30_carry0); add15.s(a_coef);
    }
};

}  // namespace shading
