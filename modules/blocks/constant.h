// Hardwired constant: wires tied to logic 1 or 0. The value is written once at time zero and
// never changes. For buses, build the value with bits_from_string("1100101") so the source
// reads like the patent's claim ("bits 1, 2, 5, 7 tied to 1").
#pragma once

#include <systemc>

#include "core/timed_block.h"

namespace shading {

template <typename T>
class constant : public sc_core::sc_module, public timed_block {
public:
    sc_core::sc_out<T> y{"y"};

    SC_HAS_PROCESS(constant);
    constant(const sc_core::sc_module_name& name, const T& value) : sc_module(name), value_(value) {
        SC_METHOD(drive);  // runs once at initialisation; nothing ever re-triggers it
    }

    // Tied wires: no propagation delay.
    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }

private:
    void drive() { y.write(value_); }
    T value_;
};

}  // namespace shading
