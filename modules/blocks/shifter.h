// Shift by a constant: pure wiring, zero delay. Input wire i lands on output wire i + shift; the
// output wires below `shift` are tied to 0, those above the input are tied to 0 (IN_SIGNED = false)
// or to the input's sign wire (IN_SIGNED = true, sign extension). A negative shift leaves the
// -shift low input wires unconnected: truncation toward minus infinity (floor), as in mul.h.
// Used to align fixed-point buses (Q.8 onto Q.16: shift 8) and to multiply by powers of two.
#pragma once

#include <cstdint>
#include <systemc>

#include "formats/fixed_point.h"
#include "core/timed_block.h"

namespace shading {

template <unsigned WIN, unsigned WOUT, bool IN_SIGNED = false>
class shifter : public sc_core::sc_module, public timed_block {
    static_assert(WIN <= 64 && WOUT <= 64, "widths");

public:
    sc_core::sc_in<sc_dt::sc_uint<WIN>> x{"x"};
    sc_core::sc_out<sc_dt::sc_uint<WOUT>> y{"y"};

    SC_HAS_PROCESS(shifter);
    shifter(const sc_core::sc_module_name& name, int shift) : sc_module(name), shift_(shift) {
        SC_METHOD(compute);
        sensitive << x;
    }

    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }  // wiring

private:
    void compute() {
        const int64_t v = code_value(x.read().to_uint64(), qfmt{WIN, IN_SIGNED, 0});
        const int64_t s = shift_ >= 0 ? static_cast<int64_t>(static_cast<uint64_t>(v) << shift_)
                                      : floor_shift(v, static_cast<unsigned>(-shift_));
        y.write(sc_dt::sc_uint<WOUT>(wrap_bits(s, WOUT)));
    }

    int shift_;
};

}  // namespace shading
