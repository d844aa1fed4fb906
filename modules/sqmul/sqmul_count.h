// The square-and-multiply device's controller as plain state (sqmul_ctrl.h's FSM, no process),
// stepped by the block-level controller and by the fast pin-level model (sqmul_fast.h) alike; the
// RTL twin is rtl/sqmul/sqmul_ctrl.v.
//
// Handshake (ours, the squared-quadratic device's, modules/squared/sq_count.h; the device's timing
// in modules/sqmul/README.md). Strobe 17 has no clock of its own, so its request crosses into
// clk's domain through a synchroniser (blocks/synchroniser.h, `sync17`, sqmul::sync_stages
// flip-flops), and every flip-flop on clk reads only the synchroniser's output:
//   req    strobe 17's domain: its falling edge (which also latches cos in RG2, UA 60553, Fig. 3)
//          sets req to the complement of `taken`, raising a request (or keeping one not yet taken)
//   taken  clk: the request last taken; a rising edge that sees req_s != taken takes it: LOAD (RG_P
//          takes cos at the falling edge that follows) with the squares to go, k = 9 - z, and the
//          bits of n below its leading one, f
//   busy   loaded, not yet done: per bit, most significant first, a SQUARE (MUL_P = RG_P x RG_P)
//          and, when the bit is 1, a MULTIPLY (MUL_P = RG_P x cos), one per clock
//   ack    clk: set to `taken` at the rising edge after the last latch (busy falls with it)
//   done   output 29's gate: req == ack and not busy. It falls with the strobe itself, before the
//          request has crossed, so output 29 never validates the previous pixel meanwhile.
// With S = sync_stages the S-th rising edge after the strobe puts the request on req_s, the
// (S+1)-th takes it, one per square and per multiplication follows, and done rises at the
// (squares + multiplies + S + 2)-th: floor(log2 n) + popcount(n) + 3 rising edges after the strobe
// fell for S = 2 (n = 0 is read as n = 1: 4). A strobe at a rising edge's own instant reaches the
// first stage one edge later (the clock is stepped first). A strobe while a result is pending or
// still being walked abandons that result (it is never validated): before the taking edge it only
// keeps the request raised (the new cos is loaded); after it, it raises a new request, taken once
// it has crossed.
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

    // Strobe 17 fell (strobe 17's domain: reads only `taken`, which stays put from the taking edge
    // until the result is valid). Returns true when it abandons a result not yet validated.
    bool strobe() {
        const bool dropped = !done();
        req_ = !taken_;
        return dropped;
    }

    // A rising edge of clk; req_s is the synchroniser's output before this edge, z the LZC of RG1
    // and f the low wires of BSH1 (read only when a request is taken).
    selects rising(bool req_s, unsigned z, unsigned f) {
        if (req_s != taken_) {  // the request is taken
            taken_ = req_s;
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
        if (busy_) {
            busy_ = false;
            ack_ = taken_;
        }
        return {p_hold, b_p};
    }

    static unsigned squarings(unsigned z) { return z <= z_full ? z_full - z : 0; }

    bool req() const { return req_; }                     // strobe 17's request, into sync17
    bool done() const { return req_ == ack_ && !busy_; }  // output 29's gate
    bool pending() const { return req_ != taken_; }       // a request not yet taken
    bool busy() const { return busy_; }                   // loaded, not yet done
    unsigned left() const { return left_; }               // squares still to come

private:
    bool req_ = false, taken_ = false, ack_ = false, busy_ = false, multiply_next_ = false;
    unsigned left_ = 0;
    uint64_t bits_ = 0;  // the next bit to walk is bits_'s top wire
};

}  // namespace shading::sqmul
