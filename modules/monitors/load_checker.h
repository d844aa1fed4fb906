// Assertion monitor (not a hardware block) for a clocked register that takes a value computed from
// strobe-latched registers: the squared-quadratic device's RG_SQ, which at a LOAD latches ADD11's
// quadratic at n', a combinational function of RG1 (n) and RG2 (cos), both latched by strobes
// (UA 60553, Fig. 3) asynchronous to clk. At every falling edge of clk where `sel` equals the load
// code, each strobe's registers must have latched at least their path to the target's data input
// ago; otherwise the value taken is not settled: shading/timing. Paths are derived at end of
// elaboration from the parent module's timing graph (core/timing_graph.h), as timing_checker does.
// A strobe whose registers feed a controller instead (the square-and-multiply device's RG1, whose
// LZC and barrel shift give its controller the bits of n to walk) is checked at the same LOAD
// against the rising edge that took it, the controller's last latch, over its path to the
// controller's inputs (sampled_by).
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

    // Strobe i's registers are read by `ctrl` (a register clocked on clk's rising edge) on the
    // ports `inputs` at the edge that takes a LOAD: its path ends there, and it is checked against
    // that edge. Call before elaboration ends.
    void sampled_by(std::size_t i, const timed_block& ctrl, std::vector<const sc_core::sc_port_base*> inputs) {
        sampler_.resize(ctl.size());
        sampler_.at(i) = {&ctrl, std::move(inputs)};
    }

    // Strobe i's derived path into the target's data input, or into its controller's inputs
    // (sampled_by; valid from end of elaboration on).
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
            std::vector<timing_graph::channel> to{g.d_of(*target_)};
            std::string what = target_->name();
            if (sampled(i)) {
                to.clear();
                for (auto* p : sampler_[i].inputs) to.push_back(timing_graph::channel_of(*p));
                what = dynamic_cast<const sc_core::sc_object&>(*sampler_[i].ctrl).name();
            }
            path_[i] = g.longest_from_registers(regs, to);
            if (!path_[i].found)
                SC_REPORT_ERROR(msg::config,
                                (std::string(name()) + ": " + ctl[i].name() + " latches no register with a path to " + what)
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
            // A sampled strobe: the instant the controller took the LOAD (a latch after it is not this
            // LOAD's: the controller read the register before).
            sc_core::sc_time at = now;
            if (sampled(i) && !sampler_[i].ctrl->last_latch(at)) continue;
            if (!fallen || fall > at || at - fall > path_[i].delay) continue;
            ++violations_;
            std::ostringstream os;
            os << name() << ": " << target_->name() << " loads at " << now;
            if (sampled(i)) os << " as taken at " << at;
            os << ", only " << (at - fall) << " after " << ctl[i].name() << " latched (its path there: "
               << path_[i].to_string() << "); the value loaded is not settled";
            SC_REPORT_WARNING(msg::timing, os.str().c_str());
        }
    }

    struct sampler {
        const timed_block* ctrl = nullptr;
        std::vector<const sc_core::sc_port_base*> inputs;
    };
    bool sampled(std::size_t i) const { return i < sampler_.size() && sampler_[i].ctrl != nullptr; }

    const sc_core::sc_object* target_;
    std::vector<sampler> sampler_;
    unsigned load_code_;
    std::vector<timing_path> path_;
    std::vector<std::vector<const timed_block*>> regs_;
    unsigned violations_ = 0;
};

}  // namespace shading
