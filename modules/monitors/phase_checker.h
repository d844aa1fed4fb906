// Assertion monitor (not a hardware block) for a clocked unit whose registers latch on one edge of
// clk while its controller switches on the other (the interpolation paper's units): each phase must hold the
// combinational paths launched at its opening edge, and each period the paths that run from one
// edge to the same edge a clock later. Every high phase (rise -> fall) not longer than min_high,
// every low phase (fall -> rise) not longer than its own paths (min_low_phase), and every period
// (fall -> fall, rise -> rise) not longer than min_period is counted and reported as shading/timing,
// naming the phase, the measured and required length and the paths; a short period counts as a
// low violation (min_low is what the low phase needs when the high phase is at its shortest).
// A phase equal to its path is a violation too: the register input would change at the latching
// instant itself, which reg.h reports as a setup violation. A zero requirement is never violated.
// Only phases whose both edges were seen are measured, so a partial phase before the clock's first
// edge is ignored. Reported: the first `max_reports_` (10) violations, one per violating
// edge, the last of them saying that later ones are only counted; violations() counts them all.
// A short clock would otherwise print one report per clock for a whole run.
// The requirements come from the unit's elaborated structure (derive(), core/timing_graph.h), not
// from hand sums: a rewiring or a slower block moves them.
#pragma once

#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <systemc>
#include <vector>

#include "core/report_ids.h"
#include "core/timed_block.h"
#include "core/timing_graph.h"

namespace shading {

class phase_checker : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> clk{"clk"};

    SC_HAS_PROCESS(phase_checker);
    // Requirements 0 (never violated) until derive() sets them.
    explicit phase_checker(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_rise);  // closes a low phase
        sensitive << clk.pos();
        dont_initialize();
        SC_METHOD(on_fall);  // closes a high phase
        sensitive << clk.neg();
        dont_initialize();
    }

    // Derives both requirements from the timing graph `g` of a unit or a whole top (build it at
    // end_of_elaboration). The input pins and the blocks that switch at the rising edge (controllers,
    // timed_block::switches_on_rising_edge) launch their paths just after it; every other clocked
    // block (reg.h, also on a strobe that falls with clk) takes its inputs at the falling edge, and
    // the rising edge takes the outputs and the controllers' inputs. So: rising to falling within
    // the high phase; falling to rising (the outputs, a controller's inputs) within the low phase;
    // falling to falling and rising to rising within the whole period, which needs from the low
    // phase what the high phase leaves over. A falling block's setup time ends its paths.
    void derive(const timing_graph& g) {
        std::vector<const sc_core::sc_object*> rise, fall;
        for (auto* r : g.registers()) (timed(*r).switches_on_rising_edge() ? rise : fall).push_back(r);
        const auto from_rise = [&](const std::vector<timing_graph::channel>& to) {
            auto p = g.longest_from_channels(g.inputs(), to);
            const auto q = g.longest_from_registers(rise, to);
            return q.found && (!p.found || q.delay > p.delay) ? q : p;
        };
        // The falling blocks' inputs, grouped by setup time (one search a group).
        std::map<sc_core::sc_time, std::vector<timing_graph::channel>> at_fall;
        for (auto* r : fall) {
            auto& v = at_fall[timed(*r).setup_time()];
            for (auto c : g.taken_by(*r)) v.push_back(c);
        }
        std::vector<timing_graph::channel> at_rise = g.outputs();
        for (auto* r : rise)
            for (auto c : g.taken_by(*r)) at_rise.push_back(c);
        timing_path high, loop;
        sc_core::sc_time high_t, loop_t;
        for (const auto& [setup, sinks] : at_fall) {
            const auto p = from_rise(sinks);
            if (p.found && (!high.found || p.delay + setup > high_t)) high = p, high_t = p.delay + setup;
            const auto l = g.longest_from_registers(fall, sinks);
            if (l.found && (!loop.found || l.delay + setup > loop_t)) loop = l, loop_t = l.delay + setup;
        }
        const auto out = g.longest_from_registers(fall, at_rise);
        const auto whole = from_rise(at_rise);  // rising to rising
        if (whole.found && (!loop.found || whole.delay > loop_t)) loop = whole, loop_t = whole.delay;
        settle(high, high_t, out, loop, loop_t);
    }
    // Requirements set from paths a unit derived itself (a unit whose registers are not all on this
    // clock, e.g. the squared-quadratic device: strobe-latched RG1..RG5 beside the clocked RG_SQ).
    // high: launched at the rising edge into a falling-edge register; out: a falling-edge register
    // to the outputs sampled at the rising edge; loop: falling-edge register to falling-edge
    // register over both phases (the setup time of the registers ending them included in all three).
    void require(const timing_path& high, const timing_path& out, const timing_path& loop,
                 const sc_core::sc_time& setup = sc_core::SC_ZERO_TIME) {
        settle(high, high.found ? high.delay + setup : sc_core::SC_ZERO_TIME, out, loop,
               loop.found ? loop.delay + setup : sc_core::SC_ZERO_TIME);
    }
    // The paths derive() found: into a register in the high phase, to the outputs, and register to
    // register (not found: no such path).
    const timing_path& high_path() const { return high_path_; }
    const timing_path& output_path() const { return out_path_; }
    const timing_path& loop_path() const { return loop_path_; }
    const sc_core::sc_time& min_high() const { return min_high_; }
    const sc_core::sc_time& min_low() const { return min_low_; }
    // The low phase's own paths (to the rising edge), and the paths over both phases.
    const sc_core::sc_time& min_low_phase() const { return min_low_phase_; }
    const sc_core::sc_time& min_period() const { return min_period_; }
    unsigned violations() const { return high_violations_ + low_violations_; }
    unsigned high_violations() const { return high_violations_; }
    unsigned low_violations() const { return low_violations_; }

private:
    void on_rise() {
        const auto now = sc_core::sc_time_stamp();
        if (fall_seen_ && too_short(now - last_fall_, min_low_phase_)) {
            ++low_violations_;
            report("low phase", last_fall_, now, min_low_phase_);
        } else if (rise_seen_ && too_short(now - last_rise_, min_period_)) {
            ++low_violations_;
            report("period", last_rise_, now, min_period_);
        }
        last_rise_ = now;
        rise_seen_ = true;
    }

    void on_fall() {
        const auto now = sc_core::sc_time_stamp();
        if (rise_seen_ && too_short(now - last_rise_, min_high_)) {
            ++high_violations_;
            report("high phase", last_rise_, now, min_high_);
        } else if (fall_seen_ && too_short(now - last_fall_, min_period_)) {
            ++low_violations_;
            report("period", last_fall_, now, min_period_);
        }
        last_fall_ = now;
        fall_seen_ = true;
    }

    // high_t, loop_t: the high and the register-to-register paths with their ends' setup times.
    void settle(const timing_path& high, const sc_core::sc_time& high_t, const timing_path& out,
                const timing_path& loop, const sc_core::sc_time& loop_t) {
        min_high_ = high_t;
        min_low_phase_ = out.found ? out.delay : sc_core::SC_ZERO_TIME;
        min_period_ = loop_t;
        min_low_ = std::max(min_low_phase_, loop_t > high_t ? loop_t - high_t : sc_core::SC_ZERO_TIME);
        std::ostringstream os;
        os << "high: " << (high.found ? high.to_string() : "no path") << "; low: "
           << (out.found ? out.to_string() : "no path");
        if (loop.found) os << "; register to register over both phases: " << loop.to_string();
        paths_ = os.str();
        high_path_ = high;
        out_path_ = out;
        loop_path_ = loop;
    }

    static const timed_block& timed(const sc_core::sc_object& o) { return dynamic_cast<const timed_block&>(o); }

    static bool too_short(const sc_core::sc_time& phase, const sc_core::sc_time& required) {
        return required > sc_core::SC_ZERO_TIME && phase <= required;
    }

    void report(const char* phase, const sc_core::sc_time& from, const sc_core::sc_time& to,
                const sc_core::sc_time& required) {
        const unsigned n = violations();
        if (n > max_reports_) return;
        std::ostringstream os;
        os << name() << ": " << phase << " of " << clk.name() << " from " << from << " to " << to
           << " lasts " << (to - from) << ", not longer than the " << required << " its paths take ("
           << paths_ << "); the values latched or sampled at " << to << " are not settled";
        if (n == max_reports_) os << " [" << n << " violations reported; further ones are only counted]";
        SC_REPORT_WARNING(msg::timing, os.str().c_str());
    }

    sc_core::sc_time min_high_, min_low_, min_low_phase_, min_period_;
    std::string paths_;
    timing_path high_path_, out_path_, loop_path_;
    static constexpr unsigned max_reports_ = 10;
    sc_core::sc_time last_rise_, last_fall_;
    bool rise_seen_ = false, fall_seen_ = false;
    unsigned high_violations_ = 0, low_violations_ = 0;
};

}  // namespace shading
