// The square-and-multiply device's controller as plain state (sqmul_ctrl.h's FSM, no process),
// stepped by the block-level controller and by the fast pin-level model (sqmul_fast.h) alike; the
// RTL twin is rtl/sqmul/sqmul_ctrl.v.
//
// Handshake (ours, the squared-quadratic device's, modules/squared/sq_count.h; the device's timing
// in modules/sqmul/README.md): strobe 17's falling edge latches cos in RG2 (UA 60553, Fig. 3) and
// raises `pending` (req toggled in strobe 17's domain), which also closes output 29's gate
// (done = !pending && !busy). At the next rising edge of clk the controller takes it (ack, in clk's
// domain): LOAD (RG_P takes cos at the falling edge that follows) with the squares to go,
// k = 9 - z, and the bits of n below its leading one, f. Then per bit, most significant first, a
// SQUARE (MUL_P = RG_P x RG_P) and, when the bit is 1, a MULTIPLY (MUL_P = RG_P x cos), one per
// clock; at the rising edge after the last latch, done = 1 and output 29 follows strobe 17 again.
// done rises floor(log2 n) + popcount(n) + 1 rising edges after the strobe was taken (the taking
// edge counted; n = 0 is read as n = 1: 2). A strobe while a result is pending or still being
// walked abandons that result (it is never validated) and restarts with the new cos.
#pragma once

#include "formats/sqmul_formats.h"

namespace shading::sqmul {

class sqmul_count {
public:
    // MX_P's and MX_B's selects for the falling edge that follows a rising edge (sqmul_formats.h).
    struct selects {
        p_select p = p_hold;
        b_select b = b_p;
    };

    // Strobe 17 fell (req toggles: pending). Returns true when it abandons a result not yet
    // validated.
    bool strobe() {
        const bool dropped = pending_ || busy_;
        pending_ = true;
        return dropped;
    }

    // A rising edge of clk; z is the LZC of RG1 and f the low wires of BSH1 (read only when a strobe
    // is taken).
    selects rising(unsigned z, unsigned f) {
        if (pending_) {  // ack: the strobe is taken
            pending_ = false;
            busy_ = true;
            left_ = squarings(z);
            bits_ = f & f_fmt.mask();
            multiply_next_ = false;
            return {p_load, b_p};
        }
        if (busy_ && multiply_next_) {
            multiply_next_ = false;
            return {p_product, b_cos};
        }
        if (busy_ && left_ > 0) {
            --left_;
            multiply_next_ = (bits_ >> (f_fmt.width - 1)) & 1u;
            bits_ = (bits_ << 1) & f_fmt.mask();
            return {p_product, b_p};
        }
        busy_ = false;
        return {p_hold, b_p};
    }

    static unsigned squarings(unsigned z) { return z <= z_full ? z_full - z : 0; }

    bool done() const { return !pending_ && !busy_; }  // output 29's gate
    bool pending() const { return pending_; }          // a strobe not yet taken
    bool busy() const { return busy_; }                // loaded, not yet done
    unsigned left() const { return left_; }            // squares still to come

private:
    bool pending_ = false, busy_ = false, multiply_next_ = false;
    unsigned left_ = 0;
    uint64_t bits_ = 0;  // the next bit to walk is bits_'s top wire
};

}  // namespace shading::sqmul
