// UA 60553's ROM-free generator of `a` (Fig. 1, formula 10): a = n * K31 + K32, MUL6 with the
// hardwired constant at node 31 and ADD15 with the hardwired constant at node 32. The constants
// come from a ua60553::linear_generator (default the patent's 0.1100101b and 0.1b). A unit with
// the n -> a interface every specular device binds (specular/specular_device.h).
#pragma once

#include <systemc>

#include "arith/specular_arith.h"
#include "blocks/adder.h"
#include "blocks/constant.h"
#include "blocks/mul.h"
#include "formats/ua60553_formats.h"
#include "specular/block_delays.h"

namespace shading {

class a_gen_linear : public sc_core::sc_module {
    using k_t = sc_dt::sc_uint<ua60553::k_fmt.width>;

public:
    using config = ua60553::linear_generator;
    static config default_config() { return ua60553::patent; }
    static constexpr qfmt n_fmt = ua60553::n_fmt;
    static constexpr qfmt a_fmt = ua60553::a_fmt;
    static constexpr const char* n_out_of_range =
        "n = 0 gives a = K32 (0.5 with the patent's constants); n > 1000 extends the linear law "
        "a = K31*n + K32";

    // For the fast pin-level model (specular/specular_fast.h): the unit's function, from the golden
    // model, and its n -> a delay (MUL6 then ADD15; core/timing_graph.h derives the same from the wiring).
    static uint64_t a_word(const config& g, uint64_t n_bits) { return golden_a_linear(n_bits, g); }
    static sc_core::sc_time path_delay(const block_delays& t) { return t.multiplier + t.adder; }

    sc_core::sc_in<sc_dt::sc_uint<n_fmt.width>> n{"n"};
    sc_core::sc_out<sc_dt::sc_uint<a_fmt.width>> a{"a"};

    sc_core::sc_signal<k_t> node31_k{"node31_k"}, node32_k{"node32_k"};
    sc_core::sc_signal<sc_dt::sc_uint<ua60553::mul6_fmt.width>> mul6_n_x_k{"mul6_n_x_k"};
    sc_core::sc_signal<bool> add15_carry0{"add15_carry0"};

    constant<k_t> node31, node32;
    // The patent names no carry input for ADD15 (an earlier model borrowed node 30's 0): the unit
    // ties its own to 0, so it does not reach into the datapath.
    constant<bool> add15_cin;
    mul<n_fmt.width, ua60553::k_fmt.width, ua60553::mul6_fmt.width> mul6;        // 10.0 x 0.7 -> 10.7
    adder<ua60553::mul6_fmt.width, ua60553::k_fmt.width, a_fmt.width> add15;     // 10.7 + 0.7 -> 11.7

    a_gen_linear(const sc_core::sc_module_name& name, const config& gen = default_config(),
                 const block_delays& t = {})
        : sc_module(name),
          node31("node31", k_t(bits_from_string(gen.k31_bits))),
          node32("node32", k_t(bits_from_string(gen.k32_bits))),
          add15_cin("add15_cin", false),
          mul6("mul6", t.multiplier),
          add15("add15", overflow_mode::wrap, 0, 0, t.adder) {
        node31.y(node31_k);
        node32.y(node32_k);
        add15_cin.y(add15_carry0);
        mul6.a(n); mul6.b(node31_k); mul6.p(mul6_n_x_k);
        add15.a(mul6_n_x_k); add15.b(node32_k); add15.cin(add15_carry0); add15.s(a);
    }
};

}  // namespace shading
