// Sample controller of the shading pipeline (ours; the interpolation paper leaves the control open): a clocked FSM
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
// A device that takes more than one clock (the squared-quadratic device): ctl17 rises after its
// clock low as before, but the sample latches at the first falling edge where output 29 (dev_valid)
// is high, and `ready` is raised at the job's last latch instead of a clock ahead of it.
// Bad input (shading/input): a job with m neither 0 nor m_min..m_max, len 0 or above 2^m, m = 0
// with deg2 (golden_interval refuses both), or, with the forward-difference evaluator built for M,
// an interval with m != M: reported and dropped (no sample, no pixel).
// Carry (ours, `carry` at construction): at a job whose first N.H / N.L codes equal the last sample's
// (carry_hit, the top's comparators), that sample's colour is not formed again: carry_sel = 1 puts the
// last-sample registers on the colour bus while ld_i1 (all four for an exact pixel) is low, and ctl17
// stays high. ld_last, low for a clock at every sample, latches each sample's colour and codes.
// The FSM is plain state (sample_fsm.h), stepped the same way by the fast pin-level pipeline.
#pragma once

#include <sstream>
#include <systemc>

#include "core/report_ids.h"
#include "core/timed_block.h"
#include "formats/interp_formats.h"
#include "pipeline/sample_fsm.h"

namespace shading {

class sample_ctrl : public sc_core::sc_module, public timed_block {
public:
    static constexpr unsigned len_bits = 16, m_bits = 4;
    using sel_t = sc_dt::sc_uint<2>;
    using bit_t = sc_dt::sc_uint<1>;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> start{"start"}, load_frame{"load_frame"};
    sc_core::sc_in<sc_dt::sc_uint<len_bits>> len{"len"};  // the job registers' outputs
    sc_core::sc_in<sc_dt::sc_uint<m_bits>> m{"m"};
    sc_core::sc_in<sc_dt::sc_uint<1>> deg2{"deg2"};
    sc_core::sc_in<bool> ld_e{"ld_e"};
    sc_core::sc_in<bool> dev_valid{"dev_valid"};  // the device's output 29 (read only with wait_valid)
    sc_core::sc_in<bool> carry_hit{"carry_hit"};  // the job's first codes are the last sample's (read only with carry)
    sc_core::sc_out<bool> ready{"ready"}, ld_job{"ld_job"}, ld_d{"ld_d"};
    sc_core::sc_out<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"}, ld_k{"ld_k"};
    sc_core::sc_out<sel_t> smp_sel{"smp_sel"};
    sc_core::sc_out<bool> ld_i1{"ld_i1"}, ld_i2{"ld_i2"}, ld_i3{"ld_i3"}, ld_i4{"ld_i4"};
    sc_core::sc_out<bool> samples_ready{"samples_ready"};
    sc_core::sc_out<bit_t> carry_sel{"carry_sel"};
    sc_core::sc_out<bool> ld_last{"ld_last"};

    SC_HAS_PROCESS(sample_ctrl);
    // fd_m: 0 for the Horner unit (any m), else the m the forward-difference evaluator is built for.
    // wait_valid: the device needs more than one clock (sample_fsm.h); carry: reuse the last sample's colour.
    sample_ctrl(const sc_core::sc_module_name& name, unsigned fd_m, bool wait_valid = false, bool carry = false)
        : sc_module(name), fd_m_(fd_m), fsm_(wait_valid, carry) {
        SC_METHOD(on_clock);
        sensitive << clk.neg();
        dont_initialize();
        ready.initialize(true);
        ld_job.initialize(true);
        ctl17.initialize(true);  // idle high: its first fall latches the first sample (Fig. 3)
    }

    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }
    const sc_core::sc_port_base* clock_port() const override { return &clk; }

    bool idle() const { return fsm_.idle(); }
    std::size_t jobs() const { return fsm_.jobs(); }
    std::size_t dropped() const { return fsm_.dropped(); }
    std::size_t samples() const { return fsm_.samples(); }
    std::size_t carried() const { return fsm_.carried(); }

private:
    // sample_fsm's view of the pins: reads see the values before the edge, writes drive the strobes.
    struct pins {
        sample_ctrl& c;
        bool start() const { return c.start.read(); }
        bool load_frame() const { return c.load_frame.read(); }
        bool ld_e() const { return c.ld_e.read(); }
        bool dev_valid() const { return c.dev_valid.read(); }
        unsigned check_job() const { return c.check_job(); }
        bool carry_hit() const { return c.carry_hit.read(); }
        void carry_sel(bool v) { c.carry_sel.write(bit_t(v ? 1 : 0)); }
        void ld_last(bool v) { c.ld_last.write(v); }
        void ready(bool v) { c.ready.write(v); }
        void ld_job(bool v) { c.ld_job.write(v); }
        void ld_d(bool v) { c.ld_d.write(v); }
        void ctl17(bool v) { c.ctl17.write(v); }
        void smp_sel(unsigned k) { c.smp_sel.write(sel_t(k)); }
        void samples_ready(bool v) { c.samples_ready.write(v); }
        void frame_strobes(bool v) {
            for (auto* s : {&c.ctl15, &c.ctl20, &c.ctl22, &c.ctl24, &c.ld_k}) s->write(v);
        }
        // Which sample registers sample k goes to: all four for an exact pixel, else I(k+1).
        void sample_strobe(unsigned k, unsigned count, bool v) {
            sc_core::sc_out<bool>* ld[] = {&c.ld_i1, &c.ld_i2, &c.ld_i3, &c.ld_i4};
            if (count == 1) {
                for (auto* l : ld) l->write(v);
            } else {
                ld[k]->write(v);
            }
        }
    };

    void on_clock() {
        pins p{*this};
        fsm_.falling(p);
    }

    unsigned check_job() const {
        const unsigned mm = m.read().to_uint(), n = len.read().to_uint();
        const bool d2 = deg2.read() == 1;
        const std::string problem = pipeline::job_problem(mm, n, d2, fd_m_);
        if (!problem.empty()) {
            std::ostringstream msg;
            msg << name() << ": job checked at " << sc_core::sc_time_stamp() << " (taken one clock before): " << problem
                << "; dropped (no pixel written)";
            SC_REPORT_WARNING(msg::input, msg.str().c_str());
            return 0;
        }
        return pipeline::job_samples(mm, d2);
    }

    unsigned fd_m_;
    pipeline::sample_fsm fsm_;
};

}  // namespace shading
