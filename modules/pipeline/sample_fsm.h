// The shading pipeline's sample controller as plain state (sample_ctrl.h's FSM, no process): one call
// per falling edge of clk. The block-level controller (sample_ctrl.h) drives its strobes from it, the
// fast pin-level pipeline (shading_pipeline_fast.h) steps the same state with its words; both see
// every input as it was before the edge. The handshake is documented in sample_ctrl.h.
//
// `Pins` is the caller's view of the controller's pins: inputs start(), load_frame(), ld_e(),
// dev_valid() (the device's output 29), and the jobs' check: check_job() returns the samples of the
// job in the job registers (1, 3 or 4) or 0 for a job it reported and drops; outputs ready(v),
// ld_job(v), ld_d(v), ctl17(v), frame_strobes(v) (ctl15, ctl20, ctl22, ctl24 and ld_k), smp_sel(k),
// sample_strobe(k, count, v) (the sample registers sample k of `count` goes to), samples_ready(v);
// with the carry (ours): carry_hit() (the job's first N.H / N.L codes equal the last sample's),
// carry_sel(v) (the sample registers take the last sample's colour) and ld_last(v) (the last-sample
// registers: its colour and codes, latched at every sample's latch).
#pragma once

#include <sstream>
#include <string>

#include "formats/interp_formats.h"

namespace shading::pipeline {

// Why a job is refused (empty: it is valid): m neither 0 nor m_min..m_max, len 0 or above 2^m, an
// exact pixel marked quadratic, or another m than the forward-difference evaluator is built for.
inline std::string job_problem(unsigned m, unsigned len, bool deg2, unsigned fd_m) {
    std::ostringstream os;
    if (m != 0 && (m < interp::m_min || m > interp::m_max))
        os << "m = " << m << " is neither 0 (exact pixel) nor " << interp::m_min << ".." << interp::m_max;
    else if (len == 0 || len > (1u << m))
        os << "len = " << len << " is outside 1.." << (1u << m) << " for m = " << m;
    else if (m == 0 && deg2)
        os << "an exact pixel (m = 0) is cubic, not quadratic";
    else if (fd_m != 0 && m != 0 && m != fd_m)
        os << "m = " << m << " but the forward-difference evaluator is built for m = " << fd_m;
    return os.str();
}

// Colour samples of a valid job: one for an exact pixel, three for a quadratic, four for a cubic.
inline unsigned job_samples(unsigned m, bool deg2) { return m == 0 ? 1 : (deg2 ? 3 : 4); }

class sample_fsm {
public:
    enum state { idle_st, frame_st, check_st, low_st, valid_st, high_st, copy_st };
    // The sample registers' interval: free, full (samples_ready = 1), or being taken (ld_e seen at
    // this edge: the interval registers latch half a clock later, the sample registers not before).
    enum bank { bank_free, bank_full, bank_taking };

    // wait_valid: the device takes more than one clock (the squared-quadratic device): after
    // strobe 17's clock low the controller raises it and latches the sample at the first falling
    // edge where output 29 is high, then announces `ready` at that edge; with a Fig. 1 device
    // (output 29 = strobe 17) the sample latches where strobe 17 rises and `ready` comes a clock
    // ahead of the job's last latch, so the next job is taken at that same edge.
    // carry: a job whose first sample point is the point whose colour was formed last (the previous
    // interval's t = 1 sample, which the geometry side sends again as this one's t = 0) takes that
    // colour from the last-sample registers instead of the device: no strobe 17, the same two clocks
    // (without waiting for output 29). Only after a sample since the frame constants were loaded.
    explicit sample_fsm(bool wait_valid = false, bool carry = false) : wait_valid_(wait_valid), carry_(carry) {}

    template <class Pins>
    void falling(Pins& p) {
        if (bank_ == bank_taking) bank_ = bank_free;
        if (bank_ == bank_full && p.ld_e()) {
            bank_ = bank_taking;
            p.samples_ready(false);
        }
        switch (state_) {
            case idle_st:
                take_request(p);
                break;
            case frame_st:
                p.frame_strobes(false);  // RG1, RG3-5, k_d*I and ambient latch
                set_ready(p, true);
                state_ = idle_st;
                break;
            case check_st:
                count_ = p.check_job();
                if (count_ == 0) {
                    ++dropped_;
                    set_ready(p, true);
                    p.ld_job(true);
                    state_ = idle_st;
                    break;
                }
                sample_ = 0;
                begin_sample(p);
                break;
            case low_st:  // strobe 17 has been low a clock: the device's settling phase
                if (wait_valid_) {
                    p.ctl17(true);  // validate: output 29 follows once the device is done
                    state_ = valid_st;
                    break;
                }
                if (bank_ != bank_free) break;  // the previous interval is still in the sample registers
                p.ctl17(true);
                latch_sample(p);
                break;
            case valid_st:
                if (bank_ != bank_free || !p.dev_valid()) break;
                latch_sample(p);
                break;
            case copy_st:  // the carried colour waits only for the sample registers
                if (bank_ != bank_free) break;
                p.carry_sel(false);
                ++carried_;
                latch_sample(p, false);
                break;
            case high_st:
                begin_sample(p);
                break;
        }
        // The last sample's latch is the edge where the next request can be taken: announce it one
        // clock ahead, once it is sure to happen there (the sample registers free by then).
        if (!wait_valid_ && (state_ == low_st || state_ == copy_st) && sample_ + 1 == count_ && bank_ != bank_full &&
            !ready_) {
            set_ready(p, true);
            p.ld_job(true);
        }
    }

    state current() const { return state_; }
    bank sample_bank() const { return bank_; }
    bool ready() const { return ready_; }
    bool wait_valid() const { return wait_valid_; }
    // Nothing taken and no interval waiting for the pixel controller.
    bool idle() const { return state_ == idle_st && bank_ != bank_full; }
    std::size_t jobs() const { return jobs_; }
    std::size_t dropped() const { return dropped_; }
    std::size_t samples() const { return samples_; }  // colours formed by the device
    std::size_t carried() const { return carried_; }  // colours taken from the last-sample registers

private:
    template <class Pins>
    void take_request(Pins& p) {
        if (p.load_frame()) {
            have_last_ = false;  // new frame constants: the last colour is not this frame's
            p.frame_strobes(true);
            set_ready(p, false);
            state_ = frame_st;
        } else if (p.start()) {
            set_ready(p, false);
            p.ld_job(false);  // the job registers latch the pins now
            p.smp_sel(0);
            ++jobs_;
            state_ = check_st;
        }
    }

    template <class Pins>
    void begin_sample(Pins& p) {
        if (sample_ == 0 && carry_ && have_last_ && p.carry_hit()) {
            p.carry_sel(true);  // the colour bus carries the last sample's colour
            state_ = copy_st;
        } else {
            p.ctl17(false);  // RG2 latches N.H of sample `sample_`
            state_ = low_st;
        }
        p.sample_strobe(sample_, count_, true);
        if (carry_) p.ld_last(true);
        if (sample_ + 1 == count_) p.ld_d(true);
    }

    template <class Pins>
    void latch_sample(Pins& p, bool formed = true) {
        p.sample_strobe(sample_, count_, false);  // I(K) takes ambient + diffuse + specular (or the carried colour)
        if (carry_) p.ld_last(false);             // and so do the last-sample registers, with its codes
        have_last_ = true;
        if (formed) ++samples_;
        if (++sample_ < count_) {
            p.smp_sel(sample_);
            state_ = high_st;
            return;
        }
        p.ld_d(false);  // the descriptor registers latch this job's y, x0, len, m, deg2
        p.samples_ready(true);
        bank_ = bank_full;
        state_ = idle_st;
        if (wait_valid_) {
            // Not announced ahead: the source learns it at the next rising edge.
            set_ready(p, true);
            p.ld_job(true);
            return;
        }
        take_request(p);  // the next job may be taken at this same edge (ready is 1 already)
    }

    template <class Pins>
    void set_ready(Pins& p, bool v) {
        ready_ = v;
        p.ready(v);
    }

    bool wait_valid_, carry_;
    bool have_last_ = false;
    state state_ = idle_st;
    bank bank_ = bank_free;
    bool ready_ = true;
    unsigned sample_ = 0, count_ = 0;
    std::size_t jobs_ = 0, dropped_ = 0, samples_ = 0, carried_ = 0;
};

}  // namespace shading::pipeline
