// Barrel shifter: y = x << s, the shift amount a bus (one row of 2:1 multiplexers per wire of s).
// Input wire i lands on output wire i + s; wires shifted past the top of the WOUT-wire output are
// dropped and the low s output wires are tied to 0. The squared-quadratic device normalises n and
// scales its bend with it. Default delay: one multiplexer per row.
#pragma once

#include <cstdint>
#include <systemc>

#include "core/comb_delay.h"
#include "core/timed_block.h"
#include "formats/fixed_point.h"

namespace shading {

template <unsigned WIN, unsigned WOUT, unsigned WS>
class barrel_shifter : public sc_core::sc_module, public timed_block {
    static_assert(WIN <= 64 && WOUT <= 64 && WS >= 1 && WS <= 6, "widths");

public:
    sc_core::sc_in<sc_dt::sc_uint<WIN>> x{"x"};
    sc_core::sc_in<sc_dt::sc_uint<WS>> s{"s"};
    sc_core::sc_out<sc_dt::sc_uint<WOUT>> y{"y"};

    SC_HAS_PROCESS(barrel_shifter);
    explicit barrel_shifter(const sc_core::sc_module_name& name, const sc_core::sc_time& delay = WS * delay_default::mux)
        : sc_module(name), drv_(y, delay) {
        SC_METHOD(compute);
        sensitive << x << s;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

private:
    void compute() {
        const unsigned sh = s.read().to_uint();
        const uint64_t v = sh >= 64 ? 0 : x.read().to_uint64() << sh;
        drv_.drive(sc_dt::sc_uint<WOUT>(wrap_bits(static_cast<int64_t>(v), WOUT)));
    }

    inertial_driver<sc_dt::sc_uint<WOUT>> drv_;
};

}  // namespace shading
