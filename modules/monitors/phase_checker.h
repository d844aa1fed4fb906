// Assertion monitor (not a hardware block) for a clocked unit whose registers latch on one edge of
// clk while its controller switches on the other (the interpolation paper's units): each phase must hold the
// combinational paths launched at its opening edge. Every high phase (rise -> fall) not longer
// than min_high and every low phase (fall -> rise) not longer than min_low is counted and reported
// as shading/timing, naming the phase, the measured and required length and the paths. A phase
// equal to its path is a violation too: the register input would change at the latching instant
// itself, which reg.h reports as a setup violation. A zero requirement is never violated.
// Only phases whose both edges were seen are measured, so a partial phase before the clock's first
// edge is ignored. Reported: the first `max_reports_` (10) violations, one per violating
// edge, the last of them saying that later ones are only counted; violations() counts them all.
// A short clock would otherwise print one report per clock for a whole run.
// The requirements come from the unit's elaborated structure (derive(), core/timing_graph.h), not
// from hand sums: a rewiring or a slower block moves them.
#pragma once

#include <algorithm>
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

    // Derives both requirements from the unit's timing graph `g` (build it at end_of_elaboration).
    // The input pins and the `launch` blocks (controllers clocked on the rising edge, timed_block
    // registers) change just after the rising edge; every other register latches on the falling
    // edge. High phase: the longest path from an input pin or a launch block to a falling-edge
    // register's data input, plus that register's setup time. Low phase: the longest path from a
    // falling-edge register to the unit's outputs, which the rising edge samples; and a path between
    // falling-edge registers, which has the whole period, needs from the low phase what the high
    // phase leaves over.
    void derive(const timing_graph& g, const std::vector<const sc_core::sc_object*>& launch = {}) {
        std::vector<const sc_core::sc_object*> regs;
        for (auto* r : g.registers())
            if (std::find(launch.begin(), launch.end(), r) == launch.end()) regs.push_back(r);
        timing_path high, loop;
        sc_core::sc_time high_t, loop_t;
        for (auto* r : regs) {
            const sc_core::sc_time setup = dynamic_cast<const timed_block&>(*r).setup_time();
            auto p = g.longest_from_channels(g.inputs(), {g.d_of(*r)});
            if (!launch.empty()) {
                const auto q = g.longest_from_registers(launch, {g.d_of(*r)});
                if (q.found && (!p.found || q.delay > p.delay)) p = q;
            }
            if (p.found && (!high.found || p.delay + setup > high_t)) high = p, high_t = p.delay + setup;
            const auto l = g.longest_from_registers(regs, {g.d_of(*r)});
            if (l.found && (!loop.found || l.delay + setup > loop_t)) loop = l, loop_t = l.delay + setup;
        }
        const auto out = g.longest_from_registers(regs, g.outputs());
        min_high_ = high_t;
        min_low_ = std::max(out.found ? out.delay : sc_core::SC_ZERO_TIME,
                            loop_t > high_t ? loop_t - high_t : sc_core::SC_ZERO_TIME);
        std::ostringstream os;
        os << "high: " << (high.found ? high.to_string() : "no path") << "; low: "
           << (out.found ? out.to_string() : "no path");
        if (loop.found) os << "; register to register over both phases: " << loop.to_string();
        paths_ = os.str();
        high_path_ = high;
        out_path_ = out;
        loop_path_ = loop;
    }
    // Requirements set from paths a unit derived itself (a unit whose registers are not all on this
    // clock, e.g. the squared-quadratic device: strobe-latched RG1..RG5 beside the clocked RG_SQ).
    // high: launched at the rising edge into a falling-edge register; out: a falling-edge register
    // to the outputs sampled at the rising edge; loop: falling-edge register to falling-edge
    // register over both phases (the setup time of the registers ending them included in all three).
    void require(const timing_path& high, const timing_path& out, const timing_path& loop,
                 const sc_core::sc_time& setup = sc_core::SC_ZERO_TIME) {
        const sc_core::sc_time high_t = high.found ? high.delay + setup : sc_core::SC_ZERO_TIME;
        const sc_core::sc_time loop_t = loop.found ? loop.delay + setup : sc_core::SC_ZERO_TIME;
        min_high_ = high_t;
        min_low_ = std::max(out.found ? out.delay : sc_core::SC_ZERO_TIME,
                            loop_t > high_t ? loop_t - high_t : sc_core::SC_ZERO_TIME);
        std::ostringstream os;
        os << "high: " << (high.found ? high.to_string() : "no path") << "; low: "
           << (out.found ? out.to_string() : "no path");
        if (loop.found) os << "; register to register over both phases: " << loop.to_string();
        paths_ = os.str();
        high_path_ = high;
        out_path_ = out;
        loop_path_ = loop;
    }
    // The paths derive() found: into a register in the high phase, to the outputs, and register to
    // register (not found: no such path).
    const timing_path& high_path() const { return high_path_; }
    const timing_path& output_path() const { return out_path_; }
    const timing_path& loop_path() const { return loop_path_; }
    const sc_core::sc_time& min_high() const { return min_high_; }
    const sc_core::sc_time& min_low() const { return min_low_; }
    unsigned violations() const { return high_violations_ + low_violations_; }
    unsigned high_violations() const { return high_violations_; }
    unsigned low_violations() const { return low_violations_; }

private:
    void on_rise() {
        const auto now = sc_core::sc_time_stamp();
        if (fall_seen_ && too_short(now - last_fall_, min_low_)) {
            ++low_violations_;
            report("low", last_fall_, now, min_low_);
        }
        last_rise_ = now;
        rise_seen_ = true;
    }

    void on_fall() {
        const auto now = sc_core::sc_time_stamp();
        if (rise_seen_ && too_short(now - last_rise_, min_high_)) {
            ++high_violations_;
            report("high", last_rise_, now, min_high_);
        }
        last_fall_ = now;
        fall_seen_ = true;
    }

    static bool too_short(const sc_core::sc_time& phase, const sc_core::sc_time& required) {
        return required > sc_core::SC_ZERO_TIME && phase <= required;
    }

    void report(const char* phase, const sc_core::sc_time& from, const sc_core::sc_time& to,
                const sc_core::sc_time& required) {
        const unsigned n = violations();
        if (n > max_reports_) return;
        std::ostringstream os;
        os << name() << ": " << phase << " phase of " << clk.name() << " from " << from << " to " << to
           << " lasts " << (to - from) << ", not longer than the " << required << " its paths take ("
           << paths_ << "); the values latched or sampled at " << to << " are not settled";
        if (n == max_reports_) os << " [" << n << " violations reported; further ones are only counted]";
        SC_REPORT_WARNING(msg::timing, os.str().c_str());
    }

    sc_core::sc_time min_high_, min_low_;
    std::string paths_;
    timing_path high_path_, out_path_, loop_path_;
    static constexpr unsigned max_reports_ = 10;
    sc_core::sc_time last_rise_, last_fall_;
    bool rise_seen_ = false, fall_seen_ = false;
    unsigned high_violations_ = 0, low_violations_ = 0;
};

}  // namespace shading
