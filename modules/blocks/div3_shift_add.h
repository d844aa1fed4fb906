// Division by 3 as the interpolation paper, Fig. 2: x/3 ~ x/2 - x/8 - x/32 - x/128 = x * 43/128 = 0.3359375 x
// (the paper: relative error <= 0.79 %; exactly +1/128 = 0.78125 % when no wire is dropped).
// Input: signed WIN-bit bus; output: signed WOUT-bit bus with ALIGN more fraction bits than the
// input. With ALIGN >= 7 every term keeps all its wires and the result is exactly 43x/128.
#pragma once

#include <systemc>

#include "blocks/shift_add_network.h"
#include "core/timed_block.h"

namespace shading {

template <unsigned WIN, unsigned WOUT, int ALIGN>
class div3_shift_add : public sc_core::sc_module, public timed_block {
public:
    sc_core::sc_in<sc_dt::sc_uint<WIN>> x{"x"};
    sc_core::sc_out<sc_dt::sc_uint<WOUT>> y{"y"};

    shift_add_network<WIN, WOUT, true> net;

    explicit div3_shift_add(const sc_core::sc_module_name& name)
        : sc_module(name),
          net("net", 1, {{0, ALIGN - 1, false},    // + x/2
                         {0, ALIGN - 3, true},     // - x/8
                         {0, ALIGN - 5, true},     // - x/32
                         {0, ALIGN - 7, true}}) {  // - x/128
        net.in[0](x);
        net.y(y);
    }

    const sc_core::sc_time& delay() const override { return net.delay(); }  // slowest x -> y path
};

}  // namespace shading
