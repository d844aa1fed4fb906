// The fast pin-level abstraction of the shading pipeline (interp/abstraction.h): the pins
// of shading_pipeline<AGen, EVAL> and the same timing at them, one process for the whole unit.
//   - Same pins, same edges: `ready` changes at the same falling edges, px_valid / px_x / px_y at
//     the same rising edges, and px_r/g/b hold the pixel's codes at every rising edge where
//     px_valid = 1 (the frame buffer's sampling edges). Between those edges px_r/g/b hold the
//     last pixel (the block model shows the evaluator's partial sums through the clamp there).
//   - The controllers are the block model's (sample_fsm.h, the sample controller's own plain state;
//     horner_pixel_ctrl.h with horner_ctrl.h, fd_pixel_ctrl.h with fd_ctrl.h / fd_ctrl_var.h),
//     stepped here at each edge, every read seeing the value before the edge as a signal would. With
//     the squared-quadratic device the sample controller waits for output 29, which that device
//     raises k + 4 clocks after its strobe (k = its squarings for the frame's n; two clocks for
//     its synchroniser), the square-and-multiply device floor(log2 n) + popcount(n) + 3 clocks
//     after it (the same synchroniser): counted here.
//   - The datapath is one function call per interval: interval_pixels() (src/floor/arith/
//     pipeline_arith.h, what the golden pipeline's golden_interval() computes: the device's specular
//     term, the diffuse and ambient adders, the coefficient units and the Horner unit or forward
//     differences, the output clamp, from the shared format definitions), with the frame constants
//     latched at the edge the device's strobes would latch them. The golden pipeline's header
//     (src/golden_pipeline/pipeline.h) is not included: it pulls in the rasteriser (docs/layers.md).
// With `carry` the sample controller's carry (sample_fsm.h) compares the job's first codes with the
// last sample's, as the block model's comparators do; the carried colour is the one interval_pixels
// forms from the same codes, so only the controller's timing and counts change.
// The device is named by scene::device_config (device and ADD11 overflow mode) instead of a
// generator type. Bit-exact with the block model (test_pipeline_fast: the frame, the write order
// and the pins at every edge) and with golden_frame (render_pipeline --abstraction fast).
#pragma once

#include <sstream>
#include <systemc>
#include <vector>

#include "arith/pipeline_arith.h"
#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "core/report_ids.h"
#include "formats/interp_formats.h"
#include "formats/pipeline_formats.h"
#include "formats/specular_formats.h"
#include "formats/ua60553_formats.h"
#include "pipeline/pipeline_pins.h"
#include "pipeline/sample_fsm.h"
#include "squared/sq_count.h"

namespace shading {

// shading_pipeline's pins (pipeline_pins.h).
template <pipeline::evaluator EVAL>
class shading_pipeline_fast : public sc_core::sc_module, public pipeline_pins {
    static constexpr bool horner = EVAL == pipeline::evaluator::horner;

public:
    SC_HAS_PROCESS(shading_pipeline_fast);
    // fd_m as shading_pipeline's: the forward differences' fixed interval length 2^fd_m, 0 for any m
    // per interval; ignored for Horner.
    shading_pipeline_fast(const sc_core::sc_module_name& name, const scene::device_config& dev,
                          interp::sample_set set, interp::div3_mode div, unsigned fd_m = 4, bool carry = false)
        : sc_module(name), dev_(dev), set_(set), div_(div), fd_m_(horner ? 0 : fd_m),
          fsm_(dev.device == scene::specular_device::squared || dev.device == scene::specular_device::sqmul, carry) {
        SC_METHOD(on_edge);
        sensitive << clk;
        dont_initialize();
        ready.initialize(true);
        k_.n = 0;
    }

    // Nothing taken and not yet written out (shading_pipeline::idle()).
    bool idle() const {
        const bool sample_idle = fsm_.idle();
        if constexpr (horner) return sample_idle && !cur_.active && !pend_.active && !ld_e_ && !in_flight_;
        else return sample_idle && !pend_.active && !ld_e_ && !start_ && left_ == 0 && f_rem_ == 0;
    }
    std::size_t jobs() const { return fsm_.jobs(); }
    std::size_t dropped() const { return fsm_.dropped(); }
    std::size_t samples() const { return fsm_.samples(); }
    std::size_t carried() const { return fsm_.carried(); }

private:
    using rgb = pipeline::rgb_codes;
    struct interval {
        bool active = false, deg2 = false;
        unsigned y = 0, x0 = 0, len = 0, m = 0, issued = 0;
        std::vector<rgb> px;  // interval_pixels' codes of its pixels
    };

    // Every edge of clk, but a falling edge where nothing can happen is skipped: the sample
    // controller waiting with its registers full for the pixel controller's ld_e (set only at rising
    // edges), and no pixel finishing in this clock. In a long interval that is most falling edges.
    void on_edge() {
        if (!clk.read()) {
            falling();
            return;
        }
        rising();
        const auto st = fsm_.current();
        const bool waiting = (st == pipeline::sample_fsm::low_st || st == pipeline::sample_fsm::copy_st) &&
                             fsm_.sample_bank() == pipeline::sample_fsm::bank_full && !ld_e_ && !fsm_.wait_valid();
        const bool finishing = horner ? h_done_ : f_rem_ != 0;
        if (waiting && !finishing) next_trigger(clk.posedge_event());
    }

    // ---- Falling edges: the sample controller (sample_fsm.h), and the evaluator's registers ----
    // sample_fsm's view of the pins: the job and frame registers latch where their strobes fall.
    struct pins {
        shading_pipeline_fast& u;
        bool start() const { return u.start.read(); }
        bool load_frame() const { return u.load_frame.read(); }
        bool ld_e() const { return u.ld_e_; }
        // A clocked device's output 29, high from the dev_clocks_-th falling edge after its strobe
        // fell (its done rises at that rising edge: sync17's two, the taking edge and the done edge
        // counted).
        bool dev_valid() const { return u.edges_ - u.strobe_edge_ >= u.dev_clocks_; }
        unsigned check_job() const { return u.check_job(); }
        void ready(bool v) { u.ready.write(v); }
        void ld_job(bool v) {
            if (!v) u.take_job();
        }
        void ld_d(bool v) {
            if (!v) u.d_ = u.job_;  // the descriptor (and the samples) for the pixel controller
        }
        void ctl17(bool v) {
            if (!v) u.strobe_edge_ = u.edges_;
        }
        void frame_strobes(bool v) {
            if (!v) u.latch_frame();
        }
        void smp_sel(unsigned) {}
        // The last-sample registers: the codes of the sample latched here (rg_lnh, rg_lnl).
        void sample_strobe(unsigned k, unsigned, bool v) {
            if (!v) u.last_s_ = u.job_s_[k];
        }
        bool carry_hit() const { return u.job_s_[0] == u.last_s_; }
        void carry_sel(bool) {}
        void ld_last(bool) {}
        void samples_ready(bool v) { u.samples_ready_ = v; }
    };

    void falling() {
        ++edges_;
        pins p{*this};
        fsm_.falling(p);

        // The evaluator's output register latches the pixel it finishes in this clock.
        if constexpr (horner) {
            if (h_state_ != 0 && h_state_ == h_last_) write_px(flight_px_);
        } else {
            if (f_rem_ != 0) write_px(f_px_[f_len_ - f_rem_]);
        }
    }

    // Rising edges from strobe 17's fall to done (sync17's and the taking edge counted): the
    // squared-quadratic device's sync17 stages, taking edge, k squares, done (sq_count.h); the
    // square-and-multiply device's sync17 stages, taking edge, one per square and per
    // multiplication, done (sqmul_count.h).
    uint64_t device_clocks(unsigned n) const {
        if (dev_.device == scene::specular_device::sqmul) {
            const auto g = golden_sqmul(n, 0, {0, 0, 0}, dev_.mode);
            return g.squares + g.multiplies + sqmul::sync_stages + 2;
        }
        return squared::sq_count::squarings(static_cast<unsigned>(golden_squared_a(n).z)) + squared::sync_stages + 2;
    }

    // RG1, RG3-5, k_d*I and ambient: the device's frame strobes fall.
    void latch_frame() {
        k_.n = static_cast<unsigned>(in_n.read().to_uint());
        k_.ksi = {in_ksi_r.read().to_uint64(), in_ksi_g.read().to_uint64(), in_ksi_b.read().to_uint64()};
        k_.kdi = {in_kdi_r.read().to_uint64(), in_kdi_g.read().to_uint64(), in_kdi_b.read().to_uint64()};
        k_.ambient = {in_amb_r.read().to_uint64(), in_amb_g.read().to_uint64(), in_amb_b.read().to_uint64()};
        dev_clocks_ = device_clocks(k_.n);
    }

    // The job registers latch the pins.
    void take_job() {
        job_.y = static_cast<unsigned>(in_y.read().to_uint());
        job_.x0 = static_cast<unsigned>(in_x0.read().to_uint());
        job_.len = static_cast<unsigned>(in_len.read().to_uint());
        job_.m = static_cast<unsigned>(in_m.read().to_uint());
        job_.deg2 = in_deg2.read() == 1;
        const sc_core::sc_in<cos_t>* nh[] = {&in_nh1, &in_nh2, &in_nh3, &in_nh4};
        const sc_core::sc_in<cos_t>* nl[] = {&in_nl1, &in_nl2, &in_nl3, &in_nl4};
        for (int i = 0; i < 4; ++i) {
            job_s_[i].cos_nh = static_cast<uint32_t>((*nh[i])->read().to_uint());
            job_s_[i].cos_nl = static_cast<uint32_t>((*nl[i])->read().to_uint());
        }
    }

    // sample_ctrl's check (sample_fsm.h's job_problem), then the interval's pixels through the
    // floor's interval arithmetic (the golden pipeline's). Returns the job's samples, 0 for a dropped job.
    unsigned check_job() {
        const std::string problem = pipeline::job_problem(job_.m, job_.len, job_.deg2, fd_m_);
        if (!problem.empty()) {
            std::ostringstream msg;
            msg << name() << ": job checked at " << sc_core::sc_time_stamp() << " (taken one clock before): " << problem
                << "; dropped (no pixel written)";
            SC_REPORT_WARNING(msg::input, msg.str().c_str());
            return 0;
        }
        pipeline::interval_job j;
        j.len = job_.len;
        j.m = job_.m;
        j.deg2 = job_.deg2;
        j.s = job_s_;
        job_.px = pipeline::interval_pixels(j, k_, dev_, EVAL, set_, div_);
        return pipeline::job_samples(job_.m, job_.deg2);
    }

    void write_px(const rgb& v) {
        px_r.write(sample_t(v[0]));
        px_g.write(sample_t(v[1]));
        px_b.write(sample_t(v[2]));
    }

    // ---- Rising edges: the evaluator's controller and the pixel controller ----
    void rising() {
        if constexpr (horner) rising_horner();
        else rising_fd();
    }

    void rising_horner() {
        // Values before this edge.
        const bool dn = h_done_, bz = h_busy_, st = start_, d2 = deg2_;
        // horner_ctrl.h (channel R's; the three units run in step).
        const bool finishing = h_state_ != 0 && h_state_ == h_last_;
        unsigned next = 0;
        if (st && (h_state_ == 0 || finishing)) next = 1;
        else if (h_state_ != 0 && !finishing) next = h_state_ + 1;
        if (next == 1) h_last_ = 6;
        if (next == 4 && d2) h_last_ = 4;
        h_state_ = next;
        h_done_ = h_state_ != 0 && h_state_ == h_last_;
        h_busy_ = h_state_ != 0;

        // horner_pixel_ctrl.h.
        if (dn) in_flight_ = false;
        if (start_ && (!bz || dn)) {
            if (cur_.issued == cur_.len && pend_.active) {
                std::swap(cur_, pend_);
                pend_.active = false;
                deg2_ = cur_.deg2;
            }
            flight_px_ = cur_.px[cur_.issued];
            px_x.write(coord_t(cur_.x0 + cur_.issued));
            px_y.write(coord_t(cur_.y));
            ++cur_.issued;
            in_flight_ = true;
            if (cur_.issued == cur_.len) {
                cur_.active = false;
                free_in_ = (cur_.deg2 ? 4 : 6) - 2;
            }
            start_ = cur_.active || pend_.active;
        } else if (free_in_ > 0) {
            --free_in_;
        }
        hand_over();
        px_valid.write(h_done_);
    }

    void rising_fd() {
        const bool vl = f_rem_ != 0, ls = f_rem_ == 1, st = start_;
        // fd_ctrl.h / fd_ctrl_var.h: takes the pending interval (the pixel controller's, below).
        if (st && f_rem_ <= 1) {
            f_len_ = pend_.len;  // the len pin, set where ld_e fell (checked by the sample controller)
            f_rem_ = f_len_;
            f_px_.swap(pend_.px);
        } else if (f_rem_ > 1) {
            --f_rem_;
        } else {
            f_rem_ = 0;
        }
        // fd_pixel_ctrl.h.
        if (st && (!vl || ls)) {
            cur_ = pend_;
            pend_.active = false;
            start_ = false;
            px_x.write(coord_t(cur_.x0));
            px_y.write(coord_t(cur_.y));
            next_ = 1;
            left_ = cur_.len - 1;
        } else if (left_ > 0) {
            px_x.write(coord_t(cur_.x0 + next_));
            ++next_;
            --left_;
        }
        hand_over();
        px_valid.write(f_rem_ != 0);
    }

    // The interval hand-over of both pixel controllers: ld_e for one clock, the descriptor captured
    // where it rises (Horner: only when no interval is pending or running and the registers are free).
    void hand_over() {
        if (ld_e_) {
            ld_e_ = false;
            std::swap(pend_, captured_);
            start_ = true;
        } else if (samples_ready_ && !pend_.active && (!horner || (!cur_.active && free_in_ == 0))) {
            ld_e_ = true;
            captured_ = d_;
            captured_.active = true;
            captured_.issued = 0;
        }
    }

    scene::device_config dev_;
    interp::sample_set set_;
    interp::div3_mode div_;
    unsigned fd_m_;
    pipeline::frame_constants k_;
    // Sample controller.
    pipeline::sample_fsm fsm_;
    bool samples_ready_ = false;
    uint64_t edges_ = 0, strobe_edge_ = 0;  // falling edges so far; the last one strobe 17 fell at
    uint64_t dev_clocks_ = 4;               // a clocked device's clocks per sample for the frame's n
    interval job_, d_;  // the job registers (with the samples' pixels) and the descriptor registers
    std::array<pipeline::sample_geometry, 4> job_s_{};
    pipeline::sample_geometry last_s_{};  // the last sample's codes
    // Pixel controller.
    interval cur_, pend_, captured_;
    bool start_ = false, ld_e_ = false, in_flight_ = false, deg2_ = false;
    unsigned free_in_ = 0, next_ = 0, left_ = 0;
    // Evaluator controller: Horner (state, last step, done, busy, the pixel in flight) or forward
    // differences (pixels remaining, length, the interval's pixels).
    unsigned h_state_ = 0, h_last_ = 6;
    bool h_done_ = false, h_busy_ = false;
    rgb flight_px_{};
    unsigned f_rem_ = 0, f_len_ = 0;
    std::vector<rgb> f_px_;
};

}  // namespace shading
