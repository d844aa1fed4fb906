// Assertion monitor (not a hardware block) for single-phase strobe timing (UA 60553, Fig. 3:
// "the duration of T must exceed the device's transient processes"). Each control input i
// latches a register whose slowest path to the outputs takes path(i). At every rising edge of
// `valid`, a register latched since the previous validating edge less than path(i) ago means
// the outputs are not settled: reported as shading/timing.
#pragma once

#include <sstream>
#ifndef SC_INCLUDE_DYNAMIC_PROCESSES
#define SC_INCLUDE_DYNAMIC_PROCESSES  // sc_spawn
#endif
#include <systemc>
#include <vector>

#include "core/report_ids.h"

namespace shading {

class timing_checker : public sc_core::sc_module {
public:
    sc_core::sc_vector<sc_core::sc_in<bool>> ctl;
    sc_core::sc_in<bool> valid{"valid"};

    SC_HAS_PROCESS(timing_checker);
    timing_checker(const sc_core::sc_module_name& name, std::size_t n_ctl)
        : sc_module(name), ctl("ctl", n_ctl), path_(n_ctl), fall_(n_ctl), fallen_(n_ctl, false) {
        SC_METHOD(on_valid);
        sensitive << valid.pos();
        dont_initialize();
        for (std::size_t i = 0; i < n_ctl; ++i) {
            sc_core::sc_spawn_options opt;
            opt.spawn_method();
            opt.set_sensitivity(&ctl[i].neg());
            opt.dont_initialize();
            sc_core::sc_spawn([this, i] { fall_[i] = sc_core::sc_time_stamp(); fallen_[i] = true; },
                              sc_core::sc_gen_unique_name("on_fall"), &opt);
        }
    }

    void set_path(std::size_t i, const sc_core::sc_time& t) { path_.at(i) = t; }
    const sc_core::sc_time& path(std::size_t i) const { return path_.at(i); }
    unsigned violations() const { return violations_; }

private:
    void on_valid() {
        const auto now = sc_core::sc_time_stamp();
        for (std::size_t i = 0; i < ctl.size(); ++i) {
            if (!fallen_[i] || (seen_valid_ && fall_[i] < last_valid_)) continue;
            if (now - fall_[i] >= path_[i]) continue;
            ++violations_;
            std::ostringstream os;
            os << name() << ": outputs validated at " << now << ", only " << (now - fall_[i])
               << " after " << ctl[i].name() << " latched (its path to the outputs takes "
               << path_[i] << "); the outputs sampled at this edge are not settled";
            SC_REPORT_WARNING(msg::timing, os.str().c_str());
        }
        last_valid_ = now;
        seen_valid_ = true;
    }

    std::vector<sc_core::sc_time> path_, fall_;
    std::vector<bool> fallen_;
    sc_core::sc_time last_valid_;
    bool seen_valid_ = false;
    unsigned violations_ = 0;
};

}  // namespace shading
