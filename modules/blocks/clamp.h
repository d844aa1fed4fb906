// Saturating output stage: y = min(max(floor(x / 2^DROP), 0), 2^WOUT - 1). DROP low wires are left
// unconnected (floor, as in mul.h), then a comparator forces all wires to 0 for a negative value
// and all to 1 above the range. Used for the shading pipeline's pixel clamp (Q16.16 signed ->
// Q8.8 unsigned, src/floor/arith/pipeline_arith.h, golden_output_clamp).
#pragma once

#include <cstdint>
#include <systemc>

#include "core/comb_delay.h"
#include "core/timed_block.h"
#include "formats/fixed_point.h"

namespace shading {

template <unsigned WIN, unsigned WOUT, unsigned DROP = 0, bool IN_SIGNED = true>
class clamp : public sc_core::sc_module, public timed_block {
    static_assert(WIN <= 64 && WOUT < 63 && DROP < WIN, "widths");

public:
    sc_core::sc_in<sc_dt::sc_uint<WIN>> x{"x"};
    sc_core::sc_out<sc_dt::sc_uint<WOUT>> y{"y"};

    SC_HAS_PROCESS(clamp);
    // A magnitude comparison is a carry chain: an adder's delay by default.
    explicit clamp(const sc_core::sc_module_name& name, const sc_core::sc_time& delay = delay_default::adder)
        : sc_module(name), drv_(y, delay) {
        SC_METHOD(compute);
        sensitive << x;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

    // The block's function, for golden models and tests.
    static uint64_t value(uint64_t bits) {
        const int64_t v = floor_shift(code_value(bits, qfmt{WIN, IN_SIGNED, 0}), DROP);
        const int64_t hi = static_cast<int64_t>((1ull << WOUT) - 1);
        return static_cast<uint64_t>(v < 0 ? 0 : (v > hi ? hi : v));
    }

private:
    void compute() { drv_.drive(sc_dt::sc_uint<WOUT>(value(x.read().to_uint64()))); }

    inertial_driver<sc_dt::sc_uint<WOUT>> drv_;
};

}  // namespace shading
