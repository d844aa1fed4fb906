// Testbench parts for the specular-colour devices (UA 60553 and its prototype UA 22802), in three
// pieces reused by the testbench programs and the GoogleTest suites:
//   specular_stimulus - drives the pins as in UA 60553, Fig. 3: per surface, n and k_s*I through
//                       their strobes (all four, or the ones a random reload picks); then per
//                       pixel, cos on in18, ctl17 falls (latch) and rises (validate);
//   specular_monitor  - watches the pins like a logic analyser: records what each register
//                       latched at its falling edge and samples out25..27 at every rising edge of
//                       out29 that follows a latch;
//   specular_checker  - compares every sample with the golden model and with cos^n.
// random_surfaces() makes the random differential mode's stream (bench_runner.h, --random).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <systemc>
#include <type_traits>
#include <vector>

#include "reference/brdf_reference.h"
#include "formats/specular_formats.h"
#include "arith/specular_arith.h"
#include "formats/ua60553_formats.h"
#include "core/report_ids.h"
#include "testbenches/common/bench_source.h"
#include "specular/fig1_pins.h"

namespace shading::tb {

using n_t = sc_dt::sc_uint<ua60553::n_fmt.width>;
using cos_t = sc_dt::sc_uint<spec::cos_fmt.width>;
using ksi_t = sc_dt::sc_uint<spec::ksi_fmt.width>;
using out_t = sc_dt::sc_uint<spec::out_fmt.width>;

struct surface {
    unsigned n = 0;
    std::array<unsigned, 3> ksi{};    // k_s*I for R, G, B
    std::vector<uint32_t> cos_codes;  // streamed on in18, one per ctl17 period
    // Which of RG1 (n), RG3, RG4, RG5 (k_s*I R, G, B) this surface loads; the others keep the
    // previous surface's value (a random reload between pixels).
    std::array<bool, 4> reload{true, true, true, true};
};

// The random differential stream: `pixels` random cos codes (0..1.0) in surfaces of 1..16
// pixels; between two surfaces a random non-empty subset of n (1..1000) and the three k_s*I
// (0..255) is reloaded through its strobe (the first surface loads all four). Item i depends
// only on (seed, i), so the stream is generated as the stimulus reads it.
inline item_source<surface> random_surfaces(std::size_t pixels, uint64_t seed) {
    const random_runs runs(pixels, 16, seed);
    return item_source<surface>(runs.count(), [=](std::size_t i) {
        split_rng r(seed, i);
        surface s;
        s.n = static_cast<unsigned>(r.range(1, 1000));
        for (auto& k : s.ksi) k = static_cast<unsigned>(r.range(0, 255));
        if (i > 0) {
            do {
                for (auto& b : s.reload) b = r.coin();
            } while (!(s.reload[0] || s.reload[1] || s.reload[2] || s.reload[3]));
        }
        for (std::size_t p = 0; p < runs.length(i); ++p)
            s.cos_codes.push_back(static_cast<uint32_t>(r.range(0, spec::cos_one)));
        return s;
    });
}

// Strobe timing of Fig. 3. A pixel takes t_high + t_low: cos changes in the middle of the high
// phase, ctl17 falls (latch), stays low for t_low (the settling phase T), rises (outputs valid).
struct strobe_timing {
    sc_core::sc_time t_low{15, sc_core::SC_NS};
    sc_core::sc_time t_high{5, sc_core::SC_NS};
    sc_core::sc_time load_pulse{4, sc_core::SC_NS};  // width of a ctl15/20/22/24 pulse
    // How long before the latching edge in18 changes; zero makes it change at the edge (a setup
    // violation, for the tests of that bad input). Negative values are not allowed.
    sc_core::sc_time cos_lead = t_high / 2;
    // The clock of a device with a `clk` pin (the squared-quadratic device's squaring stage; the
    // bench makes an sc_clock of this period and duty cycle, first rising edge at 0); others have none.
    sc_core::sc_time clk_period{20, sc_core::SC_NS};
    double clk_duty = 0.5;
};

// Fig. 3 for the squared-quadratic device: output 29 rises at most 13 clocks after strobe 17 fell
// (k = 9: the synchroniser's two rising edges, the taking edge, 9 squares, the done edge), so a
// pixel period of 15 clocks (14 low, 1 high) never strobes before the previous result is valid.
inline strobe_timing squared_timing(const sc_core::sc_time& clk_period = sc_core::sc_time(20, sc_core::SC_NS)) {
    strobe_timing t;
    t.clk_period = clk_period;
    t.t_low = 14 * clk_period;
    t.t_high = clk_period;
    t.cos_lead = t.t_high / 2;
    return t;
}

// Fig. 3 for the square-and-multiply device: output 29 rises at most 22 clocks after strobe 17
// fell (n = 1023: the synchroniser's two rising edges, the taking edge, 9 squares,
// 9 multiplications, the done edge), so a pixel period of 24 clocks (23 low, 1 high) never strobes
// before the previous result is valid (nor for the right-to-left design, at most 14).
inline strobe_timing sqmul_timing(const sc_core::sc_time& clk_period = sc_core::sc_time(20, sc_core::SC_NS)) {
    strobe_timing t = squared_timing(clk_period);
    t.t_low = 23 * clk_period;
    return t;
}

// Strobe 17 at every phase of the squared-quadratic device's clock: a pixel period of `clocks`
// clocks plus `step`, so each strobe falls `step` later in the clock's period than the one before
// (surface loads shift it by 8 ns each), strobe 17 low for `low` only (output 29 then rises with
// done). The stimulus loads the next surface (and ends the run) half the high phase after strobe
// 17 rose, so `clocks` must be at least twice the longest result's rising edges: every result is
// then valid before. With a clock of whole nanoseconds, a 0.5 ns step and the
// default 5.5 ns low phase every fall lands on the 0.5 ns grid (it comes half a high phase,
// (clocks x period - 5 ns) / 2, into each pixel), so the clock's edges are among the phases.
inline strobe_timing phase_sweep_timing(unsigned clocks, const sc_core::sc_time& step,
                                        const sc_core::sc_time& clk_period, double duty = 0.5,
                                        const sc_core::sc_time& low = sc_core::sc_time(5500, sc_core::SC_PS)) {
    strobe_timing t;
    t.clk_period = clk_period;
    t.clk_duty = duty;
    t.t_low = low;
    t.t_high = clk_period * static_cast<double>(clocks) + step - low;
    t.cos_lead = t.t_high / 2;
    return t;
}

// Whether a device has a clock pin (the bench then drives it).
template <typename D, typename = void>
struct has_clk : std::false_type {};
template <typename D>
struct has_clk<D, std::void_t<decltype(std::declval<D&>().clk)>> : std::true_type {};

struct pixel_sample {
    uint64_t n = 0, cos = 0;
    std::array<uint64_t, 3> ksi{}, out{};
    sc_core::sc_time at;
};

class specular_stimulus : public sc_core::sc_module {
public:
    sc_core::sc_out<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_out<n_t> in16_n{"in16_n"};
    sc_core::sc_out<cos_t> in18_cos{"in18_cos"};
    sc_core::sc_out<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};

    SC_HAS_PROCESS(specular_stimulus);
    specular_stimulus(const sc_core::sc_module_name& name, item_source<surface> surfaces, strobe_timing t)
        : sc_module(name), surfaces_(std::move(surfaces)), t_(t) {
        if (const auto* list = surfaces_.list())
            for (const auto& s : *list) pixels_ += s.cos_codes.size();
        // A method stepping through Fig. 3 with next_trigger: the same pin waveform as a thread's
        // waits, without a coroutine switch per edge (a large share of a fast model's run).
        SC_METHOD(run);
    }

    bool finished() const { return finished_; }
    // Pixels of the stream (of a generated stream: the pixels streamed so far).
    std::size_t pixels() const { return surfaces_.list() ? pixels_ : streamed_; }
    // Simulated time the whole stream takes (for watchdogs): 4 loads per surface, then pixels.
    // A generated stream's length is not known in advance: run it until it stops.
    sc_core::sc_time duration() const {
        if (!surfaces_.list()) return sc_core::sc_max_time();
        return t_.t_high + t_.load_pulse * (8.0 * static_cast<double>(surfaces_.size())) +
               (t_.t_low + t_.t_high) * static_cast<double>(pixels());
    }

private:
    enum class step { start, surface, load, load_fall, pixel, pixel_cos, pixel_fall, pixel_rise };

    // Idle ctl17 high; per surface the chosen loads (data and strobe up, strobe down after
    // load_pulse: the register latches, load_pulse more); per pixel cos on in18 cos_lead before
    // ctl17 falls (latch), t_low later ctl17 rises (out29: outputs 25..27 valid), t_high / 2 more.
    void run() {
        for (;;) switch (step_) {
            case step::start:
                ctl17.write(true);  // idle high: the first falling edge latches the first pixel
                step_ = step::surface;
                next_trigger(t_.t_high);
                return;
            case step::surface:
                if (surface_ == surfaces_.size()) {
                    finished_ = true;
                    sc_core::sc_stop();
                    return;
                }
                s_ = &surfaces_[surface_];
                load_ = 0;
                step_ = step::load;
                break;
            case step::load:
                while (load_ < 4 && !s_->reload[load_]) ++load_;
                if (load_ == 4) {
                    streamed_ += s_->cos_codes.size();
                    pixel_ = 0;
                    step_ = step::pixel;
                    break;
                }
                if (load_ == 0) in16_n.write(n_t(s_->n));
                else (load_ == 1 ? in19_ksi_r : load_ == 2 ? in21_ksi_g : in23_ksi_b).write(ksi_t(s_->ksi[load_ - 1]));
                load_ctl().write(true);
                step_ = step::load_fall;
                next_trigger(t_.load_pulse);
                return;
            case step::load_fall:
                load_ctl().write(false);  // falling edge: the register latches
                ++load_;
                step_ = step::load;
                next_trigger(t_.load_pulse);
                return;
            case step::pixel:
                if (pixel_ == s_->cos_codes.size()) {
                    ++surface_;
                    step_ = step::surface;
                    break;
                }
                step_ = step::pixel_cos;
                if (t_.t_high / 2 > t_.cos_lead) {
                    next_trigger(t_.t_high / 2 - t_.cos_lead);
                    return;
                }
                break;
            case step::pixel_cos:
                in18_cos.write(s_->cos_codes[pixel_]);
                step_ = step::pixel_fall;
                next_trigger(t_.cos_lead);  // zero: ctl17 falls a delta cycle after in18 changed
                return;
            case step::pixel_fall:
                ctl17.write(false);  // latch cos into RG2
                step_ = step::pixel_rise;
                next_trigger(t_.t_low);
                return;
            case step::pixel_rise:
                ctl17.write(true);  // out29 rises: outputs 25..27 valid
                ++pixel_;
                step_ = step::pixel;
                next_trigger(t_.t_high / 2);
                return;
        }
    }

    sc_core::sc_out<bool>& load_ctl() { return load_ == 0 ? ctl15 : load_ == 1 ? ctl20 : load_ == 2 ? ctl22 : ctl24; }

    item_source<surface> surfaces_;
    strobe_timing t_;
    std::size_t pixels_ = 0, streamed_ = 0;
    bool finished_ = false;
    step step_ = step::start;
    const surface* s_ = nullptr;
    std::size_t surface_ = 0, pixel_ = 0, load_ = 0;
};

class specular_monitor : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_in<n_t> in16_n{"in16_n"};
    sc_core::sc_in<cos_t> in18_cos{"in18_cos"};
    sc_core::sc_in<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};
    sc_core::sc_in<out_t> out25_r{"out25_r"}, out26_g{"out26_g"}, out27_b{"out27_b"};
    sc_core::sc_in<bool> out29_valid{"out29_valid"};

    SC_HAS_PROCESS(specular_monitor);
    specular_monitor(const sc_core::sc_module_name& name, std::function<void(const pixel_sample&)> sink)
        : sc_module(name), sink_(std::move(sink)) {
        SC_METHOD(on_load);
        sensitive << ctl15.neg() << ctl20.neg() << ctl22.neg() << ctl24.neg();
        dont_initialize();
        SC_METHOD(on_latch);
        sensitive << ctl17.neg();
        dont_initialize();
        SC_METHOD(on_valid);
        sensitive << out29_valid.pos();
        dont_initialize();
    }

private:
    void on_load() {
        if (ctl15.negedge()) cur_.n = in16_n.read().to_uint64();
        if (ctl20.negedge()) cur_.ksi[0] = in19_ksi_r.read().to_uint64();
        if (ctl22.negedge()) cur_.ksi[1] = in21_ksi_g.read().to_uint64();
        if (ctl24.negedge()) cur_.ksi[2] = in23_ksi_b.read().to_uint64();
    }
    void on_latch() {
        cur_.cos = in18_cos.read().to_uint64();
        pending_ = true;
    }
    void on_valid() {
        if (!pending_) return;  // a rising edge with no pixel latched before it
        pending_ = false;
        pixel_sample s = cur_;
        s.out = {out25_r.read().to_uint64(), out26_g.read().to_uint64(), out27_b.read().to_uint64()};
        s.at = sc_core::sc_time_stamp();
        sink_(s);
    }

    std::function<void(const pixel_sample&)> sink_;
    pixel_sample cur_;
    bool pending_ = false;
};

// Per-n statistics of one run.
struct specular_stats {
    std::size_t samples = 0, mismatches = 0;
    double max_rel_err_056 = 0.0;  // |q_device - cos^n| / cos^n where cos^n >= 0.56 (the quadratic-BRDF paper)
    std::size_t rel_err_points = 0;
};

class specular_checker {
public:
    using golden_fn = std::function<datapath_nets(uint64_t n, uint64_t cos, const std::array<uint64_t, 3>& ksi)>;

    explicit specular_checker(golden_fn golden, std::size_t max_reports = 10)
        : golden_(std::move(golden)), max_reports_(max_reports) {}

    // For the tests of the verdict: the golden values of samples k..k+count-1 (0-based) are corrupted.
    void inject_mismatch(std::size_t k, std::size_t count = 1) {
        inject_ = k;
        inject_count_ = count;
    }
    // Off: no accuracy statistics against cos^n (a pow per sample), only the golden comparison:
    // the random differential mode, which reports no accuracy.
    void measure_accuracy(bool on) { accuracy_ = on; }

    void check(const pixel_sample& s) {
        auto& st = stats_[s.n];
        ++st.samples;
        auto g = golden_(s.n, s.cos, s.ksi);
        if (checked_ >= inject_ && checked_ - inject_ < inject_count_) g.out[0] ^= 1;
        ++checked_;
        if (g.out != s.out) {
            ++st.mismatches;
            ++mismatches_;
            if (mismatches_ <= max_reports_) {
                std::ostringstream os;
                os << "at " << s.at << " n=" << s.n << " cos=0x" << std::hex << s.cos << std::dec
                   << ": device (" << s.out[0] << "," << s.out[1] << "," << s.out[2] << ") golden ("
                   << g.out[0] << "," << g.out[1] << "," << g.out[2] << ") [Q9.8 codes]";
                SC_REPORT_WARNING(msg::mismatch, os.str().c_str());
            }
        }
        // Accuracy against the exact BRDF, on the channel with the largest k_s*I.
        if (!accuracy_) return;
        std::size_t ch = 0;
        for (std::size_t i = 1; i < 3; ++i)
            if (s.ksi[i] > s.ksi[ch]) ch = i;
        if (s.ksi[ch] == 0 || s.cos > spec::cos_one) return;
        const double c = to_real(s.cos, spec::cos_fmt);
        const double exact = ref::cos_pow(c, static_cast<double>(s.n));
        if (exact < 0.56) return;
        const double q = to_real(s.out[ch], spec::out_fmt) / static_cast<double>(s.ksi[ch]);
        st.max_rel_err_056 = std::max(st.max_rel_err_056, std::abs(q - exact) / exact);
        ++st.rel_err_points;
    }

    const std::map<uint64_t, specular_stats>& stats() const { return stats_; }
    std::size_t samples() const {
        std::size_t n = 0;
        for (const auto& [k, st] : stats_) n += st.samples;
        return n;
    }
    std::size_t mismatches() const { return mismatches_; }

private:
    golden_fn golden_;
    std::size_t max_reports_;
    std::map<uint64_t, specular_stats> stats_;
    std::size_t mismatches_ = 0, checked_ = 0, inject_ = SIZE_MAX, inject_count_ = 1;
    bool accuracy_ = true;
};

// A bench that owns the pins' signals, the device, the stimulus, the monitor and the checker.
// Device is any specular_device<AGen> (device_ua60553, device_ua22802, device_ua60553_tuned), its
// fast model, or the squared-quadratic device (with its clock).
// The pins' signals are the Fig. 1 bundle (specular/fig1_pins.h).
template <typename Device>
class specular_bench : public sc_core::sc_module, public fig1_signals {
public:
    specular_checker checker;
    std::unique_ptr<sc_core::sc_clock> clk;  // devices with a clk pin only
    Device dut;
    specular_stimulus stim;
    specular_monitor mon;

    template <typename... DeviceArgs>
    specular_bench(const sc_core::sc_module_name& name, item_source<surface> surfaces, strobe_timing t,
                   specular_checker::golden_fn golden, DeviceArgs&&... device_args)
        : sc_module(name),
          checker(std::move(golden)),
          clk(has_clk<Device>::value ? std::make_unique<sc_core::sc_clock>("clk", t.clk_period, t.clk_duty) : nullptr),
          dut("dut", std::forward<DeviceArgs>(device_args)...),
          stim("stim", std::move(surfaces), t),
          mon("mon", [this](const pixel_sample& s) { checker.check(s); }) {
        if constexpr (has_clk<Device>::value) dut.clk(*clk);
        bind_fig1_inputs(dut, *this);
        bind_fig1_inputs(stim, *this);
        bind_fig1_inputs(mon, *this);
        bind_fig1_outputs(dut, *this);
        bind_fig1_outputs(mon, *this);
    }

    bool finished() const { return stim.finished(); }
};

}  // namespace shading::tb
