// Assertion monitor (not a hardware block) for single-phase strobe timing (UA 60553, Fig. 3:
// "the duration of T must exceed the device's transient processes"). Each control input i
// latches the registers whose strobe is bound to the same net; path(i) is the longest path from
// them to the outputs of the module that holds this checker, derived from the elaborated design
// (core/timing_graph.h) at end of elaboration. A register below that module that no strobe
// latches, or a strobe that latches no register, is a configuration error (shading/config): its
// path would go unchecked. At every rising edge of `valid`, a register latched since the previous
// validating edge less than path(i) ago means the outputs are not settled: shading/timing. When
// strobe i fell is read from its registers (timed_block::last_latch), not from a process woken at
// every edge (one wakeup per strobe edge that showed nothing).
#pragma once

#include <algorithm>
#include <set>
#include <sstream>
#include <string>
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
    // elsewhere: registers below the parent that other monitors check (the squared-quadratic
    // device's RG1, RG2 and RG_SQ, whose paths end at RG_SQ or start at clk), not a configuration
    // error for this one.
    timing_checker(const sc_core::sc_module_name& name, std::size_t n_ctl,
                   std::vector<const sc_core::sc_object*> elsewhere = {})
        : sc_module(name), ctl("ctl", n_ctl), path_(n_ctl), latched_by_(n_ctl), elsewhere_(std::move(elsewhere)) {
        SC_METHOD(on_valid);
        sensitive << valid.pos();
        dont_initialize();
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
            for (auto* r : regs) latched_by_[i].push_back(dynamic_cast<const timed_block*>(r));
            path_[i] = g.longest_from_registers(regs, g.outputs());
            if (!path_[i].found)
                config_error(std::string(ctl[i].name()) + " latches no register with a path to the outputs");
        }
        for (auto* r : g.registers())
            if (!latched.count(r) && std::find(elsewhere_.begin(), elsewhere_.end(), r) == elsewhere_.end())
                config_error(std::string(r->name()) + " is latched by none of this checker's strobes");
        derived_ = true;
    }

    void config_error(const std::string& what) {
        SC_REPORT_ERROR(msg::config, (std::string(name()) + ": " + what).c_str());
    }

    void on_valid() {
        const auto now = sc_core::sc_time_stamp();
        for (std::size_t i = 0; i < ctl.size(); ++i) {
            sc_core::sc_time fall;
            bool fallen = false;
            for (const timed_block* r : latched_by_[i]) {
                sc_core::sc_time at;
                if (r->last_latch(at) && (!fallen || at > fall)) fall = at, fallen = true;
            }
            if (!fallen || (seen_valid_ && fall < last_valid_)) continue;
            if (now - fall >= path_[i].delay) continue;
            ++violations_;
            std::ostringstream os;
            os << name() << ": outputs validated at " << now << ", only " << (now - fall)
               << " after " << ctl[i].name() << " latched (its path to the outputs: "
               << path_[i].to_string() << "); the outputs sampled at this edge are not settled";
            SC_REPORT_WARNING(msg::timing, os.str().c_str());
        }
        last_valid_ = now;
        seen_valid_ = true;
    }

    std::vector<timing_path> path_;
    std::vector<std::vector<const timed_block*>> latched_by_;  // strobe i's registers
    std::vector<const sc_core::sc_object*> elsewhere_;
    sc_core::sc_time last_valid_;
    bool seen_valid_ = false, derived_ = false;
    unsigned violations_ = 0;
};

}  // namespace shading
