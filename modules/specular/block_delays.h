// Propagation delays of a specular device's blocks, one per block kind (defaults in
// core/comb_delay.h and blocks/rom.h). The device passes them to every block it and its generator
// of `a` instantiate; the timing checker's paths follow them (core/timing_graph.h).
#pragma once

#include <systemc>

#include "blocks/rom.h"
#include "core/comb_delay.h"

namespace shading {

struct block_delays {
    sc_core::sc_time reg = delay_default::reg_clk_to_q;
    sc_core::sc_time inverter = delay_default::inverter;
    sc_core::sc_time adder = delay_default::adder;
    sc_core::sc_time multiplier = delay_default::multiplier;
    sc_core::sc_time rom = delay_default::rom_access;  // UA 22802's ROM access time
    sc_core::sc_time gate = delay_default::inverter;   // one gate level: OR gate, key block, AND gate
    // The squared-quadratic device's squaring stage and normaliser: a multiplexer (MX_SQ, the LZC,
    // one row of a barrel shifter).
    sc_core::sc_time mux = delay_default::mux;
};

}  // namespace shading
