// Testbench parts for the squared-quadratic device's abandon-and-restart path (modules/squared/
// README.md, bad input: strobe 17 before the previous result is valid drops that result, and the
// new cos is taken at the next rising edge), for the co-simulation and the bench programs:
//   restart_episode, restart_chain - the plan: per surface a reference pixel, then chains of
//                       strobes, each one falling at a chosen distance after the one before;
//   planned            - what the plan must produce, counted from the plan alone: strobes, dropped
//                       results, pixels with an output 29, shading/input reports;
//   restart_stimulus   - drives Fig. 1's pins (the specular stimulus's port names) as the plan says.
//                       It never assumes the device's clocks per sample: on each surface's reference
//                       pixel it measures them on the model's output 29 (the rising edge at which
//                       output 29 rose), and places every restart relative to that edge;
//   restart_plan       - the standard plan: every distance, a chain of three drops, cos > 1.0.
// The samples are taken by specular_monitor (its latch of the last strobe 17 before output 29
// names the pixel that came out) and checked by specular_checker.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <systemc>
#include <vector>

#include "core/report_ids.h"
#include "formats/specular_formats.h"
#include "formats/squared_formats.h"
#include "testbenches/specular/specular_tb.h"
#include "testbenches/squared/squared_cover.h"

namespace shading::tb {

// Where a restarting strobe 17 falls (P the clock period), counted from the previous strobe's
// taking edge T (the (squared::sync_stages + 1)-th rising edge of clk after its fall: its request
// crosses the synchroniser's flip-flops first) and its done edge D (the rising edge at which
// output 29 rises for it, from the surface's reference pixel):
enum class restart_at {
    before_take,   // half a clock after the previous fall, before its first rising edge: not yet taken
    load_clock,    // T + 3P/4: the clock after the taking edge, RG_SQ holding the loaded quadratic
    mid_squaring,  // halfway from T to D, 3P/4 into its clock
    last_clock,    // D - P/4: one clock before done
    after_done,    // D + 3P/4: the previous result was valid (no drop; both pixels come out)
};

inline bool drops(restart_at a) { return a != restart_at::after_done; }

// Strobes in a row: the first on an idle device, P/4 after a rising edge; each next one at at[i - 1]
// of the one before (before_take only right after the first); the last runs to output 29.
struct restart_chain {
    std::vector<uint32_t> cos;   // in18 at each strobe
    std::vector<restart_at> at;  // cos.size() - 1 distances
};

// A surface: n and k_s*I loaded while idle, a reference pixel (runs to output 29), the chains.
struct restart_episode {
    unsigned n = 1;
    std::array<unsigned, 3> ksi{};
    uint32_t ref_cos = 0;
    std::vector<restart_chain> chains;
};

struct restart_counts {
    std::size_t strobes = 0, drops = 0, pixels = 0, input_reports = 0;
};

// Counted from the plan: every strobe placed before done drops the result before it; a pixel comes
// out for each reference, each strobe followed by one after done, and each chain's last strobe;
// the model reports each out-of-range n and each cos > 1.0 latched (dropped or not).
inline restart_counts planned(const std::vector<restart_episode>& plan) {
    restart_counts c;
    for (const auto& e : plan) {
        if (e.n < squared::n_min || e.n > squared::n_max) ++c.input_reports;
        ++c.strobes;
        ++c.pixels;
        c.input_reports += e.ref_cos > spec::cos_one ? 1 : 0;
        for (const auto& ch : e.chains) {
            c.strobes += ch.cos.size();
            for (uint32_t x : ch.cos) c.input_reports += x > spec::cos_one ? 1 : 0;
            for (restart_at a : ch.at) (drops(a) ? c.drops : c.pixels) += 1;
            ++c.pixels;
        }
    }
    return c;
}

class restart_stimulus : public sc_core::sc_module {
public:
    using items = std::vector<restart_episode>;

    sc_core::sc_out<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_out<n_t> in16_n{"in16_n"};
    sc_core::sc_out<cos_t> in18_cos{"in18_cos"};
    sc_core::sc_out<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};
    sc_core::sc_in<bool> out29_valid{"out29_valid"};  // the model's: the clocks per sample, measured

    // From `t`: the clock period P (the clock rises at 0, P, 2P, ...; P >= 20 ns keeps every load
    // later than RG2's path after its strobe) and the load strobes' pulse. Strobe 17 stays low P/4;
    // in18 changes P/8 before it falls.
    SC_HAS_PROCESS(restart_stimulus);
    restart_stimulus(const sc_core::sc_module_name& name, items plan, const strobe_timing& t)
        : sc_module(name), plan_(std::move(plan)), p_(t.clk_period), load_pulse_(t.load_pulse) {
        SC_THREAD(run);
    }

    bool finished() const { return finished_; }
    unsigned timeouts() const { return timeouts_; }  // chains whose output 29 never rose
    // Per surface: rising edges from the reference pixel's taking edge to its done edge, both counted
    // (the taking edge placed by squared::sync_stages; the done edge measured on the model).
    const std::vector<unsigned>& edges() const { return edges_; }
    // Chains whose last pixel took another number of edges than the surface's reference pixel.
    unsigned latency_changes() const { return latency_changes_; }

private:
    void run() {
        ctl17.write(true);  // idle high (Fig. 3)
        for (const auto& e : plan_) {
            load(e);
            const unsigned ref = chain({{e.ref_cos}, {}}, 0);
            edges_.push_back(ref);
            if (ref == 0) break;  // no output 29: nothing to place the restarts against
            for (const auto& c : e.chains)
                if (chain(c, ref) != ref) ++latency_changes_;
        }
        finished_ = true;
        sc_core::sc_stop();
    }

    void load(const restart_episode& e) {
        in16_n.write(n_t(e.n));
        in19_ksi_r.write(ksi_t(e.ksi[0]));
        in21_ksi_g.write(ksi_t(e.ksi[1]));
        in23_ksi_b.write(ksi_t(e.ksi[2]));
        for (auto* ctl : {&ctl15, &ctl20, &ctl22, &ctl24}) {  // the falling edge latches
            ctl->write(true);
            wait(load_pulse_);
            ctl->write(false);
            wait(load_pulse_);
        }
    }

    // Runs one chain with `edges` from the reference (0: the reference itself); returns the edges
    // its last pixel took, 0 when output 29 did not rise within 64 clocks.
    unsigned chain(const restart_chain& c, unsigned edges) {
        const sc_core::sc_time e = edge_after(sc_core::sc_time_stamp() + p_);
        sc_core::sc_time fall = e + p_ / 4, take = taking_edge(fall);
        strobe(c.cos[0], fall);
        for (std::size_t i = 1; i < c.cos.size(); ++i) {
            fall = place(c.at.at(i - 1), fall, take, edges);
            strobe(c.cos[i], fall);
            take = taking_edge(fall);
        }
        const sc_core::sc_time start = sc_core::sc_time_stamp(), limit = 64 * p_;
        wait(limit, out29_valid.posedge_event());
        if (sc_core::sc_time_stamp() - start >= limit) {
            ++timeouts_;
            return 0;
        }
        const sc_core::sc_time done = p_ * std::floor(sc_core::sc_time_stamp() / p_);
        return static_cast<unsigned>(std::lround((done - take) / p_)) + 1;
    }

    sc_core::sc_time place(restart_at a, const sc_core::sc_time& prev, const sc_core::sc_time& take, unsigned edges) {
        const sc_core::sc_time done = take + p_ * (static_cast<double>(edges) - 1);
        switch (a) {
            case restart_at::before_take: return prev + p_ / 2;
            case restart_at::load_clock: return take + p_ * 0.75;
            case restart_at::mid_squaring: return take + p_ * (std::floor((static_cast<double>(edges) - 2) / 2) + 0.75);
            case restart_at::last_clock: return done - p_ / 4;
            case restart_at::after_done: return done + p_ * 0.75;
        }
        return done;
    }

    // in18 = cos P/8 before `fall`; strobe 17 low from `fall` for P/4. A plan that asks for a
    // strobe in the past, or one at a clock edge, is reported (shading/config).
    void strobe(uint32_t cos, const sc_core::sc_time& fall) {
        const sc_core::sc_time now = sc_core::sc_time_stamp();
        if (fall < now + p_ / 8 || std::fmod(fall / p_ * 2, 1.0) == 0.0) {
            std::ostringstream os;
            os << name() << ": a strobe asked for at " << fall << " (now " << now
               << ") is in the past or on a clock edge: the plan does not fit this device's clocks";
            SC_REPORT_ERROR(msg::config, os.str().c_str());
            return;
        }
        wait(fall - p_ / 8 - now);
        in18_cos.write(cos_t(cos));
        wait(p_ / 8);
        ctl17.write(false);
        wait(p_ / 4);
        ctl17.write(true);
    }

    sc_core::sc_time edge_after(const sc_core::sc_time& t) const { return p_ * (std::floor(t / p_) + 1); }
    // The rising edge that takes a strobe falling at t (never on an edge): the synchroniser's
    // squared::sync_stages edges, then the controller's.
    sc_core::sc_time taking_edge(const sc_core::sc_time& t) const {
        return edge_after(t) + p_ * static_cast<double>(squared::sync_stages);
    }

    items plan_;
    sc_core::sc_time p_, load_pulse_;
    std::vector<unsigned> edges_;
    unsigned timeouts_ = 0, latency_changes_ = 0;
    bool finished_ = false;
};

// For n: the reference at cos^n near 0.01; chains restarting at each distance; one after done (no
// drop); three drops in a row. cos near 0.5, 0.1 and 0.01 (cos_codes_near_levels) and above 1.0,
// so each pixel's outputs tell which cos came out.
inline restart_episode restart_plan(unsigned n) {
    const auto level = [n](double x) { return cos_codes_near_levels(n, {x}, 0).front(); };
    const uint32_t c5 = level(0.5), c1 = level(0.1), c01 = level(0.01);
    restart_episode e{n, {255, (37 * n) % 256, (101 * n + 7) % 256}, c01, {}};
    for (restart_at a : {restart_at::before_take, restart_at::load_clock, restart_at::mid_squaring,
                         restart_at::last_clock})
        e.chains.push_back({{c5, c1}, {a}});
    e.chains.push_back({{c1, 0x8001}, {restart_at::after_done}});
    e.chains.push_back({{c5, 0xC000, c01, c1},
                        {restart_at::before_take, restart_at::mid_squaring, restart_at::last_clock}});
    return e;
}

inline std::vector<restart_episode> restart_plans(unsigned first, unsigned last) {
    std::vector<restart_episode> plan;
    for (unsigned n = first; n <= last; ++n) plan.push_back(restart_plan(n));
    return plan;
}

}  // namespace shading::tb
