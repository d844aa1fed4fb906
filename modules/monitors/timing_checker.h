// Assertion monitor (not a hardware block) for single-phase strobe timing (UA 60553, Fig. 3:
// "the duration of T must exceed the device's transient processes"). Each control input i
// latches the registers whose strobe is bound to the same net; path(i) is the longest path from
// them to the outputs of the module that holds this checker, derived from the elaborated design
// (core/timing_graph.h) at end of elaboration. A register below that module that no strobe
// latches, or a strobe that latches no register, is a configuration error (shading/config): its
// path would go unchecked. At every rising edge of `valid`, a register latched since the previous
// validating edge less than path(i) ago means the outputs are not settled: shading/timing.
#pragma once

#include <set>
#include <sstream>
#include <string>
#ifndef SC_INCLUDE_DYNAMIC_PROCESSES
#define SC_INCLUDE_DYNAMIC_PROCESSES  // sc_spawn
#endif
#include <systemc>
#include <vector>

#include "core/report_ids.h"
#include "core/timing_graph.h"

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

    // Strobe i's derived path: its length, and the blocks on it. Valid from end of elaboration on.
    const sc_core::sc_time& path(std::size_t i) const { return critical_path(i).delay; }
    const timing_path& critical_path(std::size_t i) const {
        if (!derived_)
            SC_REPORT_ERROR(msg::config, (std::string(name()) + ": paths are derived at end of elaboration; "
                                          "read them after sc_start").c_str());
        return path_.at(i);
    }
    unsigned violations() const { return violations_; }

private:
    void end_of_elaboration() override {
        const auto* top = get_parent_object();
        if (top == nullptr) return;
        const timing_graph g(*top);
        std::set<const sc_core::sc_object*> latched;
        for (std::size_t i = 0; i < ctl.size(); ++i) {
            const auto regs = g.registers_clocked_by(timing_graph::channel_of(ctl[i]));
            latched.insert(regs.begin(), regs.end());
            path_[i] = g.longest_from_registers(regs, g.outputs());
            if (!path_[i].found)
                config_error(std::string(ctl[i].name()) + " latches no register with a path to the outputs");
        }
        for (auto* r : g.registers())
            if (!latched.count(r))
                config_error(std::string(r->name()) + " is latched by none of this checker's strobes");
        derived_ = true;
    }

    void config_error(const std::string& what) {
        SC_REPORT_ERROR(msg::config, (std::string(name()) + ": " + what).c_str());
    }

    void on_valid() {
        const auto now = sc_core::sc_time_stamp();
        for (std::size_t i = 0; i < ctl.size(); ++i) {
            if (!fallen_[i] || (seen_valid_ && fall_[i] < last_valid_)) continue;
            if (now - fall_[i] >= path_[i].delay) continue;
            ++violations_;
            std::ostringstream os;
            os << name() << ": outputs validated at " << now << ", only " << (now - fall_[i])
               << " after " << ctl[i].name() << " latched (its path to the outputs: "
               << path_[i].to_string() << "); the outputs sampled at this edge are not settled";
            SC_REPORT_WARNING(msg::timing, os.str().c_str());
        }
        last_valid_ = now;
        seen_valid_ = true;
    }

    std::vector<timing_path> path_;
    std::vector<sc_core::sc_time> fall_;
    std::vector<bool> fallen_;
    sc_core::sc_time last_valid_;
    bool seen_valid_ = false, derived_ = false;
    unsigned violations_ = 0;
};

}  // namespace shading
