// Assertion monitor (not a hardware block) for a clocked unit whose registers latch on one edge of
// clk while its controller switches on the other (seed 004's units): each phase must hold the
// combinational paths launched at its opening edge. Every high phase (rise -> fall) not longer
// than min_high and every low phase (fall -> rise) not longer than min_low is counted and reported
// as shading/timing, naming the phase, the measured and required length and the paths. A phase
// equal to its path is a violation too: the register input would change at the latching instant
// itself, which reg.h reports as a setup violation. A zero requirement is never violated.
// Only phases whose both edges were seen are measured, so a partial phase before the clock's first
// edge is ignored. Reported: the first `max_reports` violations (10 by default), one per violating
// edge, the last of them saying that later ones are only counted; violations() counts them all.
// A short clock would otherwise print one report per clock for a whole run.
#pragma once

#include <sstream>
#include <string>
#include <systemc>

#include "core/report_ids.h"

namespace shading {

class phase_checker : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> clk{"clk"};

    SC_HAS_PROCESS(phase_checker);
    phase_checker(const sc_core::sc_module_name& name, const sc_core::sc_time& min_high,
                  const sc_core::sc_time& min_low, std::string paths)
        : sc_module(name), min_high_(min_high), min_low_(min_low), paths_(std::move(paths)) {
        SC_METHOD(on_rise);  // closes a low phase
        sensitive << clk.pos();
        dont_initialize();
        SC_METHOD(on_fall);  // closes a high phase
        sensitive << clk.neg();
        dont_initialize();
    }

    void set_min_high(const sc_core::sc_time& t) { min_high_ = t; }
    void set_min_low(const sc_core::sc_time& t) { min_low_ = t; }
    void set_max_reports(unsigned n) { max_reports_ = n; }
    const sc_core::sc_time& min_high() const { return min_high_; }
    const sc_core::sc_time& min_low() const { return min_low_; }
    const std::string& paths() const { return paths_; }
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
    unsigned max_reports_ = 10;
    sc_core::sc_time last_rise_, last_fall_;
    bool rise_seen_ = false, fall_seen_ = false;
    unsigned high_violations_ = 0, low_violations_ = 0;
};

}  // namespace shading
