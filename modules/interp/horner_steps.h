// The Horner unit's micro-sequencer as plain state (horner_ctrl.h's FSM, no process): one call per
// rising edge. A request is accepted where start = 1 and the unit is idle or on its last step; then
// steps 1..6, or 1..4 when deg2 reads 1 entering step 4 (the interpolation paper, Fig. 4). horner_ctrl
// (block level) and horner_unit_fast (fast pin level) step this one sequencer, as fd_count.h serves
// the forward-difference units.
#pragma once

#include <cstdint>
#include <sstream>
#include <systemc>

#include "core/report_ids.h"
#include "formats/interp_formats.h"

namespace shading::interp {

// The controller's assertion (not hardware): t above 1.0 is extrapolation; the unit evaluates it as
// given. Reported once per request, entering step 2, as a shading/input warning naming `who`.
inline void check_horner_t(const char* who, uint64_t t_code) {
    if (t_code <= t_one) return;
    std::ostringstream os;
    os << who << ": t = " << t_code << "/256 > 1 at " << sc_core::sc_time_stamp()
       << "; evaluated as given (extrapolation; RG wraps if the value leaves Q16.16)";
    SC_REPORT_WARNING(msg::input, os.str().c_str());
}

class horner_steps {
public:
    // One rising edge; returns the step that starts at it (0: idle). `deg2()` is called only when
    // entering step 4 (the handshake holds it stable from the first falling edge after acceptance),
    // `entering_step2()` only when entering step 2 (where the controller checks t).
    template <class Deg2, class EnteringStep2>
    unsigned rising(bool start, Deg2&& deg2, EnteringStep2&& entering_step2) {
        unsigned next = 0;
        if (start && (state_ == 0 || done())) next = 1;
        else if (state_ != 0 && !done()) next = state_ + 1;
        if (next == 1) last_ = 6;  // until step 4 says otherwise
        if (next == 4 && deg2()) last_ = 4;
        if (next == 2) entering_step2();
        state_ = next;
        return state_;
    }

    unsigned step() const { return state_; }                  // 0 idle, 1..6
    bool done() const { return state_ != 0 && state_ == last_; }  // high during the last step
    bool busy() const { return state_ != 0; }

private:
    unsigned state_ = 0, last_ = 6;
};

}  // namespace shading::interp
