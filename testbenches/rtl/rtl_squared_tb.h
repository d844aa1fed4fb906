// Testbench parts shared by the co-simulation of the squared-quadratic device's RTL
// (test_rtl_squared.cpp, test_rtl_squared_cover.cpp) and the checks of the two designs it is
// compared with (test_rtl_squared_variants.cpp): the strobe timings, a probe that logs when output
// 29 rises after each latch, the clocks per sample each design must take, from the golden models,
// and the checker's golden function and the typed suites' variants (an RTL and its overflow mode).
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <systemc>
#include <vector>

#include "arith/squared_arith.h"
#include "arith/sqmul_arith.h"
#include "testbenches/specular/specular_tb.h"

namespace shading::tb {

// The checker's golden function: golden_squared in mode m (of n + n_offset: for negative tests).
inline specular_checker::golden_fn squared_golden(overflow_mode m, unsigned n_offset = 0) {
    return [m, n_offset](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        datapath_nets r{};
        r.out = golden_squared(n + n_offset, c, k, m).out;
        return r;
    };
}

// A verilated squared device and the overflow mode it was built with, for typed test suites.
template <typename Rtl, overflow_mode Mode>
struct squared_variant {
    using rtl = Rtl;
    static constexpr overflow_mode mode = Mode;
};

struct squared_variant_names {
    template <typename T>
    static std::string GetName(int) {
        return T::mode == overflow_mode::saturate ? "Saturate" : "Wrap";
    }
};

// A timing that shows the clocks per sample: strobe 17 low for 5 ns only, so output 29 = strobe
// 17 AND done rises when done does; high for the rest of a period of `clocks` clocks. The
// stimulus loads the next surface's registers (and ends the run) half the high phase after
// strobe 17 rose, so `clocks` must be at least twice the longest result's edges: the loads then
// come after output 29 rose. A pixel period of whole clocks keeps strobe 17's falls off every
// clock edge (they fall on half nanoseconds; surface loads shift them by 8 ns).
inline strobe_timing done_timing(unsigned clocks, const sc_core::sc_time& clk_period = sc_core::sc_time(20, sc_core::SC_NS)) {
    strobe_timing t;
    t.clk_period = clk_period;
    t.t_low = sc_core::sc_time(5, sc_core::SC_NS);
    t.t_high = clk_period * static_cast<double>(clocks) - t.t_low;
    t.cos_lead = t.t_high / 2;
    return t;
}

// Rising edges of clk from strobe 17's fall to done's rise, the taking edge counted as the first.
// The squared-quadratic device: the taking edge, k squares, the done edge.
inline unsigned squared_edges(unsigned n) { return golden_squared_a(n).k + 2; }
// The square-and-multiply baseline: the taking edge, one per square and per multiplication, done.
inline unsigned sqmul_edges(unsigned n) {
    const auto g = golden_sqmul(n, 0, {0, 0, 0}, overflow_mode::saturate);
    return g.squares + g.multiplies + 2;
}
// The right-to-left square-and-multiply design: the taking edge, one per bit of n up to its
// leading one (a square and, for a 1 bit, a multiplication in the same clock), the done edge.
inline unsigned sqmul_r2l_edges(unsigned n) {
    return golden_sqmul_r2l(n, 0, {0, 0, 0}, overflow_mode::saturate).steps + 2;
}

// The instant of the `edges`-th rising edge of a clock rising at 0, period, 2 period, ... after t
// (t never on an edge here).
inline sc_core::sc_time rising_edge_after(const sc_core::sc_time& t, const sc_core::sc_time& period, unsigned edges) {
    const double first = std::floor(t / period) + 1;
    return period * (first + edges - 1);
}

// Logs strobe 17's falling edges and, for each, output 29's first rising edge after it.
class latency_probe : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> ctl17{"ctl17"};
    sc_core::sc_in<bool> out29_valid{"out29_valid"};
    std::vector<sc_core::sc_time> falls, rises;

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
        if (!armed_) return;  // power-up: output 29 follows the idle-high strobe
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

}  // namespace shading::tb
