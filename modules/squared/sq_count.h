// The squaring stage's controller as plain state (sq_ctrl.h's FSM, no process), stepped by the
// block-level controller and by the fast pin-level model (squared_fast.h) alike.
//
// Handshake (ours; the device's timing in modules/squared/README.md): strobe 17's falling edge
// latches cos in RG2 (UA 60553, Fig. 3) and raises `pending`, which also closes output 29's gate
// (done = 0). At the next rising edge of clk the controller takes it: LOAD (RG_SQ takes ADD11, the
// quadratic at n', at the falling edge that follows) with k = 9 - z squarings to go; then one
// SQUARE per clock (RG_SQ takes its own square); at the rising edge after the last latch, done = 1
// and output 29 follows strobe 17 again. done therefore rises k + 2 rising edges after the strobe
// was taken (the taking edge counted as the first). A strobe while a result is pending or still
// being squared abandons that result (it is never validated) and restarts with the new cos.
#pragma once

#include "formats/squared_formats.h"

namespace shading::squared {

class sq_count {
public:
    using select = sq_select;  // MX_SQ's inputs (squared_formats.h)
    static constexpr select hold = sq_hold, load = sq_load, square = sq_square;

    // Strobe 17 fell. Returns true when it abandons a result not yet validated.
    bool strobe() {
        const bool dropped = pending_ || busy_;
        pending_ = true;
        done_ = false;
        return dropped;
    }

    // A rising edge of clk; z is the LZC of RG1 (read only when a strobe is taken). Returns MX_SQ's
    // select for the falling edge that follows.
    select rising(unsigned z) {
        if (pending_) {
            pending_ = false;
            busy_ = true;
            left_ = squarings(z);
            return load;
        }
        if (busy_ && left_ > 0) {
            --left_;
            return square;
        }
        if (busy_) {
            busy_ = false;
            done_ = true;
        }
        return hold;
    }

    static unsigned squarings(unsigned z) { return z <= z_full ? z_full - z : 0; }

    bool done() const { return done_; }          // output 29's gate
    bool pending() const { return pending_; }    // a strobe not yet taken
    bool busy() const { return busy_; }          // loaded, not yet done
    unsigned left() const { return left_; }      // squarings still to come

private:
    bool pending_ = false, busy_ = false, done_ = true;
    unsigned left_ = 0;
};

}  // namespace shading::squared
