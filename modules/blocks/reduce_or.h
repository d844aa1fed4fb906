// OR gate over wires LO..W-1 of a W-bit bus: y = 1 when any of them is 1, i.e. when the bus, read
// as an unsigned integer, is at least 2^LO. (The tuned UA 60553 variant uses it as "n >= 2".)
#pragma once

#include <cstdint>
#include <systemc>

#include "core/comb_delay.h"
#include "core/timed_block.h"

namespace shading {

template <unsigned W, unsigned LO = 0>
class reduce_or : public sc_core::sc_module, public timed_block {
    static_assert(LO < W && W <= 64, "at least one wire in the gate");

public:
    sc_core::sc_in<sc_dt::sc_uint<W>> x{"x"};
    sc_core::sc_out<bool> y{"y"};

    SC_HAS_PROCESS(reduce_or);
    // One gate level: the default delay is that of one inverter (comb_delay.h).
    explicit reduce_or(const sc_core::sc_module_name& name,
                       const sc_core::sc_time& delay = delay_default::inverter)
        : sc_module(name), drv_(y, delay) {
        SC_METHOD(compute);
        sensitive << x;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

private:
    void compute() { drv_.drive((x.read().to_uint64() >> LO) != 0); }

    inertial_driver<bool> drv_;
};

}  // namespace shading
