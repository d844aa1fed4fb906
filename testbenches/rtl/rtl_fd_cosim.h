// Co-simulation of our forward-difference evaluators' RTL (rtl/interp/fd_eval.v, fd_eval_var.v,
// Verilated with --sc --pins-sc-uint, so its ports are the same sc_uint buses as ours) in the same
// SystemC simulation as the SystemC unit, on the pins of its bench (testbenches/interp: fd_bench<M>
// or fd_var_bench<MMIN, MMAX>, whose stimulus drives start, len, m and A..D through our unit's
// handshake). At every rising edge the RTL's i_px, valid and last must equal ours; a second monitor
// and checker of the bench's own kinds take the RTL's pixels and check each against the golden model
// (interp::golden_fd), as the bench's checker does ours.
#pragma once

#include <cstddef>
#include <sstream>
#include <systemc>
#include <type_traits>
#include <utility>

#include "testbenches/interp/interp_fd_bench.h"
#include "testbenches/interp/interp_fd_var_bench.h"
#include "testbenches/rtl/rtl_interp_cosim.h"

namespace shading::tb {

// Bench: fd_bench<M> or fd_var_bench<MMIN, MMAX>; Rtl: the Verilated fd_eval (M) or fd_eval_var.
template <class Bench, class Rtl>
class fd_cosim : public sc_core::sc_module {
    using monitor_t = decltype(std::declval<Bench&>().mon);
    using checker_t = decltype(std::declval<Bench&>().checker);
    using sample_t = typename checker_t::sample;
    static constexpr bool has_m = !std::is_same_v<decltype(std::declval<monitor_t&>().m), no_m_pin>;

public:
    sc_core::sc_signal<coef_t> rtl_i_px{"rtl_i_px"};
    sc_core::sc_signal<bool> rtl_valid{"rtl_valid"}, rtl_last{"rtl_last"};

    Bench bench;
    Rtl rtl{"rtl"};
    checker_t rtl_checker;  // the RTL's pixels against the golden model
    monitor_t rtl_mon;
    std::size_t edges = 0, edge_mismatches = 0;  // rising edges compared; those where RTL != ours

    SC_HAS_PROCESS(fd_cosim);
    template <class Intervals>
    fd_cosim(const sc_core::sc_module_name& name, Intervals ivs)
        : sc_module(name), bench("bench", std::move(ivs)),
          rtl_mon("rtl_mon", [this](const sample_t& s) { rtl_checker.check(s); }) {
        rtl.clk(bench.clk); rtl.start(bench.start); rtl.len(bench.len);
        rtl.a(bench.a); rtl.b(bench.b); rtl.c(bench.c); rtl.d(bench.d);
        rtl.i_px(rtl_i_px); rtl.valid(rtl_valid); rtl.last(rtl_last);
        rtl_mon.clk(bench.clk); rtl_mon.start(bench.start); rtl_mon.valid(rtl_valid); rtl_mon.last(rtl_last);
        rtl_mon.len(bench.len);
        rtl_mon.a(bench.a); rtl_mon.b(bench.b); rtl_mon.c(bench.c); rtl_mon.d(bench.d); rtl_mon.i_px(rtl_i_px);
        if constexpr (has_m) {
            rtl.m(bench.m);
            rtl_mon.m(bench.m);
        }
        SC_METHOD(compare);
        sensitive << bench.clk.posedge_event();
        dont_initialize();
    }
    bool finished() const { return bench.finished(); }

private:
    // Reads give the values before this edge: the pixel latched at the last falling edge and the
    // controllers' outputs of the previous rising edge.
    void compare() {
        ++edges;
        const uint64_t ours = bench.i_px.read().to_uint64(), rtl_v = rtl_i_px.read().to_uint64();
        if (ours == rtl_v && bench.valid.read() == rtl_valid.read() && bench.last.read() == rtl_last.read()) return;
        ++edge_mismatches;
        std::ostringstream os;
        os << name() << " at " << sc_core::sc_time_stamp() << ": RTL i_px 0x" << std::hex << rtl_v << " valid "
           << rtl_valid.read() << " last " << rtl_last.read() << ", ours i_px 0x" << ours << " valid "
           << bench.valid.read() << " last " << bench.last.read();
        cosim_report(edge_mismatches, os.str());
    }
};

}  // namespace shading::tb
