// Adder block with a carry input: s = a + b + cin. Operands are zero- or sign-extended
// (ASIGNED/BSIGNED) and summed exactly; the WS-bit output then either carries the low WS bits
// (overflow_mode::wrap, a real two's-complement adder) or the sum clamped to [sat_lo, sat_hi]
// (overflow_mode::saturate, for a saturating output stage).
#pragma once

#include <algorithm>
#include <cstdint>
#include <systemc>

#include "formats/fixed_point.h"
#include "core/comb_delay.h"
#include "core/timed_block.h"

namespace shading {

template <unsigned WA, unsigned WB, unsigned WS, bool ASIGNED = false, bool BSIGNED = false>
class adder : public sc_core::sc_module, public timed_block {
    static_assert(WA < 63 && WB < 63 && WS <= 64, "widths");

public:
    sc_core::sc_in<sc_dt::sc_uint<WA>> a{"a"};
    sc_core::sc_in<sc_dt::sc_uint<WB>> b{"b"};
    sc_core::sc_in<bool> cin{"cin"};
    sc_core::sc_out<sc_dt::sc_uint<WS>> s{"s"};

    SC_HAS_PROCESS(adder);
    explicit adder(const sc_core::sc_module_name& name,
                   overflow_mode mode = overflow_mode::wrap, int64_t sat_lo = 0,
                   int64_t sat_hi = static_cast<int64_t>((1ull << (WS < 63 ? WS : 62)) - 1),
                   const sc_core::sc_time& delay = delay_default::adder)
        : sc_module(name), mode_(mode), lo_(sat_lo), hi_(sat_hi), drv_(s, delay) {
        SC_METHOD(compute);
        sensitive << a << b << cin;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

private:
    void compute() {
        const int64_t sum = code_value(a.read().to_uint64(), qfmt{WA, ASIGNED, 0}) +
                            code_value(b.read().to_uint64(), qfmt{WB, BSIGNED, 0}) +
                            (cin.read() ? 1 : 0);
        const int64_t out = mode_ == overflow_mode::saturate ? std::clamp(sum, lo_, hi_) : sum;
        drv_.drive(sc_dt::sc_uint<WS>(wrap_bits(out, WS)));
    }

    overflow_mode mode_;
    int64_t lo_, hi_;
    inertial_driver<sc_dt::sc_uint<WS>> drv_;
};

}  // namespace shading
