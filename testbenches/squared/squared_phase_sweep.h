// Testbench parts for the squared-quadratic device's clock-domain crossing, shared by the SystemC
// models' tests (test_squared_fast.cpp) and the RTL co-simulations (test_rtl_squared*.cpp): a probe
// on strobe 17 and output 29 (the monitor's part), the stream that labels every pixel by its own
// cos (the stimulus's part, with phase_sweep_timing() of specular_tb.h), and the check of the
// probe's log against the hand count of rising edges (the checker's part).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <systemc>
#include <vector>

#include "testbenches/specular/specular_tb.h"

namespace shading::tb {

// The instant of the `edges`-th rising edge of a clock rising at 0, period, 2 period, ... after t
// (a t on an edge counts from the next one: the devices take the clock edge first).
inline sc_core::sc_time rising_edge_after(const sc_core::sc_time& t, const sc_core::sc_time& period, unsigned edges) {
    const double first = std::floor(t / period) + 1;
    return period * (first + edges - 1);
}

// Logs strobe 17's falling edges and, for each, output 29's first rising edge after it; counts
// every further rise before the next fall (a pixel validated twice, or a previous one validated
// again) in `extra_rises`.
class latency_probe : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> ctl17{"ctl17"};
    sc_core::sc_in<bool> out29_valid{"out29_valid"};
    std::vector<sc_core::sc_time> falls, rises;
    unsigned extra_rises = 0;

    SC_HAS_PROCESS(latency_probe);
    explicit latency_probe(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_fall);
        sensitive << ctl17.neg();
        dont_initialize();
        SC_METHOD(on_rise);
        sensitive << out29_valid.pos();
        dont_initialize();
    }

private:
    void on_fall() {
        falls.push_back(sc_core::sc_time_stamp());
        armed_ = true;
    }
    void on_rise() {
        if (!armed_) {
            if (!falls.empty()) ++extra_rises;
            return;  // before the first fall: power-up, output 29 follows the idle-high strobe
        }
        rises.push_back(sc_core::sc_time_stamp());
        armed_ = false;
    }
    bool armed_ = false;
};

// The n of every pixel of a list of surfaces that each load n, in streaming order.
inline std::vector<unsigned> pixel_ns(const std::vector<surface>& s) {
    std::vector<unsigned> ns;
    for (const auto& x : s) ns.insert(ns.end(), x.cos_codes.size(), x.n);
    return ns;
}

// The phase sweep's stream: for each n, `pixels` distinct cos codes (each pixel labelled by its
// own), with k_s*I of its own per n.
inline std::vector<surface> phase_sweep_surfaces(const std::vector<unsigned>& ns, std::size_t pixels) {
    std::vector<surface> s;
    for (std::size_t j = 0; j < ns.size(); ++j) {
        std::vector<uint32_t> codes;
        for (std::size_t i = 0; i < pixels; ++i) codes.push_back(static_cast<uint32_t>(0x4000 + 0xF1 * i + 0x11 * j));
        s.push_back({ns[j], {255u - static_cast<unsigned>(j), 200, 77u + static_cast<unsigned>(j)}, codes});
    }
    return s;
}

// Checks a probe's log against the hand count `edges(n)`: every strobe validated exactly once, at
// the edges(n)-th rising edge after its fall (plus `gate`), never again before the next strobe.
// Returns the number of strobes that were not.
template <typename Edges>
unsigned phase_sweep_wrong(const std::vector<sc_core::sc_time>& falls, const std::vector<sc_core::sc_time>& rises,
                           unsigned extra_rises, const std::vector<unsigned>& ns, const sc_core::sc_time& period,
                           const sc_core::sc_time& gate, Edges edges) {
    unsigned wrong = extra_rises;
    if (falls.size() != ns.size() || rises.size() != ns.size()) {
        ADD_FAILURE() << ns.size() << " pixels, " << falls.size() << " strobes, " << rises.size() << " rises of output 29";
        return wrong + 1;
    }
    for (std::size_t i = 0; i < ns.size(); ++i) {
        const sc_core::sc_time want = rising_edge_after(falls[i], period, edges(ns[i])) + gate;
        if (rises[i] == want) continue;
        if (++wrong <= 10)
            ADD_FAILURE() << "n = " << ns[i] << ": strobe fell at " << falls[i] << " ("
                          << (falls[i].value() % period.value()) << " ps into the clock's period), output 29 rose at "
                          << rises[i] << ", want " << want;
    }
    return wrong;
}
// The phases of a clock's period, on a grid of `step` from the rising edge (0) on, at which no
// strobe fell: 0 when the sweep visited every one, the clock's edges included.
inline std::size_t phases_missed(const std::vector<sc_core::sc_time>& falls, const sc_core::sc_time& period,
                                 const sc_core::sc_time& step) {
    const uint64_t slots = period.value() / step.value();
    std::vector<bool> seen(slots, false);
    for (const auto& f : falls) {
        const uint64_t in_period = f.value() % period.value();
        if (in_period % step.value() == 0) seen[in_period / step.value()] = true;
    }
    std::size_t missed = 0;
    for (bool b : seen) missed += b ? 0 : 1;
    return missed;
}

template <typename Edges>
unsigned phase_sweep_wrong(const latency_probe& p, const std::vector<unsigned>& ns, const sc_core::sc_time& period,
                           const sc_core::sc_time& gate, Edges edges) {
    return phase_sweep_wrong(p.falls, p.rises, p.extra_rises, ns, period, gate, edges);
}

}  // namespace shading::tb
