// Leading-zero counter (a priority encoder): z = the number of 0 wires above the highest 1 of a
// W-wire bus, W for an all-zero bus. The squared-quadratic device normalises n with it
// (n = 2^(W-1-z) * 1.f). One block of a few gate levels: its delay is a constructor argument.
#pragma once

#include <systemc>

#include "blocks/mux.h"
#include "core/comb_delay.h"
#include "core/timed_block.h"

namespace shading {

template <unsigned W>
class lzc : public sc_core::sc_module, public timed_block {
    static_assert(W >= 1 && W <= 64, "width");

public:
    static constexpr unsigned z_width = select_width(W + 1);  // 0..W
    sc_core::sc_in<sc_dt::sc_uint<W>> x{"x"};
    sc_core::sc_out<sc_dt::sc_uint<z_width>> z{"z"};

    SC_HAS_PROCESS(lzc);
    explicit lzc(const sc_core::sc_module_name& name, const sc_core::sc_time& delay = delay_default::mux)
        : sc_module(name), drv_(z, delay) {
        SC_METHOD(compute);
        sensitive << x;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

private:
    void compute() {
        const uint64_t v = x.read().to_uint64();
        unsigned n = 0;
        while (n < W && !((v >> (W - 1 - n)) & 1u)) ++n;
        drv_.drive(sc_dt::sc_uint<z_width>(n));
    }

    inertial_driver<sc_dt::sc_uint<z_width>> drv_;
};

}  // namespace shading
