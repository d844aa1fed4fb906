// Testbench parts shared by the co-simulation of the squared-quadratic device's RTL
// (test_rtl_squared.cpp, test_rtl_squared_cover.cpp) and the checks of the two designs it is
// compared with (test_rtl_squared_variants.cpp): the strobe timings, the clocks per sample each
// design must take, from the golden models, and the checker's golden function and the typed
// suites' variants (an RTL and its overflow mode); the latency probe is
// testbenches/squared/squared_phase_sweep.h's.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <systemc>
#include <vector>

#include "arith/squared_arith.h"
#include "arith/sqmul_arith.h"
#include "testbenches/specular/specular_tb.h"
#include "testbenches/squared/squared_phase_sweep.h"

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

// Rising edges of clk from strobe 17's fall to done's rise, counted by hand from the handshake
// (rtl/squared/sq_ctrl.v): the first edge after the fall clocks the request into the
// synchroniser's first flip-flop, the second into its second, the third takes it (LOAD).
// The squared-quadratic device: those three, k squares, the done edge.
inline unsigned squared_edges(unsigned n) { return 3 + golden_squared_a(n).k + 1; }
// The square-and-multiply baseline: those three, one per square and per multiplication, done.
inline unsigned sqmul_edges(unsigned n) {
    const auto g = golden_sqmul(n, 0, {0, 0, 0}, overflow_mode::saturate);
    return 3 + g.squares + g.multiplies + 1;
}
// The right-to-left square-and-multiply design (rtl/sqmul/sqmul_r2l_ctrl.v, the same handshake):
// those three, one per bit of n up to its leading one (a square and, for a 1 bit, a
// multiplication in the same clock), the done edge.
inline unsigned sqmul_r2l_edges(unsigned n) {
    return 3 + golden_sqmul_r2l(n, 0, {0, 0, 0}, overflow_mode::saturate).steps + 1;
}

}  // namespace shading::tb
