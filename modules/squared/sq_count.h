// The squaring stage's controller as plain state (sq_ctrl.h's FSM, no process), stepped by the
// block-level controller and by the fast pin-level model (squared_fast.h) alike.
//
// Handshake (ours; the device's timing in modules/squared/README.md). Strobe 17 has no clock of
// its own, so its request crosses into clk's domain through a synchroniser (blocks/
// synchroniser.h, `sync17`, squared::sync_stages flip-flops), and every flip-flop on clk reads only
// the synchroniser's output:
//   req    strobe 17's domain: its falling edge (which also latches cos in RG2, UA 60553, Fig. 3)
//          sets req to the complement of `taken`, raising a request (or keeping one not yet taken)
//   taken  clk: the request last taken; a rising edge that sees req_s != taken takes it: LOAD (RG_SQ
//          takes ADD11, the quadratic at n', at the falling edge that follows), k = 9 - z to go
//   busy, left   loaded, not yet done; one SQUARE per clock while left > 0
//   ack    clk: set to `taken` at the rising edge after the last square (busy falls with it)
//   done   output 29's gate: req == ack and not busy. It falls with the strobe itself, before the
//          request has crossed, so output 29 never validates the previous pixel meanwhile.
// With S = sync_stages the first rising edge after the strobe is the synchroniser's first stage,
// the S-th puts the request on req_s, the (S+1)-th takes it, k more square, and done rises at the
// (k + S + 2)-th: k + 4 rising edges after the strobe fell for S = 2. A strobe at a rising edge's
// own instant reaches the first stage one edge later (the clock is stepped first).
// A strobe while a result is pending or still being squared abandons that result (it is never
// validated): before the taking edge it only keeps the request raised (the new cos is loaded);
// after it, it raises a new request, taken once it has crossed.
#pragma once

#include "formats/squared_formats.h"

namespace shading::squared {

class sq_count {
public:
    using select = sq_select;  // MX_SQ's inputs (squared_formats.h)
    static constexpr select hold = sq_hold, load = sq_load, square = sq_square;

    // Strobe 17 fell (strobe 17's domain: reads only `taken`, which stays put from the taking
    // edge until the result is valid). Returns true when it abandons a result not yet validated.
    bool strobe() {
        const bool dropped = !done();
        req_ = !taken_;
        return dropped;
    }

    // A rising edge of clk; req_s is the synchroniser's output before this edge, z the LZC of RG1
    // (read only when a request is taken). Returns MX_SQ's select for the falling edge that follows.
    select rising(bool req_s, unsigned z) {
        if (req_s != taken_) {
            taken_ = req_s;
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
            ack_ = taken_;
        }
        return hold;
    }

    static unsigned squarings(unsigned z) { return z <= z_full ? z_full - z : 0; }

    bool req() const { return req_; }                         // strobe 17's request, into sync17
    bool done() const { return req_ == ack_ && !busy_; }      // output 29's gate
    bool pending() const { return req_ != taken_; }           // a request not yet taken
    bool busy() const { return busy_; }                       // loaded, not yet done
    unsigned left() const { return left_; }                   // squarings still to come

private:
    bool req_ = false, taken_ = false, ack_ = false, busy_ = false;
    unsigned left_ = 0;
};

}  // namespace shading::squared
