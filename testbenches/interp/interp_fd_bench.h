// Testbench parts for the forward-difference evaluator: one interval of up to 2^M pixels per
// start, one pixel per clock, each pixel checked against the golden model and against the Horner
// unit's golden result at the same t (stimulus, monitor, checker: interp_bench_common.h).
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <systemc>
#include <vector>

#include "interp/fd_eval.h"
#include "interp/fd_eval_fast.h"
#include "interp/interp_bench_common.h"
#include "interp/interp_line.h"

namespace shading::tb {

struct fd_interval {
    interp::cubic_coefs k;
    unsigned len = 0;
};

// The random mode's stream: `pixels` pixels in intervals of random length 1..2^M, each with a
// random unit's golden coefficients of random samples (quadratics as cubics with A = 0); item i
// from (seed, i).
template <unsigned M>
item_source<fd_interval> random_fd_intervals(std::size_t pixels, uint64_t seed) {
    const random_runs runs(pixels, 1u << M, seed);
    return item_source<fd_interval>(runs.count(), [seed, runs](std::size_t i) {
        split_rng r(seed, i);
        line_interval iv;
        iv.c1 = random_samples<4>(r);
        iv.c2 = random_samples<4>(r);
        iv.q = random_samples<3>(r);
        const variant v = all_variants[r.range(0, all_variants.size() - 1)];
        const auto k = variant_coefs(v, iv);
        return fd_interval{is_quad(v) ? as_cubic(k) : k, static_cast<unsigned>(runs.length(i))};
    });
}

struct fd_sample {
    fd_interval iv;
    std::size_t interval = 0;  // index of the accepted interval
    unsigned k = 0;            // pixel index within it
    uint64_t out = 0;
    sc_core::sc_time accepted, valid;
    bool matched = true;  // set by the checker
};

// Moore source: presents interval 0 with start = 1; at each acceptance edge (start = 1 and
// valid = 0 or last = 1) it drops start, holds the inputs one more clock (the registers load at
// the falling edge after acceptance) and then presents the next interval with start = 1.
template <unsigned M>
class fd_stimulus : public sc_core::sc_module {
public:
    using len_t = typename fd_ctrl<M>::len_t;
    sc_core::sc_in<bool> clk{"clk"}, valid{"valid"}, last{"last"};
    sc_core::sc_out<bool> start{"start"};
    sc_core::sc_out<len_t> len{"len"};
    sc_core::sc_out<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"};

    SC_HAS_PROCESS(fd_stimulus);
    fd_stimulus(const sc_core::sc_module_name& name, item_source<fd_interval> ivs)
        : sc_module(name), ivs_(std::move(ivs)) {
        SC_THREAD(run);
    }
    bool finished() const { return finished_; }

private:
    void present(const fd_interval& iv) {
        a.write(coef_word(iv.k.a)); b.write(coef_word(iv.k.b));
        c.write(coef_word(iv.k.c)); d.write(coef_word(iv.k.d));
        len.write(len_t(iv.len));
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
    item_source<fd_interval> ivs_;
    bool finished_ = false;
};

template <unsigned M>
class fd_monitor : public sc_core::sc_module {
public:
    using len_t = typename fd_ctrl<M>::len_t;
    sc_core::sc_in<bool> clk{"clk"}, start{"start"}, valid{"valid"}, last{"last"};
    sc_core::sc_in<len_t> len{"len"};
    sc_core::sc_in<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"}, i_px{"i_px"};

    SC_HAS_PROCESS(fd_monitor);
    fd_monitor(const sc_core::sc_module_name& name, std::function<void(const fd_sample&)> sink)
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
            fd_sample s;
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
            accepted_ = now;
            k_ = 0;
            ++index_;
        }
    }
    std::function<void(const fd_sample&)> sink_;
    fd_interval cur_;
    std::size_t index_ = 0;
    unsigned k_ = 0;
    sc_core::sc_time accepted_;
};

template <unsigned M>
class fd_checker : public checker_log<fd_sample> {
public:
    static constexpr unsigned n_pixels = 1u << M;
    explicit fd_checker(int frac = interp::fd_fmt.frac) : frac_(frac) {}

    void check(const fd_sample& s) {
        fd_sample r = s;
        const unsigned len = (s.iv.len == 0 || s.iv.len > n_pixels) ? n_pixels : s.iv.len;
        if (s.interval != golden_interval_ || golden_.empty()) {  // one golden run per interval
            golden_ = interp::golden_fd(s.iv.k, M, len, frac_);
            golden_interval_ = s.interval;
        }
        const bool in_range = s.k < golden_.size();
        uint64_t g = in_range ? golden_[s.k] : 0;
        if (begin(s.accepted, s.valid)) g ^= 1;
        if (!in_range || g != s.out) {
            r.matched = false;
            ++mismatches_;
            std::ostringstream os;
            os << "forward differences at " << s.valid << " interval " << s.interval << " pixel " << s.k
               << ": device 0x" << std::hex << s.out << " golden 0x" << g << std::dec;
            report_mismatch(mismatches_, 10, os.str());
        }
        record(r);
        // Against Horner at the same t (t = k/N on Q1.8): FD is floor(P) of the exact polynomial,
        // Horner P minus less than 3 LSB of floors, so 0 <= FD - Horner <= 2 LSB.
        const uint64_t t = static_cast<uint64_t>(s.k) << (interp::t_fmt.frac - M);
        const int64_t diff = code_value(s.out, interp::coef_fmt) -
                             code_value(interp::golden_horner(s.iv.k, t, false), interp::coef_fmt);
        min_vs_horner_ = std::min(min_vs_horner_, diff);
        max_vs_horner_ = std::max(max_vs_horner_, diff);
        latencies_[s.k].insert(s.valid - s.accepted);
    }
    int64_t min_vs_horner() const { return min_vs_horner_; }
    int64_t max_vs_horner() const { return max_vs_horner_; }
    bool within_horner_bound() const { return min_vs_horner_ >= 0 && max_vs_horner_ <= 2; }
    const std::map<unsigned, std::set<sc_core::sc_time>>& latencies() const { return latencies_; }
    double cycles_per_pixel() const { return cycles_per_result(); }

private:
    int frac_;
    std::vector<uint64_t> golden_;
    std::size_t golden_interval_ = 0;
    int64_t min_vs_horner_ = INT64_MAX, max_vs_horner_ = INT64_MIN;
    std::map<unsigned, std::set<sc_core::sc_time>> latencies_;
};

// DUT: fd_eval<M> (block level) or fd_eval_fast<M> (the fast pin-level abstraction): the same pins.
template <unsigned M, class DUT = fd_eval<M>>
class fd_bench : public sc_core::sc_module {
public:
    using len_t = typename fd_ctrl<M>::len_t;
    sc_core::sc_clock clk;
    sc_core::sc_signal<bool> start{"start"}, valid{"valid"}, last{"last"};
    sc_core::sc_signal<len_t> len{"len"};
    sc_core::sc_signal<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"}, i_px{"i_px"};

    fd_checker<M> checker;
    DUT dut{"dut"};
    fd_stimulus<M> stim;
    fd_monitor<M> mon;

    fd_bench(const sc_core::sc_module_name& name, item_source<fd_interval> ivs, const interp_clock& ck = {})
        : sc_module(name), clk("clk", ck.period(), ck.duty()), stim("stim", std::move(ivs)),
          mon("mon", [this](const fd_sample& s) { checker.check(s); }) {
        checker.set_period(ck.period());
        dut.clk(clk); dut.start(start); dut.len(len);
        dut.a(a); dut.b(b); dut.c(c); dut.d(d);
        dut.i_px(i_px); dut.valid(valid); dut.last(last);
        stim.clk(clk); stim.valid(valid); stim.last(last); stim.start(start); stim.len(len);
        stim.a(a); stim.b(b); stim.c(c); stim.d(d);
        mon.clk(clk); mon.start(start); mon.valid(valid); mon.last(last); mon.len(len);
        mon.a(a); mon.b(b); mon.c(c); mon.d(d); mon.i_px(i_px);
    }
    bool finished() const { return stim.finished(); }
};

}  // namespace shading::tb
