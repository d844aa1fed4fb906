// Testbench parts for the forward-difference evaluator with a per-interval length (fd_eval_var.h):
// intervals of 2^m pixels, m given per interval, one pixel per clock; each pixel checked against
// interp::golden_fd(coefs, m, len) and against the Horner unit's golden result at the same t.
// Stimulus, monitor and checker: interp_fd_bench.h's, with the m pin.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <systemc>
#include <vector>

#include "interp/fd_eval_var.h"
#include "testbenches/interp/interp_bench_common.h"
#include "testbenches/interp/interp_fd_bench.h"

namespace shading::tb {

struct fd_var_interval {
    interp::cubic_coefs k;
    unsigned m = 0;
    unsigned len = 0;
};

// What the evaluator makes of an interval (fd_ctrl_var): m neither 0 nor MMIN..MMAX -> MMAX; len
// outside 1..2^m -> 2^m. Independent of the controller's code: from its documented rule.
template <unsigned MMIN, unsigned MMAX>
fd_var_interval fd_var_effective(fd_var_interval iv) {
    if (iv.m != 0 && (iv.m < MMIN || iv.m > MMAX)) iv.m = MMAX;
    if (iv.len == 0 || iv.len > (1u << iv.m)) iv.len = 1u << iv.m;
    return iv;
}

using fd_var_sample = fd_sample_of<fd_var_interval>;

// Stimulus, monitor and checker: interp_fd_bench.h's, with the m pin.
template <unsigned MMIN, unsigned MMAX>
using fd_var_stimulus = fd_stimulus_of<fd_var_interval, typename fd_eval_var<MMIN, MMAX>::len_t,
                                       typename fd_eval_var<MMIN, MMAX>::m_t>;
template <unsigned MMIN, unsigned MMAX>
using fd_var_monitor = fd_monitor_of<fd_var_interval, typename fd_eval_var<MMIN, MMAX>::len_t,
                                     typename fd_eval_var<MMIN, MMAX>::m_t>;

template <unsigned MMIN, unsigned MMAX>
class fd_var_checker : public fd_checker_of<fd_var_interval> {
public:
    fd_var_checker()
        : fd_checker_of<fd_var_interval>(
              [](const fd_var_interval& iv) {
                  const fd_var_interval e = fd_var_effective<MMIN, MMAX>(iv);
                  return fd_effective{e.k, e.m, e.len};
              },
              interp::fd_fmt.frac, true) {}
};

template <unsigned MMIN, unsigned MMAX>
class fd_var_bench : public sc_core::sc_module {
public:
    using len_t = typename fd_eval_var<MMIN, MMAX>::len_t;
    using m_t = typename fd_eval_var<MMIN, MMAX>::m_t;
    sc_core::sc_clock clk;
    sc_core::sc_signal<bool> start{"start"}, valid{"valid"}, last{"last"};
    sc_core::sc_signal<len_t> len{"len"};
    sc_core::sc_signal<m_t> m{"m"};
    sc_core::sc_signal<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"}, i_px{"i_px"};

    fd_var_checker<MMIN, MMAX> checker;
    fd_eval_var<MMIN, MMAX> dut{"dut"};
    fd_var_stimulus<MMIN, MMAX> stim;
    fd_var_monitor<MMIN, MMAX> mon;

    fd_var_bench(const sc_core::sc_module_name& name, std::vector<fd_var_interval> ivs, const interp_clock& ck = {})
        : sc_module(name), clk("clk", ck.period(), ck.duty()), stim("stim", std::move(ivs)),
          mon("mon", [this](const fd_var_sample& s) { checker.check(s); }) {
        checker.set_period(ck.period());
        dut.clk(clk); dut.start(start); dut.len(len); dut.m(m);
        dut.a(a); dut.b(b); dut.c(c); dut.d(d);
        dut.i_px(i_px); dut.valid(valid); dut.last(last);
        stim.clk(clk); stim.valid(valid); stim.last(last); stim.start(start); stim.len(len); stim.m(m);
        stim.a(a); stim.b(b); stim.c(c); stim.d(d);
        mon.clk(clk); mon.start(start); mon.valid(valid); mon.last(last); mon.len(len); mon.m(m);
        mon.a(a); mon.b(b); mon.c(c); mon.d(d); mon.i_px(i_px);
    }
    bool finished() const { return stim.finished(); }
};

}  // namespace shading::tb
