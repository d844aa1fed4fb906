// The shading pipeline's clock from its phase requirements: every clocked unit's phase_checker
// (monitors/phase_checker.h) derives, at the end of elaboration, the shortest high and low phases
// and period its own paths need, and the top's own checker those of every path of the top, also
// between its units; the pipeline runs on one clock, so its clock must give every checker all three.
// Shared by timing_report (which prints them) and test_timing_graph (which checks them against hand
// sums of core/comb_delay.h's delays).
#pragma once

#include <algorithm>
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "monitors/phase_checker.h"
#include "pipeline/cell_unit.h"
#include "testbenches/pipeline/pipeline_tops.h"

namespace shading::timing {

// A clock of `high` then `low` from time 0, or none (both zero): a plain net, nothing simulated.
struct test_clock {
    explicit test_clock(const sc_core::sc_time& high = {}, const sc_core::sc_time& low = {}) {
        if (high + low == sc_core::SC_ZERO_TIME) return;
        clock = std::make_unique<sc_core::sc_clock>("clock", high + low, high / (high + low));
    }
    sc_core::sc_signal_in_if<bool>& net() { return clock ? static_cast<sc_core::sc_signal_in_if<bool>&>(*clock) : plain; }

private:
    std::unique_ptr<sc_core::sc_clock> clock;
    sc_core::sc_signal<bool> plain{"plain_clk"};
};

// A shading pipeline with every pin on a net of its own (the phase checkers derive their paths from
// the elaborated, fully bound design), its clock `clk` (none by default: nothing is simulated).
template <class AGen, pipeline::evaluator EVAL>
struct bound_pipeline : sc_core::sc_module {
    using pins = pipeline_pins;
    shading_pipeline<AGen, EVAL> dut;

    // fd_m: as the pipeline's (0: the forward-difference evaluator takes any m per interval).
    bound_pipeline(const sc_core::sc_module_name& name, unsigned fd_m, test_clock* clk = nullptr)
        : sc_module(name),
          dut("dut", overflow_mode::saturate, AGen::default_config(), interp::sample_set::case1,
              interp::div3_mode::shift_add, fd_m) {
        bind_inputs();
        dut.clk(clk ? clk->net() : clk_net);
        dut.ready(ready_net);
        dut.px_valid(px_valid_net); dut.px_x(px_x_net); dut.px_y(px_y_net);
        dut.px_r(px_r_net); dut.px_g(px_g_net); dut.px_b(px_b_net);
    }

private:
    template <class T>
    using net = sc_core::sc_signal<T>;
    net<bool> clk_net, start_net, load_frame_net, ready_net, px_valid_net;
    net<pins::coord_t> y_net, x0_net, px_x_net, px_y_net;
    net<pins::len_t> len_net;
    net<pins::m_t> m_net;
    net<pins::bit_t> deg2_net;
    net<pins::cos_t> nh_net[4], nl_net[4];
    net<pins::n_t> n_net;
    net<pins::ksi_t> ksi_net[3];
    net<pins::kdi_t> kdi_net[3];
    net<pins::sample_t> amb_net[3], px_r_net, px_g_net, px_b_net;

    void bind_inputs() {
        sc_core::sc_in<pins::cos_t>* nh[] = {&dut.in_nh1, &dut.in_nh2, &dut.in_nh3, &dut.in_nh4};
        sc_core::sc_in<pins::cos_t>* nl[] = {&dut.in_nl1, &dut.in_nl2, &dut.in_nl3, &dut.in_nl4};
        for (int k = 0; k < 4; ++k) {
            (*nh[k])(nh_net[k]);
            (*nl[k])(nl_net[k]);
        }
        dut.start(start_net);
        dut.load_frame(load_frame_net);
        dut.in_y(y_net);
        dut.in_x0(x0_net);
        dut.in_len(len_net);
        dut.in_m(m_net);
        dut.in_deg2(deg2_net);
        dut.in_n(n_net);
        sc_core::sc_in<pins::ksi_t>* ksi[] = {&dut.in_ksi_r, &dut.in_ksi_g, &dut.in_ksi_b};
        sc_core::sc_in<pins::kdi_t>* kdi[] = {&dut.in_kdi_r, &dut.in_kdi_g, &dut.in_kdi_b};
        sc_core::sc_in<pins::sample_t>* amb[] = {&dut.in_amb_r, &dut.in_amb_g, &dut.in_amb_b};
        for (int c = 0; c < 3; ++c) {
            (*ksi[c])(ksi_net[c]);
            (*kdi[c])(kdi_net[c]);
            (*amb[c])(amb_net[c]);
        }
    }
};

// The cell unit (ours) with every pin on a net of its own, as bound_pipeline.
struct bound_cell : sc_core::sc_module {
    cell_unit dut{"dut"};

    explicit bound_cell(const sc_core::sc_module_name& name, test_clock* clk = nullptr) : sc_module(name) {
        dut.clk(clk ? clk->net() : clk_net); dut.start(start_net); dut.ready(ready_net);
        dut.in_x0(x0_net); dut.in_y0(y0_net); dut.in_m(m_net);
        dut.in_lat_r.bind(lat_r); dut.in_lat_g.bind(lat_g); dut.in_lat_b.bind(lat_b);
        dut.px_valid(px_valid_net); dut.px_x(px_x_net); dut.px_y(px_y_net);
        dut.px_r(px_r_net); dut.px_g(px_g_net); dut.px_b(px_b_net);
    }

private:
    sc_core::sc_signal<bool> clk_net, start_net, ready_net, px_valid_net;
    sc_core::sc_signal<cell_unit::coord_t> x0_net, y0_net, px_x_net, px_y_net;
    sc_core::sc_signal<cell_unit::m_t> m_net;
    sc_core::sc_vector<sc_core::sc_signal<cell_unit::sample_t>> lat_r{"lat_r", 9}, lat_g{"lat_g", 9}, lat_b{"lat_b", 9};
    sc_core::sc_signal<cell_unit::sample_t> px_r_net, px_g_net, px_b_net;
};

// One clocked unit's requirements: the unit (the checker's parent, by hierarchical name) and the
// shortest high and low phases its paths need.
struct unit_phases {
    std::string unit;
    const phase_checker* chk;
};

// Every phase_checker under `top`, in the hierarchy's order (call after elaboration).
inline void collect(const sc_core::sc_object& top, std::vector<unit_phases>& out) {
    for (const auto* c : top.get_child_objects()) {
        if (const auto* p = dynamic_cast<const phase_checker*>(c))
            out.push_back({p->get_parent_object()->name(), p});
        collect(*c, out);
    }
}

// The one clock the units share: every unit's high phase, every unit's low phase, and every path
// over both phases (the whole top's checker holds those between units). A phase equal to its
// requirement is a violation too (phase_checker.h), so a usable period is strictly longer than these.
struct clock_bound {
    sc_core::sc_time high, low_phase, period;  // the largest requirements
    // The shortest period with the high phase at its shortest, and at 50 % duty.
    sc_core::sc_time best_duty() const { return std::max(high + low_phase, period); }
    sc_core::sc_time half_duty() const { return std::max(2 * std::max(high, low_phase), period); }
    // The low phase the best duty leaves.
    sc_core::sc_time low() const { return best_duty() - high; }
};

inline clock_bound shortest_clock(const std::vector<unit_phases>& units) {
    clock_bound b;
    for (const auto& u : units) {
        b.high = std::max(b.high, u.chk->min_high());
        b.low_phase = std::max(b.low_phase, u.chk->min_low_phase());
        b.period = std::max(b.period, u.chk->min_period());
    }
    return b;
}

}  // namespace shading::timing
