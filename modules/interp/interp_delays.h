// Propagation delays of the interpolation paper's units, one per block kind the units instantiate themselves
// (defaults in core/comb_delay.h). A unit passes them to its registers, adders, inverter banks,
// multipliers, multiplexers and key blocks; its clock-phase requirements follow them, derived from
// the elaborated structure (monitors/phase_checker.h, core/timing_graph.h). The shift-and-add
// networks and the /3 keep their adders' defaults.
#pragma once

#include <systemc>

#include "core/comb_delay.h"

namespace shading {

struct interp_delays {
    sc_core::sc_time reg = delay_default::reg_clk_to_q;  // clock-to-output
    sc_core::sc_time adder = delay_default::adder;
    sc_core::sc_time inverter = delay_default::inverter;
    sc_core::sc_time multiplier = delay_default::multiplier;
    sc_core::sc_time mux = delay_default::mux;
    sc_core::sc_time gate = delay_default::inverter;  // one gate level: the key block
};

}  // namespace shading
