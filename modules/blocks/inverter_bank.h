// Inverter bank: one inverter per wire. The input bus of WIN bits lands on wires ALIGN..ALIGN+WIN-1
// of a WOUT-bit bus whose other wires are tied to 0 (so their inverters output 1): the block
// yields ~(in << ALIGN), the one's complement an adder turns into -in with a carry-in of 1.
#pragma once

#include <cstdint>
#include <systemc>

#include "core/comb_delay.h"
#include "core/timed_block.h"

namespace shading {

template <unsigned WIN, unsigned WOUT = WIN, unsigned ALIGN = 0>
class inverter_bank : public sc_core::sc_module, public timed_block {
    static_assert(WIN + ALIGN <= WOUT && WOUT <= 64, "the aligned input must fit the output bus");

public:
    sc_core::sc_in<sc_dt::sc_uint<WIN>> x{"x"};
    sc_core::sc_out<sc_dt::sc_uint<WOUT>> y{"y"};

    SC_HAS_PROCESS(inverter_bank);
    explicit inverter_bank(const sc_core::sc_module_name& name,
                           const sc_core::sc_time& delay = delay_default::inverter)
        : sc_module(name), drv_(y, delay) {
        SC_METHOD(compute);
        sensitive << x;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

private:
    void compute() { drv_.drive(sc_dt::sc_uint<WOUT>(~(x.read().to_uint64() << ALIGN))); }

    inertial_driver<sc_dt::sc_uint<WOUT>> drv_;
};

}  // namespace shading
