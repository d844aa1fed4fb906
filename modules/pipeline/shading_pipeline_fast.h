// The fast pin-level abstraction of the shading pipeline (issue 11; interp/abstraction.h): the pins
// of shading_pipeline<AGen, EVAL> and the same timing at them, one process for the whole unit.
//   - Same pins, same edges: `ready` changes at the same falling edges, px_valid / px_x / px_y at
//     the same rising edges, and px_r/g/b hold the pixel's codes at every rising edge where
//     px_valid = 1 (the frame buffer's sampling edges). Between those edges px_r/g/b hold the
//     last pixel (the block model shows the evaluator's partial sums through the clamp there).
//   - The controllers are the block model's (sample_ctrl.h, horner_pixel_ctrl.h with
//     horner_ctrl.h, fd_pixel_ctrl.h with fd_ctrl.h / fd_ctrl_var.h), stepped here as plain state
//     at each edge, every read seeing the value before the edge as a signal would.
//   - The datapath is one function call per interval: golden_interval() (src/pipeline/pipeline.h:
//     the device's specular term, the diffuse and ambient adders, the coefficient units and the
//     Horner unit or forward differences, the output clamp, from the shared format definitions),
//     with the frame constants latched at the edge the device's strobes would latch them.
// The device is named by scene::device_config (device and ADD11 overflow mode) instead of a
// generator type. Bit-exact with the block model (test_pipeline_fast: the frame, the write order
// and the pins at every edge) and with golden_frame (render_pipeline --abstraction fast).
#pragma once

#include <sstream>
#include <systemc>
#include <vector>

#include "core/report_ids.h"
#include "formats/interp_formats.h"
#include "formats/pipeline_formats.h"
#include "formats/specular_formats.h"
#include "formats/ua60553_formats.h"
#include "pipeline/pipe_eval.h"
#include "pipeline/pipeline.h"

namespace shading {

template <pipe_eval EVAL>
class shading_pipeline_fast : public sc_core::sc_module {
    static constexpr bool horner = EVAL == pipe_eval::horner;

public:
    using coord_t = sc_dt::sc_uint<16>;
    using len_t = sc_dt::sc_uint<16>;
    using m_t = sc_dt::sc_uint<4>;
    using bit_t = sc_dt::sc_uint<1>;
    using n_t = sc_dt::sc_uint<ua60553::n_fmt.width>;
    using cos_t = sc_dt::sc_uint<spec::cos_fmt.width>;
    using ksi_t = sc_dt::sc_uint<spec::ksi_fmt.width>;
    using kdi_t = sc_dt::sc_uint<pipeline::kdi_fmt.width>;
    using sample_t = sc_dt::sc_uint<interp::sample_fmt.width>;

    // Pins from the geometry side (shading_pipeline.h).
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> start{"start"}, load_frame{"load_frame"};
    sc_core::sc_out<bool> ready{"ready"};
    sc_core::sc_in<coord_t> in_y{"in_y"}, in_x0{"in_x0"};
    sc_core::sc_in<len_t> in_len{"in_len"};
    sc_core::sc_in<m_t> in_m{"in_m"};
    sc_core::sc_in<bit_t> in_deg2{"in_deg2"};
    sc_core::sc_in<cos_t> in_nh1{"in_nh1"}, in_nh2{"in_nh2"}, in_nh3{"in_nh3"}, in_nh4{"in_nh4"};
    sc_core::sc_in<cos_t> in_nl1{"in_nl1"}, in_nl2{"in_nl2"}, in_nl3{"in_nl3"}, in_nl4{"in_nl4"};
    // Frame constants.
    sc_core::sc_in<n_t> in_n{"in_n"};
    sc_core::sc_in<ksi_t> in_ksi_r{"in_ksi_r"}, in_ksi_g{"in_ksi_g"}, in_ksi_b{"in_ksi_b"};
    sc_core::sc_in<kdi_t> in_kdi_r{"in_kdi_r"}, in_kdi_g{"in_kdi_g"}, in_kdi_b{"in_kdi_b"};
    sc_core::sc_in<sample_t> in_amb_r{"in_amb_r"}, in_amb_g{"in_amb_g"}, in_amb_b{"in_amb_b"};
    // Pixel stream.
    sc_core::sc_out<bool> px_valid{"px_valid"};
    sc_core::sc_out<coord_t> px_x{"px_x"}, px_y{"px_y"};
    sc_core::sc_out<sample_t> px_r{"px_r"}, px_g{"px_g"}, px_b{"px_b"};

    SC_HAS_PROCESS(shading_pipeline_fast);
    // fd_m as shading_pipeline's: the forward differences' fixed interval length 2^fd_m, 0 for any m
    // per interval; ignored for Horner.
    shading_pipeline_fast(const sc_core::sc_module_name& name, const scene::device_config& dev,
                          interp::sample_set set, interp::div3_mode div, unsigned fd_m = 4)
        : sc_module(name), dev_(dev), set_(set), div_(div), fd_m_(horner ? 0 : fd_m) {
        SC_METHOD(on_edge);
        sensitive << clk;
        dont_initialize();
        ready.initialize(true);
        k_.n = 0;
    }

    // Nothing taken and not yet written out (shading_pipeline::idle()).
    bool idle() const {
        const bool sample_idle = state_ == idle_st && bank_ != bank_full;
        if constexpr (horner) return sample_idle && !cur_.active && !pend_.active && !ld_e_ && !in_flight_;
        else return sample_idle && !pend_.active && !ld_e_ && !start_ && left_ == 0 && f_rem_ == 0;
    }
    std::size_t jobs() const { return jobs_; }
    std::size_t dropped() const { return dropped_; }

private:
    using rgb = pipeline::rgb_codes;
    struct interval {
        bool active = false, deg2 = false;
        unsigned y = 0, x0 = 0, len = 0, m = 0, issued = 0;
        std::vector<rgb> px;  // golden_interval's codes of its pixels
    };
    enum state { idle_st, frame_st, check_st, low_st, high_st };
    enum bank { bank_free, bank_full, bank_taking };

    // Every edge of clk, but a falling edge where nothing can happen is skipped: the sample
    // controller waiting with its registers full for the pixel controller's ld_e (set only at rising
    // edges), and no pixel finishing in this clock. In a long interval that is most falling edges.
    void on_edge() {
        if (!clk.read()) {
            falling();
            return;
        }
        rising();
        const bool waiting = state_ == low_st && bank_ == bank_full && !ld_e_;
        const bool finishing = horner ? h_done_ : f_rem_ != 0;
        if (waiting && !finishing) next_trigger(clk.posedge_event());
    }

    // ---- Falling edges: sample_ctrl.h, and the evaluator's registers ----
    void falling() {
        if (bank_ == bank_taking) bank_ = bank_free;
        if (bank_ == bank_full && ld_e_) {
            bank_ = bank_taking;
            samples_ready_ = false;
        }
        switch (state_) {
            case idle_st:
                take_request();
                break;
            case frame_st:  // RG1, RG3-5, k_d*I and ambient latch (the device's frame strobes fall)
                k_.n = static_cast<unsigned>(in_n.read().to_uint());
                k_.ksi = {in_ksi_r.read().to_uint64(), in_ksi_g.read().to_uint64(), in_ksi_b.read().to_uint64()};
                k_.kdi = {in_kdi_r.read().to_uint64(), in_kdi_g.read().to_uint64(), in_kdi_b.read().to_uint64()};
                k_.ambient = {in_amb_r.read().to_uint64(), in_amb_g.read().to_uint64(), in_amb_b.read().to_uint64()};
                set_ready(true);
                state_ = idle_st;
                break;
            case check_st:
                if (!plan_job()) {
                    ++dropped_;
                    set_ready(true);
                    state_ = idle_st;
                    break;
                }
                sample_ = 0;
                state_ = low_st;  // begin_sample: ctl17 falls
                break;
            case low_st:
                if (bank_ != bank_free) break;
                if (++sample_ < count_) {
                    state_ = high_st;
                    break;
                }
                d_ = job_;  // ld_d falls: the descriptor (and the samples) for the pixel controller
                samples_ready_ = true;
                bank_ = bank_full;
                state_ = idle_st;
                take_request();
                break;
            case high_st:
                state_ = low_st;
                break;
        }
        if (state_ == low_st && sample_ + 1 == count_ && bank_ != bank_full && !ready_) set_ready(true);

        // The evaluator's output register latches the pixel it finishes in this clock.
        if constexpr (horner) {
            if (h_state_ != 0 && h_state_ == h_last_) write_px(flight_px_);
        } else {
            if (f_rem_ != 0) write_px(f_px_[f_len_ - f_rem_]);
        }
    }

    void set_ready(bool v) {
        ready_ = v;
        ready.write(v);
    }

    void take_request() {
        if (load_frame.read()) {
            set_ready(false);
            state_ = frame_st;
        } else if (start.read()) {
            set_ready(false);
            // The job registers latch the pins.
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
            ++jobs_;
            state_ = check_st;
        }
    }

    // sample_ctrl::plan_job's checks, then the interval's pixels through the golden pipeline.
    bool plan_job() {
        const unsigned mm = job_.m, n = job_.len;
        std::ostringstream os;
        if (mm != 0 && (mm < interp::m_min || mm > interp::m_max))
            os << "m = " << mm << " is neither 0 (exact pixel) nor " << interp::m_min << ".." << interp::m_max;
        else if (n == 0 || n > (1u << mm))
            os << "len = " << n << " is outside 1.." << (1u << mm) << " for m = " << mm;
        else if (mm == 0 && job_.deg2)
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
        count_ = mm == 0 ? 1 : (job_.deg2 ? 3 : 4);
        pipeline::interval_job j;
        j.len = n;
        j.m = mm;
        j.deg2 = job_.deg2;
        j.s = job_s_;
        job_.px = pipeline::golden_interval(j, k_, dev_, horner ? pipeline::evaluator::horner : pipeline::evaluator::fd,
                                            set_, div_);
        return true;
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
    state state_ = idle_st;
    bank bank_ = bank_free;
    bool ready_ = true, samples_ready_ = false;
    unsigned sample_ = 0, count_ = 0;
    std::size_t jobs_ = 0, dropped_ = 0;
    interval job_, d_;  // the job registers (with the samples' pixels) and the descriptor registers
    std::array<pipeline::sample_geometry, 4> job_s_{};
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
