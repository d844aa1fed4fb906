// Sampling a write strobe at rising edges without a wake-up per idle clock (the RAM's write port,
// the frame buffer's check). A method sensitive to clk.pos() asks sample() at each wake-up: at an
// edge where the strobe is 0 the method sleeps until the strobe rises (just after some rising edge)
// and samples again from the next rising edge; every edge where the strobe is 1 is still seen.
#pragma once

#include <systemc>

namespace shading {

class strobe_gate {
public:
    // Called first in the method: true at a rising edge where `strobe` is 1 (sample it); false
    // otherwise, with the method's next trigger set to the strobe's rise or the edge after it.
    bool sample(const sc_core::sc_in<bool>& clk, const sc_core::sc_in<bool>& strobe) {
        if (waiting_) {  // the strobe has just risen: its first sampling edge is the next one
            waiting_ = false;
            sc_core::next_trigger(clk.posedge_event());
            return false;
        }
        if (!strobe.read()) {
            waiting_ = true;
            sc_core::next_trigger(strobe.posedge_event());
            return false;
        }
        return true;
    }

private:
    bool waiting_ = false;
};

}  // namespace shading
