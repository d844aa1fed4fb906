// The tuned variant of UA 60553 (README, "A better ROM-free a(n)"): the patent's MUL6 and ADD15 on
// the same buses, with node 32 carrying a signed constant (ua60553::tuned_generator, default the
// search's winner ua60553::minimax: a = 0.7890625 n - 0.625), and one special case: n < 2 forces
// a = 0 (an OR gate over n's bits 9..1 opens the key block between ADD15 and MUL10). The patent's
// device, device_ua60553 (ua60553.h), is unchanged; this is a separate top on the shared datapath.
#pragma once

#include <algorithm>
#include <systemc>

#include "formats/ua60553_formats.h"
#include "blocks/key_block.h"
#include "blocks/reduce_or.h"
#include "specular/specular_datapath.h"

namespace shading {

class device_ua60553_tuned
    : public specular_datapath<ua60553::n_fmt.width, ua60553::a_fmt.width, ua60553::a_fmt.frac> {
    using k31_t = sc_dt::sc_uint<ua60553::k_fmt.width>;
    using k32_t = sc_dt::sc_uint<ua60553::k32s_fmt.width>;
    using a_t = sc_dt::sc_uint<ua60553::a_fmt.width>;

    // Node 32's wires: the two's complement of -|K32| on the Q1.7 bus when k32_negative.
    static k32_t node32_bits(const ua60553::tuned_generator& g) {
        const int64_t k = static_cast<int64_t>(bits_from_string(g.k32_bits));
        return k32_t(wrap_bits(g.k32_negative ? -k : k, ua60553::k32s_fmt.width));
    }

public:
    sc_core::sc_signal<k31_t> node31_k{"node31_k"};
    sc_core::sc_signal<k32_t> node32_k{"node32_k"};
    sc_core::sc_signal<sc_dt::sc_uint<ua60553::mul6_fmt.width>> mul6_n_x_k{"mul6_n_x_k"};
    sc_core::sc_signal<a_t> add15_a_linear{"add15_a_linear"};
    sc_core::sc_signal<bool> or_n_ge2{"or_n_ge2"};

    constant<k31_t> node31;
    constant<k32_t> node32;
    mul<ua60553::n_fmt.width, ua60553::k_fmt.width, ua60553::mul6_fmt.width> mul6;  // 10.0 x 0.7 -> 10.7
    adder<ua60553::mul6_fmt.width, ua60553::k32s_fmt.width, ua60553::a_fmt.width, false, true>
        add15;                                                      // 10.7 + 1.7 signed -> 11.7, wraps
    reduce_or<ua60553::n_fmt.width, 1> or_n;                        // n[9:1] != 0, i.e. n >= 2
    key_block<ua60553::a_fmt.width> key_a;                          // a = n >= 2 ? ADD15 : 0

    device_ua60553_tuned(const sc_core::sc_module_name& name, overflow_mode mode = overflow_mode::saturate,
                         const ua60553::tuned_generator& gen = ua60553::minimax, const block_delays& t = {})
        : specular_datapath(name, mode, t, ua60553::n_min, ua60553::n_max,
                            "n = 0 gives a = 0 through the n < 2 special case (q = cos, as for n = 1); "
                            "n > 1000 extends the law a = K31*n + K32"),
          node31("node31", k31_t(bits_from_string(gen.k31_bits))),
          node32("node32", node32_bits(gen)),
          mul6("mul6", t.multiplier),
          add15("add15", overflow_mode::wrap, 0, 0, t.adder),
          or_n("or_n"), key_a("key_a") {
        node31.y(node31_k);
        node32.y(node32_k);
        mul6.a(rg1_n); mul6.b(node31_k); mul6.p(mul6_n_x_k);
        // As in UA 60553, ADD15 shares node 30's logic 0 as its carry input.
        add15.a(mul6_n_x_k); add15.b(node32_k); add15.cin(node30_carry0); add15.s(add15_a_linear);
        or_n.x(rg1_n); or_n.y(or_n_ge2);
        key_a.x(add15_a_linear); key_a.pass(or_n_ge2); key_a.y(a_coef);
    }
};

}  // namespace shading
