// Testbench parts for the forward-difference evaluator with a per-interval length (fd_eval_var.h):
// intervals of 2^m pixels, m given per interval, one pixel per clock; each pixel checked against
// interp::golden_fd(coefs, m, len) and against the Horner unit's golden result at the same t.
// Stimulus and monitor as in interp_fd_bench.h, with the m pin.
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
#include "interp/interp_bench_common.h"

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

struct fd_var_sample {
    fd_var_interval iv;        // as presented at acceptance
    std::size_t interval = 0;  // index of the accepted interval
    unsigned k = 0;            // pixel index within it
    uint64_t out = 0;
    sc_core::sc_time accepted, valid;
    bool matched = true;
};

// Moore source, as fd_stimulus: each interval is presented with start = 1 until an acceptance edge,
// then held one more clock (the registers load at the falling edge after acceptance).
template <unsigned MMIN, unsigned MMAX>
class fd_var_stimulus : public sc_core::sc_module {
public:
    using len_t = typename fd_eval_var<MMIN, MMAX>::len_t;
    using m_t = typename fd_eval_var<MMIN, MMAX>::m_t;
    sc_core::sc_in<bool> clk{"clk"}, valid{"valid"}, last{"last"};
    sc_core::sc_out<bool> start{"start"};
    sc_core::sc_out<len_t> len{"len"};
    sc_core::sc_out<m_t> m{"m"};
    sc_core::sc_out<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"};

    SC_HAS_PROCESS(fd_var_stimulus);
    fd_var_stimulus(const sc_core::sc_module_name& name, std::vector<fd_var_interval> ivs)
        : sc_module(name), ivs_(std::move(ivs)) {
        SC_THREAD(run);
    }
    bool finished() const { return finished_; }

private:
    void present(const fd_var_interval& iv) {
        a.write(coef_word(iv.k.a)); b.write(coef_word(iv.k.b));
        c.write(coef_word(iv.k.c)); d.write(coef_word(iv.k.d));
        len.write(len_t(iv.len));
        m.write(m_t(iv.m));
        start.write(true);
    }
    void run() {
        const std::size_t n = ivs_.size();
        wait(clk.posedge_event());
        if (n > 0) present(ivs_[0]);
        std::size_t accepted = 0, ended = 0;
        bool change = false;
        while (ended < n) {
            wait(clk.posedge_event());
            const bool v = valid.read(), l = last.read();
            if (v && l) ++ended;
            if (change) {
                present(ivs_[accepted]);
                change = false;
            } else if (start.read() && (!v || l)) {
                ++accepted;
                start.write(false);
                change = accepted < n;
            }
        }
        wait(2 * interp_period());
        finished_ = true;
        sc_core::sc_stop();
    }
    std::vector<fd_var_interval> ivs_;
    bool finished_ = false;
};

template <unsigned MMIN, unsigned MMAX>
class fd_var_monitor : public sc_core::sc_module {
public:
    using len_t = typename fd_eval_var<MMIN, MMAX>::len_t;
    using m_t = typename fd_eval_var<MMIN, MMAX>::m_t;
    sc_core::sc_in<bool> clk{"clk"}, start{"start"}, valid{"valid"}, last{"last"};
    sc_core::sc_in<len_t> len{"len"};
    sc_core::sc_in<m_t> m{"m"};
    sc_core::sc_in<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"}, i_px{"i_px"};

    SC_HAS_PROCESS(fd_var_monitor);
    fd_var_monitor(const sc_core::sc_module_name& name, std::function<void(const fd_var_sample&)> sink)
        : sc_module(name), sink_(std::move(sink)) {
        SC_METHOD(on_edge);
        sensitive << clk.pos();
        dont_initialize();
    }

private:
    void on_edge() {
        const auto now = sc_core::sc_time_stamp();
        const bool v = valid.read(), l = last.read();
        if (v) {
            fd_var_sample s;
            s.iv = cur_;
            s.interval = index_ - 1;
            s.k = k_++;
            s.out = i_px.read().to_uint64();
            s.accepted = accepted_;
            s.valid = now;
            sink_(s);
        }
        if (start.read() && (!v || l)) {  // acceptance: the inputs are presented before it
            cur_.k = {coef_code(a.read()), coef_code(b.read()), coef_code(c.read()), coef_code(d.read())};
            cur_.len = len.read().to_uint();
            cur_.m = m.read().to_uint();
            accepted_ = now;
            k_ = 0;
            ++index_;
        }
    }
    std::function<void(const fd_var_sample&)> sink_;
    fd_var_interval cur_;
    std::size_t index_ = 0;
    unsigned k_ = 0;
    sc_core::sc_time accepted_;
};

template <unsigned MMIN, unsigned MMAX>
class fd_var_checker : public checker_log<fd_var_sample> {
public:
    void check(const fd_var_sample& s) {
        fd_var_sample r = s;
        const fd_var_interval e = fd_var_effective<MMIN, MMAX>(s.iv);
        if (s.interval != golden_interval_ || golden_.empty()) {  // one golden run per interval
            golden_ = interp::golden_fd(e.k, e.m, e.len);
            golden_interval_ = s.interval;
            pixels_of_[s.interval] = 0;
        }
        ++pixels_of_[s.interval];
        const bool in_range = s.k < golden_.size();
        uint64_t g = in_range ? golden_[s.k] : 0;
        if (begin(s.accepted, s.valid)) g ^= 1;
        if (!in_range || g != s.out) {
            r.matched = false;
            ++mismatches_;
            std::ostringstream os;
            os << "forward differences (m = " << e.m << ") at " << s.valid << " interval " << s.interval << " pixel "
               << s.k << ": device 0x" << std::hex << s.out << " golden 0x" << g << std::dec;
            report_mismatch(mismatches_, 10, os.str());
        }
        record(r);
        // Against Horner at the same t = k / 2^m (Q1.8): 0 <= FD - Horner <= 2 LSB (interp_fd_bench.h).
        const uint64_t t = static_cast<uint64_t>(s.k) << (interp::t_fmt.frac - e.m);
        const int64_t diff = code_value(s.out, interp::coef_fmt) -
                             code_value(interp::golden_horner(e.k, t, false), interp::coef_fmt);
        min_vs_horner_ = std::min(min_vs_horner_, diff);
        max_vs_horner_ = std::max(max_vs_horner_, diff);
        latencies_[s.k].insert(s.valid - s.accepted);
    }
    int64_t min_vs_horner() const { return min_vs_horner_; }
    int64_t max_vs_horner() const { return max_vs_horner_; }
    const std::map<unsigned, std::set<sc_core::sc_time>>& latencies() const { return latencies_; }
    // Pixels that came out per accepted interval (index -> count).
    const std::map<std::size_t, unsigned>& pixels_of() const { return pixels_of_; }
    double cycles_per_pixel() const { return cycles_per_result(); }

private:
    std::vector<uint64_t> golden_;
    std::size_t golden_interval_ = 0;
    int64_t min_vs_horner_ = INT64_MAX, max_vs_horner_ = INT64_MIN;
    std::map<unsigned, std::set<sc_core::sc_time>> latencies_;
    std::map<std::size_t, unsigned> pixels_of_;
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
