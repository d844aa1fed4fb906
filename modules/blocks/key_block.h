// Key block BK of the interpolation paper, Fig. 4 ("блок ключів"): one AND gate per wire, so the block passes its
// operand when `pass` is 1 and forces every wire to 0 when `pass` is 0 ("режим обнулення").
#pragma once

#include <systemc>

#include "core/comb_delay.h"
#include "core/timed_block.h"

namespace shading {

template <unsigned W>
class key_block : public sc_core::sc_module, public timed_block {
    static_assert(W >= 1 && W <= 64, "width");

public:
    using word = sc_dt::sc_uint<W>;
    sc_core::sc_in<word> x{"x"};
    sc_core::sc_in<bool> pass{"pass"};
    sc_core::sc_out<word> y{"y"};

    SC_HAS_PROCESS(key_block);
    // One gate level: the default delay is that of one inverter (comb_delay.h).
    explicit key_block(const sc_core::sc_module_name& name,
                       const sc_core::sc_time& delay = delay_default::inverter)
        : sc_module(name), drv_(y, delay) {
        SC_METHOD(compute);
        sensitive << x << pass;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

private:
    void compute() { drv_.drive(pass.read() ? x.read() : word(0)); }

    inertial_driver<word> drv_;
};

}  // namespace shading
