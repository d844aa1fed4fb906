// Saturating stage on an unsigned bus (rtl/blocks/saturator.v): y = x clamped to `hi` in saturate
// mode (a comparator and a multiplexer; a magnitude comparison is a carry chain, so an adder's
// delay by default), y = x in wrap mode (wires, no delay). The square-and-multiply device clamps
// the loaded cos to 1.0 with it, as the squared-quadratic device's ADD11 clamps its sum.
#pragma once

#include <cstdint>
#include <systemc>

#include "core/comb_delay.h"
#include "core/timed_block.h"
#include "formats/fixed_point.h"

namespace shading {

template <unsigned W>
class saturator : public sc_core::sc_module, public timed_block {
    static_assert(W >= 1 && W <= 64, "width");

public:
    sc_core::sc_in<sc_dt::sc_uint<W>> x{"x"};
    sc_core::sc_out<sc_dt::sc_uint<W>> y{"y"};

    SC_HAS_PROCESS(saturator);
    saturator(const sc_core::sc_module_name& name, overflow_mode mode, uint64_t hi,
              const sc_core::sc_time& delay = delay_default::adder)
        : sc_module(name), mode_(mode), hi_(hi),
          drv_(y, mode == overflow_mode::saturate ? delay : sc_core::SC_ZERO_TIME) {
        SC_METHOD(compute);
        sensitive << x;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

    // The block's function, for golden models and tests.
    static uint64_t value(uint64_t bits, overflow_mode mode, uint64_t hi) {
        return mode == overflow_mode::saturate && bits > hi ? hi : bits;
    }

private:
    void compute() { drv_.drive(sc_dt::sc_uint<W>(value(x.read().to_uint64(), mode_, hi_))); }

    overflow_mode mode_;
    uint64_t hi_;
    inertial_driver<sc_dt::sc_uint<W>> drv_;
};

}  // namespace shading
