// N-input multiplexer, W bits wide: y = in[sel]. Select codes >= N (possible when N is not a
// power of two) drive all wires to 0, a defined result rather than an unknown one.
#pragma once

#include <systemc>

#include "core/comb_delay.h"
#include "core/timed_block.h"

namespace shading {

// Wires a select bus needs to address N inputs.
constexpr unsigned select_width(unsigned n) {
    unsigned w = 1;
    while ((1u << w) < n) ++w;
    return w;
}

template <unsigned W, unsigned N>
class mux : public sc_core::sc_module, public timed_block {
    static_assert(N >= 2 && W <= 64, "a multiplexer selects among two or more buses of <= 64 wires");

public:
    static constexpr unsigned sel_width = select_width(N);
    using word = sc_dt::sc_uint<W>;
    using select = sc_dt::sc_uint<sel_width>;

    sc_core::sc_vector<sc_core::sc_in<word>> in{"in", N};
    sc_core::sc_in<select> sel{"sel"};
    sc_core::sc_out<word> y{"y"};

    SC_HAS_PROCESS(mux);
    explicit mux(const sc_core::sc_module_name& name, const sc_core::sc_time& delay = delay_default::mux)
        : sc_module(name), drv_(y, delay) {
        SC_METHOD(compute);
        sensitive << sel;
        for (auto& i : in) sensitive << i;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

private:
    void compute() {
        const unsigned s = sel.read().to_uint();
        drv_.drive(s < N ? in[s].read() : word(0));
    }

    inertial_driver<word> drv_;
};

}  // namespace shading
