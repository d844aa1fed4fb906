// The fast pin-level abstraction of a specular device: the pins of specular_device<AGen>
// and their timing, none of its blocks. Registers 1-5 are five words latched at the falling edges
// of their strobes (UA 60553, Fig. 3: "write on the trailing edge"); one method computes the block
// network's function from the golden model (AGen::a_word, golden_datapath: the format tables of
// src/floor/formats) and writes outputs 25-27 once, at the derived path delay after the latch (in delta
// time when the block delays are zero), where the block-level model settles after its transients;
// output 29 follows strobe 17. The input range and strobe timing checks of the block-level model
// are made here at the same edges, with the same message ids and the same counts.
//
// Not modelled: the setup check of blocks/reg.h (a data pin changing at its latching edge is
// latched as read in that delta), the internal nets and their transients (the per-block waveform
// is the block-level model's). Paths: RG1 = reg + AGen::path_delay + MUL10 + ADD11 + MUL12;
// RG2 = reg + max(MUL7, INV8) + ADD9 + MUL10 + ADD11 + MUL12; RG3-5 = reg + MUL12; the tests check
// them against the timing graph of the block-level model (core/timing_graph.h).
//
//   specular_fast<a_gen_linear> dut("dut", overflow_mode::saturate);  // = device_ua60553_fast
//   specular_model<a_gen_linear, abstraction::fast>                    // the same, by a parameter
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <systemc>
#include <type_traits>

#include "arith/specular_arith.h"
#include "core/abstraction.h"
#include "core/report_ids.h"
#include "formats/specular_formats.h"
#include "formats/ua60553_formats.h"
#include "specular/block_delays.h"
#include "specular/specular_device.h"

namespace shading {

template <class AGen>
class specular_fast : public sc_core::sc_module {
    static constexpr unsigned WN = AGen::n_fmt.width;
    using cos_t = sc_dt::sc_uint<spec::cos_fmt.width>;
    using ksi_t = sc_dt::sc_uint<spec::ksi_fmt.width>;
    using out_t = sc_dt::sc_uint<spec::out_fmt.width>;

public:
    using generator = AGen;
    static constexpr abstraction level = abstraction::fast;

    // Device pins, numbered as in UA 60553, Fig. 1 (the same as specular_device's).
    sc_core::sc_in<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_in<sc_dt::sc_uint<WN>> in16_n{"in16_n"};
    sc_core::sc_in<cos_t> in18_cos{"in18_cos"};
    sc_core::sc_in<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};
    sc_core::sc_out<out_t> out25_r{"out25_r"}, out26_g{"out26_g"}, out27_b{"out27_b"};
    sc_core::sc_out<bool> out29_valid{"out29_valid"};

    SC_HAS_PROCESS(specular_fast);
    // The constructor of specular_device<AGen>, so a top switches models by the type alone.
    explicit specular_fast(const sc_core::sc_module_name& name, overflow_mode mode = overflow_mode::saturate,
                           const typename AGen::config& gen = AGen::default_config(), const block_delays& t = {})
        : sc_module(name), mode_(mode), gen_(gen) {
        const sc_core::sc_time rg2_tail = t.adder + t.multiplier;  // ADD11 -> MUL12..14
        path_[0] = t.reg + AGen::path_delay(t) + t.multiplier + rg2_tail;
        path_[1] = t.reg + std::max(t.multiplier, t.inverter) + t.adder + t.multiplier + rg2_tail;
        for (std::size_t i = 2; i < 5; ++i) path_[i] = t.reg + t.multiplier;
        for (const auto& p : path_) timed_ = timed_ || p > sc_core::SC_ZERO_TIME;
        a_ = AGen::a_word(gen_, 0);
        // The registers' latches, output 29 and the timing check (strobe 17's both edges); with
        // zero delays also the outputs, which otherwise on_settle alone drives (one writer each).
        SC_METHOD(on_strobe);
        sensitive << ctl17 << ctl15.neg() << ctl20.neg() << ctl22.neg() << ctl24.neg();
        dont_initialize();
        SC_METHOD(on_settle);  // the outputs, at the path delay
        sensitive << settle_;
        dont_initialize();
    }

    // The derived paths of specular_device (rg1_to_outputs, rg2_to_outputs), and every strobe's.
    const sc_core::sc_time& rg1_to_outputs() const { return path_[0]; }
    const sc_core::sc_time& rg2_to_outputs() const { return path_[1]; }
    const sc_core::sc_time& path(std::size_t strobe) const { return path_.at(strobe); }
    // The counts of the block-level monitors (chk_in16_n, chk_in18_cos, chk_timing).
    unsigned n_violations() const { return n_violations_; }
    unsigned cos_violations() const { return cos_violations_; }
    unsigned timing_violations() const { return timing_violations_; }
    // What registers 1-5 hold (n, cos, k_s*I R, G, B) and the generator's word a(n).
    const std::array<uint64_t, 5>& registers() const { return rg_; }
    uint64_t a_coef() const { return a_; }

private:
    void on_strobe() {
        std::size_t last = 5;
        if (ctl17.event()) {
            const bool high = ctl17.read();
            out29_valid.write(high);  // Fig. 3: output 29 is strobe 17 itself
            if (high) {
                check_timing();
            } else {
                rg_[1] = in18_cos.read().to_uint64();
                check_range(rg_[1], 0, spec::cos_one, "chk_in18_cos",
                            mode_ == overflow_mode::saturate
                                ? "cos > 1.0: ADD11 saturates the BRDF to 1.0 (outputs = k_s*I)"
                                : "cos > 1.0: wrap mode passes the overflowed BRDF bits on unchanged",
                            cos_violations_);
                latched(1, last);
            }
        }
        if (ctl15.negedge()) {
            rg_[0] = in16_n.read().to_uint64();
            a_ = AGen::a_word(gen_, rg_[0]);
            check_range(rg_[0], ua60553::n_min, ua60553::n_max, "chk_in16_n", AGen::n_out_of_range, n_violations_);
            latched(0, last);
        }
        if (ctl20.negedge()) rg_[2] = in19_ksi_r.read().to_uint64(), latched(2, last);
        if (ctl22.negedge()) rg_[3] = in21_ksi_g.read().to_uint64(), latched(3, last);
        if (ctl24.negedge()) rg_[4] = in23_ksi_b.read().to_uint64(), latched(4, last);
        if (last < 5) evaluate();
    }

    void latched(std::size_t i, std::size_t& last) {
        fall_[i] = sc_core::sc_time_stamp();
        fallen_[i] = true;
        const sc_core::sc_time due = fall_[i] + path_[i];
        if (last == 5 || due > due_now_) due_now_ = due;
        last = i;
    }

    // The block network's function on the registers' words; the outputs change once, when the
    // slowest path still in flight settles (an unchanged result cancels nothing and schedules
    // nothing, as core/comb_delay.h's inertial driver).
    void evaluate() {
        const datapath_nets r =
            golden_datapath(a_, AGen::a_fmt.frac, rg_[1], {rg_[2], rg_[3], rg_[4]}, mode_);
        if (!timed_) {
            write_outputs(r.out);
            return;
        }
        if (in_flight_ && pending_due_ > due_now_) due_now_ = pending_due_;
        if (r.out == written_) {
            if (in_flight_) settle_.cancel();
            in_flight_ = false;
            return;
        }
        pending_ = r.out;
        pending_due_ = due_now_;
        in_flight_ = true;
        settle_.cancel();
        settle_.notify(due_now_ - sc_core::sc_time_stamp());
    }

    void on_settle() {
        in_flight_ = false;
        write_outputs(pending_);
    }

    void write_outputs(const std::array<uint64_t, 3>& o) {
        written_ = o;
        out25_r.write(out_t(o[0]));
        out26_g.write(out_t(o[1]));
        out27_b.write(out_t(o[2]));
    }

    void check_range(uint64_t v, uint64_t lo, uint64_t hi, const char* checker, const char* what, unsigned& count) {
        if (v >= lo && v <= hi) return;
        ++count;
        std::ostringstream os;
        os << name() << '.' << checker << ": " << v << " (0x" << std::hex << v << std::dec << ") latched at "
           << sc_core::sc_time_stamp() << " is outside " << lo << ".." << hi << "; " << what;
        SC_REPORT_WARNING(msg::input, os.str().c_str());
    }

    // monitors/timing_checker.h at a rising edge of output 29: a register latched since the
    // previous one, less than its path ago, means the outputs are not settled.
    void check_timing() {
        const auto now = sc_core::sc_time_stamp();
        if (timed_)
            for (std::size_t i = 0; i < 5; ++i) {
                if (!fallen_[i] || (seen_valid_ && fall_[i] < last_valid_)) continue;
                if (now - fall_[i] >= path_[i]) continue;
                ++timing_violations_;
                std::ostringstream os;
                os << name() << ": outputs validated at " << now << ", only " << (now - fall_[i]) << " after strobe "
                   << strobe_pin[i] << " latched (its path to the outputs: " << path_[i]
                   << "); the outputs sampled at this edge are not settled";
                SC_REPORT_WARNING(msg::timing, os.str().c_str());
            }
        last_valid_ = now;
        seen_valid_ = true;
    }

    static constexpr const char* strobe_pin[5] = {"ctl15", "ctl17", "ctl20", "ctl22", "ctl24"};

    overflow_mode mode_;
    typename AGen::config gen_;
    std::array<sc_core::sc_time, 5> path_, fall_;
    std::array<bool, 5> fallen_{};
    std::array<uint64_t, 5> rg_{};
    uint64_t a_ = 0;
    bool timed_ = false, in_flight_ = false, seen_valid_ = false;
    sc_core::sc_event settle_{"settle"};
    sc_core::sc_time due_now_, pending_due_, last_valid_;
    std::array<uint64_t, 3> pending_{}, written_{};
    unsigned n_violations_ = 0, cos_violations_ = 0, timing_violations_ = 0;
};

// The model of a device by a parameter: specular_model<a_gen_linear, abstraction::fast>.
template <class AGen, abstraction A>
using specular_model = std::conditional_t<A == abstraction::block, specular_device<AGen>, specular_fast<AGen>>;

}  // namespace shading
