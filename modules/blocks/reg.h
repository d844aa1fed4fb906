// Register written on the falling edge of its control input (UA 60553, Fig. 3: "write on the
// trailing edge"). Checks that the data input is stable at that edge: a change within `setup`
// before the edge, or at the same instant, is reported (shading/setup) and the register keeps
// the value that was stable before that late change, whichever delta cycle the change came in.
#pragma once

#include <sstream>
#include <systemc>

#include "core/comb_delay.h"
#include "core/report_ids.h"
#include "core/timed_block.h"

namespace shading {

template <unsigned W>
class reg : public sc_core::sc_module, public timed_block {
public:
    using word = sc_dt::sc_uint<W>;
    sc_core::sc_in<bool> ctl{"ctl"};
    sc_core::sc_in<word> d{"d"};
    sc_core::sc_out<word> q{"q"};

    SC_HAS_PROCESS(reg);
    explicit reg(const sc_core::sc_module_name& name,
                 const sc_core::sc_time& clk_to_q = delay_default::reg_clk_to_q,
                 const sc_core::sc_time& setup = sc_core::SC_ZERO_TIME)
        : sc_module(name), setup_(setup), drv_(q, clk_to_q) {
        // One process for the edge and the data input: the output's only writer (a zero clock-to-q
        // writes q from it directly, core/comb_delay.h). A data change in the edge's own delta is
        // taken first, so the edge sees it as the late change it is.
        SC_METHOD(on_event);
        sensitive << ctl.neg() << d;
        dont_initialize();
    }

    const sc_core::sc_time& clk_to_q() const { return drv_.delay(); }
    const sc_core::sc_time& setup() const { return setup_; }
    // timed_block: a path starts at q (clock-to-q) and ends at d.
    const sc_core::sc_time& delay() const override { return drv_.delay(); }
    const sc_core::sc_port_base* clock_port() const override { return &ctl; }
    const sc_core::sc_port_base* data_port() const override { return &d; }
    const sc_core::sc_time& setup_time() const override { return setup_; }
    unsigned violations() const { return violations_; }
    bool last_latch(sc_core::sc_time& at) const override {
        if (edge_seen_) at = last_edge_;
        return edge_seen_;
    }

private:
    void start_of_simulation() override { current_ = stable_ = d.read(); }

    void on_event() {
        if (d.event()) on_data();
        if (ctl.negedge()) on_falling_edge();
    }

    void on_falling_edge() {
        const auto now = sc_core::sc_time_stamp();
        last_edge_ = now;
        edge_seen_ = true;
        if (changed_ever_ && (changed_at_ == now || now - changed_at_ < setup_)) {
            violation(stable_);
            return;
        }
        drv_.drive(current_);
    }

    void on_data() {
        const auto now = sc_core::sc_time_stamp();
        if (!changed_ever_ || changed_at_ != now) stable_ = current_;  // value held before `now`
        current_ = d.read();
        changed_at_ = now;
        changed_ever_ = true;
        // The edge was processed earlier in this same instant: it latched the old value already.
        if (edge_seen_ && last_edge_ == now && reported_at_ != now) violation(stable_);
    }

    void violation(const word& kept) {
        const auto now = sc_core::sc_time_stamp();
        if (reported_at_ == now && violations_ > 0) return;
        reported_at_ = now;
        ++violations_;
        std::ostringstream os;
        os << name() << ": data input changed at the latching edge (" << now << "): keeping 0x"
           << std::hex << kept.to_uint64() << ", new value 0x" << current_.to_uint64() << " ignored";
        drv_.drive(kept);
        SC_REPORT_WARNING(msg::setup, os.str().c_str());
    }

    sc_core::sc_time setup_;
    inertial_driver<word> drv_;
    word current_{}, stable_{};
    sc_core::sc_time changed_at_, last_edge_, reported_at_;
    bool changed_ever_ = false, edge_seen_ = false;
    unsigned violations_ = 0;
};

}  // namespace shading
