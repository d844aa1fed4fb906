// Equality comparator on two W-bit buses: y = 1 where every wire of a equals its wire of b (an XNOR
// per wire and an AND tree; one comparator delay). The shading pipeline's sample stage uses it to see
// that a job's first sample point is the point whose colour it formed last.
#pragma once

#include <systemc>

#include "core/comb_delay.h"
#include "core/timed_block.h"

namespace shading {

template <unsigned W>
class eq_cmp : public sc_core::sc_module, public timed_block {
    static_assert(W >= 1 && W <= 64, "an equality comparator compares buses of 1..64 wires");

public:
    using word = sc_dt::sc_uint<W>;
    sc_core::sc_in<word> a{"a"}, b{"b"};
    sc_core::sc_out<bool> y{"y"};

    SC_HAS_PROCESS(eq_cmp);
    explicit eq_cmp(const sc_core::sc_module_name& name, const sc_core::sc_time& delay = delay_default::mux)
        : sc_module(name), drv_(y, delay) {
        SC_METHOD(compute);
        sensitive << a << b;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

private:
    void compute() { drv_.drive(a.read() == b.read()); }

    inertial_driver<bool> drv_;
};

}  // namespace shading
