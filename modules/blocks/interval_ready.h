// "Ready for the next interval" gate of the raster-line interpolator (interp_line_unit.h, the interpolation paper):
// ready = NOT valid OR last, from the forward-difference controller's registered outputs. It says
// what fd_ctrl decides internally at the next rising edge: an interval pending on `start` is taken
// there when the evaluator is idle (valid = 0) or on its last pixel (last = 1). Exported so a
// sample source knows when to present the next interval's I1..I4 without rebuilding that rule.
// One gate level (an OR with one inverted input): the delay of one inverter by default.
#pragma once

#include <systemc>

#include "core/comb_delay.h"
#include "core/timed_block.h"

namespace shading {

class interval_ready : public sc_core::sc_module, public timed_block {
public:
    sc_core::sc_in<bool> valid{"valid"}, last{"last"};
    sc_core::sc_out<bool> ready{"ready"};

    SC_HAS_PROCESS(interval_ready);
    explicit interval_ready(const sc_core::sc_module_name& name,
                            const sc_core::sc_time& delay = delay_default::inverter)
        : sc_module(name), drv_(ready, delay) {
        SC_METHOD(compute);  // also at time zero: idle, so ready rises one gate delay after 0
        sensitive << valid << last;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }

private:
    void compute() { drv_.drive(!valid.read() || last.read()); }

    inertial_driver<bool> drv_;
};

}  // namespace shading
