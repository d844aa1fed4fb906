// The forward-difference controller's interval counter as plain state (fd_ctrl.h's FSM, no process):
// one call per rising edge. An interval is accepted where start = 1 and the counter is idle or on its
// last pixel; then LOAD, STEP for len - 1 clocks, HOLD. valid / last / ready as fd_ctrl drives them.
// The fast pin-level units (fd_eval_fast.h, interp_line_unit_fast.h) step it inside their one process.
#pragma once

#include <sstream>
#include <string>
#include <systemc>

#include "core/report_ids.h"

namespace shading::interp {

// A len outside 1..n_pixels: reported as fd_ctrl does (shading/input warning naming `who` and the
// time; `context` goes after the range) and evaluated as a full interval. Returns the length used.
inline unsigned checked_len(const char* who, unsigned len, unsigned n_pixels, const std::string& context = {}) {
    if (len != 0 && len <= n_pixels) return len;
    std::ostringstream os;
    os << who << ": len = " << len << " at " << sc_core::sc_time_stamp() << " is outside 1.." << n_pixels << context
       << "; a full interval of " << n_pixels << " pixels is evaluated";
    SC_REPORT_WARNING(msg::input, os.str().c_str());
    return n_pixels;
}

class fd_count {
public:
    enum select : unsigned { hold = 0, load = 1, step = 2 };  // fd_ctrl's sel_hold / sel_load / sel_step

    // One rising edge. `accept_len()` is called only when an interval is accepted (the unit reads its
    // len there, and nowhere else) and returns the length to evaluate (see checked_len).
    template <class AcceptLen>
    select rising(bool start, AcceptLen&& accept_len) {
        if (start && remaining_ <= 1) {
            length_ = accept_len();
            remaining_ = length_;
            return load;
        }
        if (remaining_ > 1) {
            --remaining_;
            return step;
        }
        remaining_ = 0;
        return hold;
    }

    bool valid() const { return remaining_ != 0; }
    bool last() const { return remaining_ == 1; }
    bool ready() const { return remaining_ <= 1; }  // an interval would be accepted at the next edge
    unsigned length() const { return length_; }     // of the interval last accepted
    unsigned pixel() const { return remaining_ ? length_ - remaining_ : 0; }  // index k on its way out

private:
    unsigned remaining_ = 0, length_ = 0;
};

}  // namespace shading::interp
