// The timing interface every hardware block in modules/blocks implements, so core/timing_graph.h
// can derive a top's paths from its elaborated port bindings instead of hand-written sums.
// A combinational block: delay() from any input to any output (0 for wiring and constants).
// A register: delay() is clock-to-output; clock_port() and data_port() name its strobe and data
// inputs, where combinational paths end (the register is where a path starts again).
#pragma once

#include <systemc>

namespace shading {

class timed_block {
public:
    virtual ~timed_block() = default;
    virtual const sc_core::sc_time& delay() const = 0;
    virtual const sc_core::sc_port_base* clock_port() const { return nullptr; }
    virtual const sc_core::sc_port_base* data_port() const { return nullptr; }
    virtual const sc_core::sc_time& setup_time() const { return sc_core::SC_ZERO_TIME; }
    // A register's last latching edge (false before the first): monitors read it instead of
    // waking a process of their own at every edge.
    virtual bool last_latch(sc_core::sc_time&) const { return false; }
    // A clocked block whose outputs switch at its clock's rising edge (the controllers, the
    // synchroniser); every other one (reg.h) takes its inputs at the falling edge of its clock.
    virtual bool switches_on_rising_edge() const { return false; }
    bool is_register() const { return clock_port() != nullptr; }
};

}  // namespace shading
