// The tuned generator of `a` (modules/tuned/README.md, "A better ROM-free a(n)"): the patent's MUL6 and ADD15 on
// the same buses, with node 32 carrying a signed constant (ua60553::tuned_generator, default the
// search's winner ua60553::minimax: a = 0.7890625 n - 0.625), and one special case: n < 2 forces
// a = 0 (an OR gate over n's bits 9..1 opens the key block between ADD15 and MUL10). A unit with
// the n -> a interface every specular device binds (specular/specular_device.h).
#pragma once

#include <algorithm>
#include <cstdint>
#include <systemc>

#include "arith/ua60553_tuned_arith.h"
#include "blocks/adder.h"
#include "blocks/constant.h"
#include "blocks/key_block.h"
#include "blocks/mul.h"
#include "blocks/reduce_or.h"
#include "formats/ua60553_formats.h"
#include "specular/block_delays.h"

namespace shading {

class a_gen_tuned : public sc_core::sc_module {
    using k31_t = sc_dt::sc_uint<ua60553::k_fmt.width>;
    using k32_t = sc_dt::sc_uint<ua60553::k32s_fmt.width>;

    // Node 32's wires: the two's complement of -|K32| on the Q1.7 bus when k32_negative.
    static k32_t node32_bits(const ua60553::tuned_generator& g) {
        const int64_t k = static_cast<int64_t>(bits_from_string(g.k32_bits));
        return k32_t(wrap_bits(g.k32_negative ? -k : k, ua60553::k32s_fmt.width));
    }

public:
    using config = ua60553::tuned_generator;
    static config default_config() { return ua60553::minimax; }
    static constexpr qfmt n_fmt = ua60553::n_fmt;
    static constexpr qfmt a_fmt = ua60553::a_fmt;
    static constexpr const char* n_out_of_range =
        "n = 0 gives a = 0 through the n < 2 special case (q = cos, as for n = 1); n > 1000 extends "
        "the law a = K31*n + K32";

    // For the fast pin-level model (specular/specular_fast.h): the unit's function, from the golden
    // model, and its n -> a delay (MUL6, ADD15 beside OR, then the key block).
    static uint64_t a_word(const config& g, uint64_t n_bits) { return golden_a_tuned(n_bits, g); }
    static sc_core::sc_time path_delay(const block_delays& t) {
        return std::max(t.multiplier + t.adder, t.gate) + t.gate;
    }

    sc_core::sc_in<sc_dt::sc_uint<n_fmt.width>> n{"n"};
    sc_core::sc_out<sc_dt::sc_uint<a_fmt.width>> a{"a"};

    sc_core::sc_signal<k31_t> node31_k{"node31_k"};
    sc_core::sc_signal<k32_t> node32_k{"node32_k"};
    sc_core::sc_signal<sc_dt::sc_uint<ua60553::mul6_fmt.width>> mul6_n_x_k{"mul6_n_x_k"};
    sc_core::sc_signal<sc_dt::sc_uint<a_fmt.width>> add15_a_linear{"add15_a_linear"};
    sc_core::sc_signal<bool> add15_carry0{"add15_carry0"}, or_n_ge2{"or_n_ge2"};

    constant<k31_t> node31;
    constant<k32_t> node32;
    constant<bool> add15_cin;  // ADD15's carry: none in the patent; this unit's own logic 0
    mul<n_fmt.width, ua60553::k_fmt.width, ua60553::mul6_fmt.width> mul6;   // 10.0 x 0.7 -> 10.7
    adder<ua60553::mul6_fmt.width, ua60553::k32s_fmt.width, a_fmt.width, false, true>
        add15;                                                          // 10.7 + 1.7 signed -> 11.7, wraps
    reduce_or<n_fmt.width, ua60553::tuned_or_lo> or_n;                  // n[9:1] != 0, i.e. n >= 2
    key_block<a_fmt.width> key_a;                                       // a = n >= 2 ? ADD15 : 0

    a_gen_tuned(const sc_core::sc_module_name& name, const config& gen = default_config(),
                const block_delays& t = {})
        : sc_module(name),
          node31("node31", k31_t(bits_from_string(gen.k31_bits))),
          node32("node32", node32_bits(gen)),
          add15_cin("add15_cin", false),
          mul6("mul6", t.multiplier),
          add15("add15", overflow_mode::wrap, 0, 0, t.adder),
          or_n("or_n", t.gate), key_a("key_a", t.gate) {
        node31.y(node31_k);
        node32.y(node32_k);
        add15_cin.y(add15_carry0);
        mul6.a(n); mul6.b(node31_k); mul6.p(mul6_n_x_k);
        add15.a(mul6_n_x_k); add15.b(node32_k); add15.cin(add15_carry0); add15.s(add15_a_linear);
        or_n.x(n); or_n.y(or_n_ge2);
        key_a.x(add15_a_linear); key_a.pass(or_n_ge2); key_a.y(a);
    }
};

}  // namespace shading
