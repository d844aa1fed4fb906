// Sample controller of the shading pipeline (ours; seed 004 leaves the control open): a clocked FSM
// on the FALLING edge of clk, so every strobe it drives falls at a falling edge, half a clock away
// from the rising edges where the geometry side changes the pins and the pixel controller acts.
//
// Handshake with the geometry side (decision). `ready` changes only at falling edges. A request is
// taken at a falling edge where it is present and ready = 1, so a source that changes its pins at
// rising edges knows at the rising edge before it (ready = 1 then) and must hold them across that
// falling edge; it may present the next request from the next rising edge on.
// - load_frame = 1: the frame constants (n, k_s*I, k_d*I, ambient) are latched one clock after
//   the request is taken, by the device's own strobes ctl15, ctl20, ctl22, ctl24 (UA 60553, Fig. 3)
//   and ld_k for k_d*I and the ambient term; the pins must stay stable until ready returns.
// - start = 1 (an interval): the job registers latch its pins where ld_job falls, at the edge that
//   takes the request. A clock later the job is checked and its first sample starts; one sample per
//   two clocks, through the device's real strobe: smp_sel picks the sample's N.H / N.L one clock
//   ahead; ctl17 falls (RG2 latches in18), stays low at least one clock (the device's settling phase
//   T), rises (out29: outputs valid) while ld_iK falls and the sample register I(K) takes ambient +
//   diffuse + specular. An exact pixel (m = 0) is one sample latched into all four registers at
//   once, a quadratic three (I1..I3 at t = 0, 1/2, 1), a cubic four. At the last sample's latch the
//   descriptor registers take the job's y, x0, len, m, deg2 (ld_d falls) and the next request can
//   be taken at that same edge (ready rises a clock before): 2 clocks per exact pixel, 6 per
//   quadratic, 8 per cubic interval, while the pixel controller keeps up.
// Handshake with the pixel controller: samples_ready = 1 when the sample registers and the
// descriptor registers hold an interval; the pixel controller raises ld_e for a clock and the
// interval registers latch where it falls. Seeing ld_e = 1 this controller drops samples_ready; the
// next interval's samples latch no earlier than the falling edge after the interval registers did
// (until then ctl17 stays low and ready stays 0).
// Bad input (shading/input): a job with m neither 0 nor m_min..m_max, len 0 or above 2^m, m = 0
// with deg2 (golden_interval refuses both), or, with the forward-difference evaluator built for M,
// an interval with m != M: reported and dropped (no sample, no pixel).
#pragma once

#include <sstream>
#include <systemc>

#include "core/report_ids.h"
#include "core/timed_block.h"
#include "formats/interp_formats.h"

namespace shading {

class sample_ctrl : public sc_core::sc_module, public timed_block {
public:
    static constexpr unsigned len_bits = 16, m_bits = 4;
    using sel_t = sc_dt::sc_uint<2>;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> start{"start"}, load_frame{"load_frame"};
    sc_core::sc_in<sc_dt::sc_uint<len_bits>> len{"len"};  // the job registers' outputs
    sc_core::sc_in<sc_dt::sc_uint<m_bits>> m{"m"};
    sc_core::sc_in<sc_dt::sc_uint<1>> deg2{"deg2"};
    sc_core::sc_in<bool> ld_e{"ld_e"};
    sc_core::sc_out<bool> ready{"ready"}, ld_job{"ld_job"}, ld_d{"ld_d"};
    sc_core::sc_out<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"}, ld_k{"ld_k"};
    sc_core::sc_out<sel_t> smp_sel{"smp_sel"};
    sc_core::sc_out<bool> ld_i1{"ld_i1"}, ld_i2{"ld_i2"}, ld_i3{"ld_i3"}, ld_i4{"ld_i4"};
    sc_core::sc_out<bool> samples_ready{"samples_ready"};

    SC_HAS_PROCESS(sample_ctrl);
    // fd_m: 0 for the Horner unit (any m), else the m the forward-difference evaluator is built for.
    sample_ctrl(const sc_core::sc_module_name& name, unsigned fd_m) : sc_module(name), fd_m_(fd_m) {
        SC_METHOD(on_clock);
        sensitive << clk.neg();
        dont_initialize();
        ready.initialize(true);
        ld_job.initialize(true);
        ctl17.initialize(true);  // idle high: its first fall latches the first sample (Fig. 3)
    }

    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }
    const sc_core::sc_port_base* clock_port() const override { return &clk; }

    // Nothing taken and no interval waiting for the pixel controller.
    bool idle() const { return state_ == idle_st && bank_ != bank_full; }
    std::size_t jobs() const { return jobs_; }
    std::size_t dropped() const { return dropped_; }
    std::size_t samples() const { return samples_; }

private:
    enum state { idle_st, frame_st, check_st, low_st, high_st };
    // The sample registers' interval: free, full (samples_ready = 1), or being taken (ld_e seen at
    // this edge: the interval registers latch half a clock later, the sample registers not before).
    enum bank { bank_free, bank_full, bank_taking };

    void on_clock() {
        if (bank_ == bank_taking) bank_ = bank_free;
        if (bank_ == bank_full && ld_e.read()) {
            bank_ = bank_taking;
            samples_ready.write(false);
        }
        switch (state_) {
            case idle_st:
                take_request();
                break;
            case frame_st:
                frame_strobes(false);  // RG1, RG3-5, k_d*I and ambient latch
                ready.write(true);
                ready_ = true;
                state_ = idle_st;
                break;
            case check_st:
                if (!plan_job()) {
                    ++dropped_;
                    ready.write(true);
                    ld_job.write(true);
                    ready_ = true;
                    state_ = idle_st;
                    break;
                }
                sample_ = 0;
                begin_sample();
                break;
            case low_st:  // the device's outputs have settled: validate and latch the sample
                if (bank_ != bank_free) break;  // the previous interval is still in the sample registers
                ctl17.write(true);
                strobe(sample_, false);
                ++samples_;
                if (++sample_ < count_) {
                    smp_sel.write(sample_);
                    state_ = high_st;
                    break;
                }
                ld_d.write(false);  // the descriptor registers latch this job's y, x0, len, m, deg2
                samples_ready.write(true);
                bank_ = bank_full;
                state_ = idle_st;
                take_request();  // the next job may be taken at this same edge (ready is 1 already)
                break;
            case high_st:
                begin_sample();
                break;
        }
        // The last sample's latch is the edge where the next request can be taken: announce it one
        // clock ahead, once it is sure to happen there (the sample registers free by then).
        if (state_ == low_st && sample_ + 1 == count_ && bank_ != bank_full && !ready_) {
            ready.write(true);
            ld_job.write(true);
            ready_ = true;
        }
    }

    void take_request() {
        if (load_frame.read()) {
            frame_strobes(true);
            ready.write(false);
            ready_ = false;
            state_ = frame_st;
        } else if (start.read()) {
            ready.write(false);
            ready_ = false;
            ld_job.write(false);  // the job registers latch the pins now
            smp_sel.write(0);
            ++jobs_;
            state_ = check_st;
        }
    }

    void begin_sample() {
        ctl17.write(false);  // RG2 latches N.H of sample `sample_`
        strobe(sample_, true);
        if (sample_ + 1 == count_) ld_d.write(true);
        state_ = low_st;
    }

    // Which sample registers sample k goes to: all four for an exact pixel, else I(k+1).
    void strobe(unsigned k, bool level) {
        sc_core::sc_out<bool>* ld[] = {&ld_i1, &ld_i2, &ld_i3, &ld_i4};
        if (count_ == 1) {
            for (auto* l : ld) l->write(level);
        } else {
            ld[k]->write(level);
        }
    }

    void frame_strobes(bool level) {
        for (auto* s : {&ctl15, &ctl20, &ctl22, &ctl24, &ld_k}) s->write(level);
    }

    bool plan_job() {
        const unsigned mm = m.read().to_uint(), n = len.read().to_uint();
        std::ostringstream os;
        if (mm != 0 && (mm < interp::m_min || mm > interp::m_max))
            os << "m = " << mm << " is neither 0 (exact pixel) nor " << interp::m_min << ".." << interp::m_max;
        else if (n == 0 || n > (1u << mm))
            os << "len = " << n << " is outside 1.." << (1u << mm) << " for m = " << mm;
        else if (mm == 0 && deg2.read() == 1)
            os << "an exact pixel (m = 0) is cubic, not quadratic";
        else if (fd_m_ != 0 && mm != 0 && mm != fd_m_)
            os << "m = " << mm << " but the forward-difference evaluator is built for m = " << fd_m_;
        if (!os.str().empty()) {
            std::ostringstream msg;
            msg << name() << ": job checked at " << sc_core::sc_time_stamp() << " (taken one clock before): " << os.str()
                << "; dropped (no pixel written)";
            SC_REPORT_WARNING(msg::input, msg.str().c_str());
            return false;
        }
        count_ = mm == 0 ? 1 : (deg2.read() == 1 ? 3 : 4);
        return true;
    }

    unsigned fd_m_;
    state state_ = idle_st;
    bank bank_ = bank_free;
    bool ready_ = true;
    unsigned sample_ = 0, count_ = 0;
    std::size_t jobs_ = 0, dropped_ = 0, samples_ = 0;
};

}  // namespace shading
