// Assertion monitor (not a hardware block) for a clocked register that takes a value computed from
// strobe-latched registers: the squared-quadratic device's RG_SQ, which at a LOAD latches ADD11's
// quadratic at n', a combinational function of RG1 (n) and RG2 (cos), both latched by strobes
// (UA 60553, Fig. 3) asynchronous to clk. At every falling edge of clk where `sel` equals the load
// code, each strobe's registers must have latched at least their path to the target's data input
// ago; otherwise the value taken is not settled: shading/timing. Paths are derived at end of
// elaboration from the parent module's timing graph (core/timing_graph.h), as timing_checker does.
#pragma once

#include <sstream>
#include <string>
#include <systemc>
#include <vector>

#include "core/report_ids.h"
#include "core/timing_graph.h"

namespace shading {

template <unsigned WSEL>
class load_checker : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<sc_dt::sc_uint<WSEL>> sel{"sel"};
    sc_core::sc_vector<sc_core::sc_in<bool>> ctl;

    SC_HAS_PROCESS(load_checker);
    load_checker(const sc_core::sc_module_name& name, std::size_t n_ctl, const sc_core::sc_object& target,
                 unsigned load_code)
        : sc_module(name), ctl("ctl", n_ctl), target_(&target), load_code_(load_code), path_(n_ctl), regs_(n_ctl) {
        SC_METHOD(on_fall);
        sensitive << clk.neg();
        dont_initialize();
    }

    // Strobe i's derived path into the target's data input (valid from end of elaboration on).
    const timing_path& path(std::size_t i) const { return path_.at(i); }
    unsigned violations() const { return violations_; }

private:
    void end_of_elaboration() override {
        const auto* top = get_parent_object();
        if (top == nullptr) return;
        const timing_graph g(*top);
        for (std::size_t i = 0; i < ctl.size(); ++i) {
            const auto regs = g.registers_clocked_by(timing_graph::channel_of(ctl[i]));
            for (auto* r : regs) regs_[i].push_back(dynamic_cast<const timed_block*>(r));
            path_[i] = g.longest_from_registers(regs, {g.d_of(*target_)});
            if (!path_[i].found)
                SC_REPORT_ERROR(msg::config, (std::string(name()) + ": " + ctl[i].name() +
                                              " latches no register with a path to " + target_->name())
                                                 .c_str());
        }
    }

    void on_fall() {
        if (sel.read().to_uint() != load_code_) return;
        const auto now = sc_core::sc_time_stamp();
        for (std::size_t i = 0; i < ctl.size(); ++i) {
            sc_core::sc_time fall;
            bool fallen = false;
            for (const timed_block* r : regs_[i]) {
                sc_core::sc_time at;
                if (r->last_latch(at) && (!fallen || at > fall)) fall = at, fallen = true;
            }
            if (!fallen || now - fall > path_[i].delay) continue;
            ++violations_;
            std::ostringstream os;
            os << name() << ": " << target_->name() << " loads at " << now << ", only " << (now - fall) << " after "
               << ctl[i].name() << " latched (its path there: " << path_[i].to_string()
               << "); the value loaded is not settled";
            SC_REPORT_WARNING(msg::timing, os.str().c_str());
        }
    }

    const sc_core::sc_object* target_;
    unsigned load_code_;
    std::vector<timing_path> path_;
    std::vector<std::vector<const timed_block*>> regs_;
    unsigned violations_ = 0;
};

}  // namespace shading
