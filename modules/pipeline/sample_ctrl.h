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
//   takes the request. Then one sample per two clocks, through the device's real strobe: smp_sel
//   picks the sample's N.H / N.L one clock ahead; ctl17 falls (RG2 latches in18), stays low one
//   clock (the device's settling phase T), rises (out29: outputs valid) while ld_iK falls and the
//   sample register I(K) takes ambient + diffuse + specular. An exact pixel (m = 0) is one sample
//   latched into all four registers at once, a quadratic three (I1..I3 at t = 0, 1/2, 1), a cubic
//   four.
// Handshake with the pixel controller: samples_ready = 1 when the four sample registers hold an
// interval; the pixel controller raises ld_e (it captures the job's descriptor then) and the
// interval registers latch when it falls; seeing ld_e = 1 this controller drops samples_ready and
// takes the next request, whose samples are latched no earlier than two clocks later.
// Bad input (shading/input): a job with m neither 0 nor m_min..m_max, len 0 or above 2^m, m = 0
// with deg2 (golden_interval refuses both), or, with
// the forward-difference evaluator built for M, an interval with m != M: reported and dropped (no
// sample, no pixel).
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
    sc_core::sc_out<bool> ready{"ready"}, ld_job{"ld_job"};
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

    bool idle() const { return state_ == idle_st; }
    std::size_t jobs() const { return jobs_; }
    std::size_t dropped() const { return dropped_; }
    std::size_t samples() const { return samples_; }

private:
    enum state { idle_st, frame_st, check_st, low_st, high_st, handoff_st };

    void on_clock() {
        switch (state_) {
            case idle_st:
                if (load_frame.read()) {
                    frame_strobes(true);
                    ready.write(false);
                    state_ = frame_st;
                } else if (start.read()) {
                    ready.write(false);
                    ld_job.write(false);  // the job registers latch the pins now
                    smp_sel.write(0);
                    ++jobs_;
                    state_ = check_st;
                }
                break;
            case frame_st:
                frame_strobes(false);  // RG1, RG3-5, k_d*I and ambient latch
                ready.write(true);
                state_ = idle_st;
                break;
            case check_st:
                if (!plan_job()) {
                    ++dropped_;
                    release();
                    break;
                }
                sample_ = 0;
                begin_sample();
                break;
            case low_st:  // the device's outputs have settled: validate and latch the sample
                ctl17.write(true);
                strobe(sample_, false);
                ++samples_;
                if (++sample_ < count_) {
                    smp_sel.write(sample_);
                    state_ = high_st;
                } else {
                    samples_ready.write(true);
                    state_ = handoff_st;
                }
                break;
            case high_st:
                begin_sample();
                break;
            case handoff_st:
                if (ld_e.read()) {  // the pixel controller took the interval (its registers latch next)
                    samples_ready.write(false);
                    release();
                }
                break;
        }
    }

    void begin_sample() {
        ctl17.write(false);  // RG2 latches N.H of sample `sample_`
        strobe(sample_, true);
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

    void release() {
        ready.write(true);
        ld_job.write(true);
        state_ = idle_st;
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
    unsigned sample_ = 0, count_ = 0;
    std::size_t jobs_ = 0, dropped_ = 0, samples_ = 0;
};

}  // namespace shading
