// Divider by a hardwired constant K: y = floor((x << ALIGN) / K) for a signed WIN-bit x, on a
// signed WOUT-bit bus (wraps if the quotient does not fit). The reference against which the interpolation paper's
// shift-and-add x/3 is compared ("exact division" option). In silicon this is a constant divider
// (e.g. x * 0.010101...b to enough terms plus a remainder correction); modelled by its function,
// with the delay of a multiplier.
#pragma once

#include <cstdint>
#include <systemc>

#include "formats/fixed_point.h"
#include "core/comb_delay.h"
#include "core/timed_block.h"

namespace shading {

template <unsigned WIN, unsigned WOUT, unsigned K, unsigned ALIGN>
class const_div : public sc_core::sc_module, public timed_block {
    static_assert(K >= 1 && WIN + ALIGN < 63 && WOUT <= 64, "widths");

public:
    sc_core::sc_in<sc_dt::sc_uint<WIN>> x{"x"};
    sc_core::sc_out<sc_dt::sc_uint<WOUT>> y{"y"};

    SC_HAS_PROCESS(const_div);
    explicit const_div(const sc_core::sc_module_name& name,
                       const sc_core::sc_time& delay = delay_default::multiplier)
        : sc_module(name), drv_(y, delay) {
        SC_METHOD(compute);
        sensitive << x;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

private:
    void compute() {
        const int64_t v = code_value(x.read().to_uint64(), qfmt{WIN, true, 0}) * (int64_t{1} << ALIGN);
        const int64_t k = static_cast<int64_t>(K);
        const int64_t q = v / k - ((v % k != 0 && v < 0) ? 1 : 0);  // floor
        drv_.drive(sc_dt::sc_uint<WOUT>(wrap_bits(q, WOUT)));
    }

    inertial_driver<sc_dt::sc_uint<WOUT>> drv_;
};

}  // namespace shading
