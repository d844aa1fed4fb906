// The fast pin-level abstraction of the squared-quadratic device: the pins of squared_device and
// their timing, none of its blocks. One process at the pins' edges: at a rising edge of clk the
// controller's plain state (sq_count.h, the block model's own FSM) steps; at a falling edge the
// squaring register takes the golden model's quadratic at n' (a LOAD) or its own square (a SQUARE);
// registers 1-5 are words latched at their strobes' falling edges; strobe 17's request crosses
// the block model's synchroniser sync17 as its plain chain (blocks/synchroniser.h). Outputs 25-27
// change once per latch that changes them, at the derived path delay (RG_SQ or RG3-5 ->
// MUL12-14), where the block model's multipliers settle; output 29 is strobe 17 AND done after the
// gate's delay. The block model's checks are made at the same edges with the same message ids:
// the input ranges, a strobe before the result is valid, each LOAD against RG1's and RG2's paths,
// strobes 20/22/24 against output 29's rise, and every clock phase.
//
// Not modelled: the register setup check of blocks/reg.h, values still settling (a LOAD taken too
// soon takes the golden value of the registers' new words, where the block model takes whatever
// ADD11 shows; both report it), the internal nets (the per-block waveform is the block model's).
//
//   squared_fast dut("dut", overflow_mode::saturate);   // = device_squared_fast
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <systemc>

#include "arith/squared_arith.h"
#include "blocks/synchroniser.h"
#include "core/abstraction.h"
#include "core/report_ids.h"
#include "formats/specular_formats.h"
#include "formats/squared_formats.h"
#include "specular/block_delays.h"
#include "squared/sq_count.h"
#include "squared/squared_device.h"

namespace shading {

class squared_fast : public sc_core::sc_module {
    using cos_t = sc_dt::sc_uint<spec::cos_fmt.width>;
    using ksi_t = sc_dt::sc_uint<spec::ksi_fmt.width>;
    using out_t = sc_dt::sc_uint<spec::out_fmt.width>;

public:
    static constexpr abstraction level = abstraction::fast;
    using config = squared_device::config;  // squared_device's constructors, for tops that switch by type

    // The pins of squared_device.
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_in<sc_dt::sc_uint<squared::n_fmt.width>> in16_n{"in16_n"};
    sc_core::sc_in<cos_t> in18_cos{"in18_cos"};
    sc_core::sc_in<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};
    sc_core::sc_out<out_t> out25_r{"out25_r"}, out26_g{"out26_g"}, out27_b{"out27_b"};
    sc_core::sc_out<bool> out29_valid{"out29_valid"};

    SC_HAS_PROCESS(squared_fast);
    explicit squared_fast(const sc_core::sc_module_name& name, overflow_mode mode = overflow_mode::saturate,
                          const block_delays& t = {})
        : sc_module(name), mode_(mode), gate_(t.gate) {
        // The block model's derived paths, summed from the same delays (the tests compare them).
        const sc_core::sc_time shift = 4 * t.mux;  // a barrel shifter of 4 rows
        const sc_core::sc_time tail = t.multiplier + t.adder + t.mux;  // MUL10 -> ADD11 -> MX_SQ
        load_path_[0] = t.reg + t.mux + shift + t.inverter + t.multiplier + shift + t.adder + tail;
        load_path_[1] = t.reg + std::max(t.multiplier, t.inverter) + t.adder + tail;
        out_path_ = t.reg + t.multiplier;
        min_high_ = t.mux;
        const sc_core::sc_time loop = t.reg + t.multiplier + t.mux;
        min_period_ = loop;
        min_low_ = std::max(out_path_, loop > min_high_ ? loop - min_high_ : sc_core::SC_ZERO_TIME);
        if (loop == sc_core::SC_ZERO_TIME)
            SC_REPORT_ERROR(msg::config, (std::string(this->name()) +
                                          ": the squaring loop RG_SQ -> MUL_SQ -> MX_SQ -> RG_SQ needs a delay: "
                                          "with none, RG_SQ's own square reaches its input at the latching edge")
                                             .c_str());
        SC_METHOD(on_edge);
        sensitive << clk << ctl15.neg() << ctl17 << ctl20.neg() << ctl22.neg() << ctl24.neg();
        dont_initialize();
        SC_METHOD(on_outputs);
        sensitive << out_[0].settle << out_[1].settle << out_[2].settle;
        dont_initialize();
        SC_METHOD(on_valid);
        sensitive << valid_settle_;
        dont_initialize();
        SC_METHOD(power_up);  // once, as the block model's gate computes its first output
    }

    squared_fast(const sc_core::sc_module_name& name, overflow_mode mode, const config&, const block_delays& t)
        : squared_fast(name, mode, t) {}

    // The block model's derived paths and clock requirements (squared_device's accessors).
    const sc_core::sc_time& rg1_to_load() const { return load_path_[0]; }
    const sc_core::sc_time& rg2_to_load() const { return load_path_[1]; }
    const sc_core::sc_time& min_high() const { return min_high_; }
    const sc_core::sc_time& min_low() const { return min_low_; }
    const sc_core::sc_time& colour_path() const { return out_path_; }
    // The block model's monitor counts: chk_in16_n, chk_in18_cos, chk_load, chk_timing, chk_clk;
    // and sq.ctl_sq.dropped().
    unsigned n_violations() const { return n_violations_; }
    unsigned cos_violations() const { return cos_violations_; }
    unsigned load_violations() const { return load_violations_; }
    unsigned timing_violations() const { return timing_violations_; }
    unsigned clock_violations() const { return clock_violations_; }
    unsigned dropped() const { return dropped_; }
    const squared::sq_count& state() const { return st_; }
    uint64_t sq_word() const { return sq_; }  // RG_SQ

private:
    void on_edge() {
        const auto now = sc_core::sc_time_stamp();
        // The clock first: a strobe at a clock edge's instant is seen after it (sq_ctrl.h's order;
        // RG_SQ latches the value MX_SQ showed before the strobe's register changed).
        if (clk.posedge()) rising(now);
        if (clk.negedge()) falling(now);
        if (ctl15.negedge()) {
            rg_[0] = in16_n.read().to_uint64();
            latched(0, now);
            check_range(rg_[0], squared::n_min, squared::n_max, "chk_in16_n",
                        "n = 0 is read as n = 1 (the LZC counts 10 zeros: a = 0, no squaring, outputs cos * k_s*I); "
                        "n > 1000 extends the law (k = 9, f up to 511/512)",
                        n_violations_);
        }
        if (ctl17.event()) {
            if (ctl17.read()) {
                drive_valid();
            } else {
                rg_[1] = in18_cos.read().to_uint64();
                latched(1, now);
                check_range(rg_[1], 0, spec::cos_one, "chk_in18_cos",
                            mode_ == overflow_mode::saturate
                                ? "cos > 1.0: ADD11 saturates the quadratic to 1.0 (outputs = k_s*I)"
                                : "cos > 1.0: wrap mode passes ADD11's and the squarer's low wires on unchanged",
                            cos_violations_);
                const bool was_busy = st_.busy();
                if (st_.strobe()) report_dropped(was_busy);
                drive_valid();
            }
        }
        for (std::size_t i = 2; i < 5; ++i) {
            sc_core::sc_in<bool>& s = i == 2 ? ctl20 : i == 3 ? ctl22 : ctl24;
            if (!s.negedge()) continue;
            const uint64_t v = (i == 2 ? in19_ksi_r : i == 3 ? in21_ksi_g : in23_ksi_b).read().to_uint64();
            latched(i, now);
            if (v == rg_[i]) continue;  // the register's output does not change: its multiplier sleeps
            rg_[i] = v;
            evaluate(i - 2);
        }
    }

    void rising(const sc_core::sc_time& now) {
        // As monitors/phase_checker.h: the low phase against RG's path to the outputs, else the period
        // against the loop.
        if (fall_seen_ && too_short(now - last_fall_, out_path_))
            report_phase("low phase", last_fall_, now, out_path_);
        else if (rise_seen_ && too_short(now - last_rise_, min_period_))
            report_phase("period", last_rise_, now, min_period_);
        last_rise_ = now;
        rise_seen_ = true;
        const bool was_done = st_.done();
        // sync17's flip-flops and the controller's take their inputs at the same edge: the
        // controller reads the synchroniser's output from before it.
        const bool req_s = sync_.q() != 0;
        sync_.rising(st_.req());
        sel_ = st_.rising(req_s, static_cast<unsigned>(golden_squared_a(rg_[0]).z));
        if (st_.done() != was_done) drive_valid();
    }

    void falling(const sc_core::sc_time& now) {
        if (rise_seen_ && too_short(now - last_rise_, min_high_))
            report_phase("high phase", last_rise_, now, min_high_);
        else if (fall_seen_ && too_short(now - last_fall_, min_period_))
            report_phase("period", last_fall_, now, min_period_);
        last_fall_ = now;
        fall_seen_ = true;
        if (sel_ == squared::sq_count::load) {
            check_load(now);
            sq_ = golden_squared(rg_[0], rg_[1], {0, 0, 0}, mode_).q;
        } else if (sel_ == squared::sq_count::square) {
            sq_ = ((sq_ * sq_) >> squared::q_frac) & squared::sq_fmt.mask();
        } else {
            return;
        }
        // The colour multipliers read RG_SQ's 16 high wires: a change below them wakes none.
        const uint64_t q15 = (sq_ >> squared::sq_to_brdf_drop) & spec::brdf_fmt.mask();
        if (q15 == q15_) return;
        q15_ = q15;
        for (std::size_t ch = 0; ch < 3; ++ch) evaluate(ch);
    }

    void latched(std::size_t i, const sc_core::sc_time& now) {
        fall_[i] = now;
        fallen_[i] = true;
    }

    // MUL12..14 on RG_SQ's 16 high wires and RG3..5, each multiplier on its own: it recomputes when
    // one of its inputs changes (a register that latches the word it holds changes nothing) and its
    // output changes a register's clock-to-q plus a multiplier later; an unchanged result swallows
    // one in flight (core/comb_delay.h's inertial driver).
    void evaluate(std::size_t ch) {
        const uint64_t o = ((q15_ * rg_[2 + ch]) >> spec::out_drop) & spec::out_fmt.mask();
        channel& c = out_[ch];
        if (out_path_ == sc_core::SC_ZERO_TIME) {
            write_output(ch, o);
            return;
        }
        if (o == c.written) {
            if (c.in_flight) c.settle.cancel();
            c.in_flight = false;
            return;
        }
        c.pending = o;
        c.in_flight = true;
        c.due = sc_core::sc_time_stamp() + out_path_;
        c.settle.cancel();
        c.settle.notify(out_path_);
    }

    void on_outputs() {
        for (std::size_t ch = 0; ch < 3; ++ch) {
            channel& c = out_[ch];
            if (!c.in_flight || !c.settle_due()) continue;
            c.in_flight = false;
            write_output(ch, c.pending);
        }
    }

    void write_output(std::size_t ch, uint64_t v) {
        out_[ch].written = v;
        (ch == 0 ? out25_r : ch == 1 ? out26_g : out27_b).write(out_t(v));
    }

    // Output 29: strobe 17 AND done through one gate (inertial, as and_gate.h).
    void drive_valid() {
        const bool v = ctl17.read() && st_.done();
        if (gate_ == sc_core::SC_ZERO_TIME) {
            write_valid(v);
            return;
        }
        if (!first_valid_ && v == valid_written_) {
            if (valid_in_flight_) valid_settle_.cancel();
            valid_in_flight_ = false;
            return;
        }
        first_valid_ = false;
        valid_pending_ = v;
        valid_in_flight_ = true;
        valid_settle_.cancel();
        valid_settle_.notify(gate_);
    }

    void power_up() { drive_valid(); }

    void on_valid() {
        valid_in_flight_ = false;
        write_valid(valid_pending_);
    }

    void write_valid(bool v) {
        valid_written_ = v;
        out29_valid.write(v);
        if (v) check_colour_timing();
    }

    void check_range(uint64_t v, uint64_t lo, uint64_t hi, const char* checker, const char* what, unsigned& count) {
        if (v >= lo && v <= hi) return;
        ++count;
        std::ostringstream os;
        os << name() << '.' << checker << ": " << v << " (0x" << std::hex << v << std::dec << ") latched at "
           << sc_core::sc_time_stamp() << " is outside " << lo << ".." << hi << "; " << what;
        SC_REPORT_WARNING(msg::input, os.str().c_str());
    }

    void report_dropped(bool was_busy) {
        ++dropped_;
        std::ostringstream os;
        os << name() << ": ctl17 fell at " << sc_core::sc_time_stamp() << " before the previous result was valid ("
           << (was_busy ? "still being squared" : "not yet taken by clk")
           << "); that result is dropped, output 29 stays low until the new cos has been squared";
        SC_REPORT_WARNING(msg::timing, os.str().c_str());
    }

    // monitors/load_checker.h: RG1 and RG2 latched at least their path into RG_SQ before a LOAD.
    void check_load(const sc_core::sc_time& now) {
        for (std::size_t i = 0; i < 2; ++i) {
            if (!fallen_[i] || now - fall_[i] > load_path_[i]) continue;
            ++load_violations_;
            std::ostringstream os;
            os << name() << ": RG_SQ loads at " << now << ", only " << (now - fall_[i]) << " after "
               << (i == 0 ? "ctl15" : "ctl17") << " latched (its path there: " << load_path_[i]
               << "); the value loaded is not settled";
            SC_REPORT_WARNING(msg::timing, os.str().c_str());
        }
    }

    // monitors/timing_checker.h at a rising edge of output 29, for strobes 20, 22, 24.
    void check_colour_timing() {
        const auto now = sc_core::sc_time_stamp();
        static constexpr const char* pin[5] = {"ctl15", "ctl17", "ctl20", "ctl22", "ctl24"};
        for (std::size_t i = 2; i < 5; ++i) {
            if (!fallen_[i] || (seen_valid_ && fall_[i] < last_valid_)) continue;
            if (now - fall_[i] >= out_path_) continue;
            ++timing_violations_;
            std::ostringstream os;
            os << name() << ": outputs validated at " << now << ", only " << (now - fall_[i]) << " after strobe "
               << pin[i] << " latched (its path to the outputs: " << out_path_
               << "); the outputs sampled at this edge are not settled";
            SC_REPORT_WARNING(msg::timing, os.str().c_str());
        }
        last_valid_ = now;
        seen_valid_ = true;
    }

    // monitors/phase_checker.h: the first 10 violations reported, the rest counted.
    static bool too_short(const sc_core::sc_time& phase, const sc_core::sc_time& required) {
        return required > sc_core::SC_ZERO_TIME && phase <= required;
    }
    void report_phase(const char* phase, const sc_core::sc_time& from, const sc_core::sc_time& to,
                      const sc_core::sc_time& required) {
        const unsigned n = ++clock_violations_;
        if (n > 10) return;
        std::ostringstream os;
        os << name() << ": " << phase << " of clk from " << from << " to " << to << " lasts " << (to - from)
           << ", not longer than the " << required << " its paths take; the values latched or sampled at " << to
           << " are not settled";
        if (n == 10) os << " [10 violations reported; further ones are only counted]";
        SC_REPORT_WARNING(msg::timing, os.str().c_str());
    }

    overflow_mode mode_;
    sc_core::sc_time gate_;
    std::array<sc_core::sc_time, 2> load_path_;
    sc_core::sc_time out_path_, min_high_, min_low_, min_period_;
    std::array<uint64_t, 5> rg_{};
    std::array<sc_core::sc_time, 5> fall_;
    std::array<bool, 5> fallen_{};
    synchroniser_chain<1, squared::sync_stages> sync_;  // sync17
    squared::sq_count st_;
    squared::sq_count::select sel_ = squared::sq_count::hold;
    uint64_t sq_ = 0, q15_ = 0;
    // One colour multiplier's inertial output (its power-up output is 0, as the block model's first
    // drive): its settle event wakes the shared on_outputs, which writes the channels due now.
    struct channel {
        sc_core::sc_event settle;
        uint64_t pending = 0, written = 0;
        bool in_flight = false;
        sc_core::sc_time due;
        bool settle_due() const { return sc_core::sc_time_stamp() == due; }
    };
    std::array<channel, 3> out_;
    sc_core::sc_event valid_settle_{"valid_settle"};
    bool valid_pending_ = false, valid_written_ = false, valid_in_flight_ = false, first_valid_ = true;
    sc_core::sc_time last_rise_, last_fall_, last_valid_;
    bool rise_seen_ = false, fall_seen_ = false, seen_valid_ = false;
    unsigned n_violations_ = 0, cos_violations_ = 0, load_violations_ = 0, timing_violations_ = 0,
             clock_violations_ = 0, dropped_ = 0;
};

}  // namespace shading
