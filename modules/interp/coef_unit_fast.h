// Fast pin-level abstractions of the interpolation paper's coefficient units (interp/abstraction.h): the pins and the
// timing at them of coef_unit_cubic<SET, DIV> and coef_unit_quad, one process each, no internal
// blocks or delays. At each falling edge of clk the samples on the pins are latched (as rg_i1..4
// do) and A..D (a..c) computed by golden_cubic_coefs (the sample set, the /3 mode, the whole-sum
// grouping coef_unit_cubic wires) or golden_quad_coefs (src/floor/arith/interp_arith.h, the shared
// Q8.8 / Q16.8 / Q16.16 formats) and driven at once: valid from that falling edge, so at the next
// rising edge as the block units promise. Unchanged samples recompute nothing.
#pragma once

#include <array>
#include <systemc>

#include "arith/interp_arith.h"
#include "formats/interp_formats.h"

namespace shading {

template <interp::sample_set SET, interp::div3_mode DIV>
class coef_unit_cubic_fast : public sc_core::sc_module {
    using sample_t = sc_dt::sc_uint<interp::sample_fmt.width>;
    using coef_t = sc_dt::sc_uint<interp::coef_fmt.width>;

public:
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<sample_t> i1{"i1"}, i2{"i2"}, i3{"i3"}, i4{"i4"};
    sc_core::sc_out<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"};

    SC_HAS_PROCESS(coef_unit_cubic_fast);
    explicit coef_unit_cubic_fast(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_falling_edge);
        sensitive << clk.neg();
        dont_initialize();
    }

private:
    void on_falling_edge() {
        const std::array<uint64_t, 4> s{i1.read().to_uint64(), i2.read().to_uint64(), i3.read().to_uint64(),
                                         i4.read().to_uint64()};
        if (latched_ && s == held_) return;
        held_ = s;
        latched_ = true;
        const auto k = interp::golden_cubic_coefs(s, SET, DIV, interp::div3_grouping::whole_sum);
        a.write(word(k.a));
        b.write(word(k.b));
        c.write(word(k.c));
        d.write(word(k.d));
    }
    static coef_t word(int64_t code) { return coef_t(wrap_bits(code, interp::coef_fmt.width)); }

    std::array<uint64_t, 4> held_{};
    bool latched_ = false;
};

class coef_unit_quad_fast : public sc_core::sc_module {
    using sample_t = sc_dt::sc_uint<interp::sample_fmt.width>;
    using coef_t = sc_dt::sc_uint<interp::coef_fmt.width>;

public:
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<sample_t> i1{"i1"}, i2{"i2"}, i3{"i3"};
    sc_core::sc_out<coef_t> a{"a"}, b{"b"}, c{"c"};

    SC_HAS_PROCESS(coef_unit_quad_fast);
    explicit coef_unit_quad_fast(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_falling_edge);
        sensitive << clk.neg();
        dont_initialize();
    }

private:
    void on_falling_edge() {
        const std::array<uint64_t, 3> s{i1.read().to_uint64(), i2.read().to_uint64(), i3.read().to_uint64()};
        if (latched_ && s == held_) return;
        held_ = s;
        latched_ = true;
        const auto k = interp::golden_quad_coefs(s);
        a.write(word(k.a));
        b.write(word(k.b));
        c.write(word(k.c));
    }
    static coef_t word(int64_t code) { return coef_t(wrap_bits(code, interp::coef_fmt.width)); }

    std::array<uint64_t, 3> held_{};
    bool latched_ = false;
};

}  // namespace shading
