// Two-input AND gate on single wires. The squared-quadratic device's output 29 is strobe 17
// gated by its squaring stage's done flag: y = a AND b, one gate level.
#pragma once

#include <systemc>

#include "core/comb_delay.h"
#include "core/timed_block.h"

namespace shading {

class and_gate : public sc_core::sc_module, public timed_block {
public:
    sc_core::sc_in<bool> a{"a"}, b{"b"};
    sc_core::sc_out<bool> y{"y"};

    SC_HAS_PROCESS(and_gate);
    explicit and_gate(const sc_core::sc_module_name& name, const sc_core::sc_time& delay = sc_core::SC_ZERO_TIME)
        : sc_module(name), drv_(y, delay) {
        SC_METHOD(compute);
        sensitive << a << b;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

private:
    void compute() { drv_.drive(a.read() && b.read()); }

    inertial_driver<bool> drv_;
};

}  // namespace shading
