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
#include <type_traits>
#include <vector>

#include "interp/fd_eval.h"
#include "interp/fd_eval_fast.h"
#include "testbenches/interp/interp_bench_common.h"
#include "testbenches/interp/interp_line.h"

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

// The stimulus, monitor and checker below serve fd_bench (fd_eval<M>, fd_eval_fast<M>: Iv =
// fd_interval, no m pin) and fd_var_bench (interp_fd_var_bench.h: fd_eval_var, Iv = fd_var_interval
// with its m, MT the m pin's type).
template <class Iv>
struct fd_sample_of {
    Iv iv;                     // as presented at acceptance
    std::size_t interval = 0;  // index of the accepted interval
    unsigned k = 0;            // pixel index within it
    uint64_t out = 0;
    sc_core::sc_time accepted, valid;
    bool matched = true;  // set by the checker
};
using fd_sample = fd_sample_of<fd_interval>;

// The m pin: a port where the evaluator has one (MT its type), else nothing (fd_eval<M>).
struct no_m_pin {
    explicit no_m_pin(const char*) {}
};
template <template <class> class Port, class MT>
struct m_pin_of {
    using type = Port<MT>;
};
template <template <class> class Port>
struct m_pin_of<Port, void> {
    using type = no_m_pin;
};

// Moore source: presents interval 0 with start = 1; at each acceptance edge (start = 1 and
// valid = 0 or last = 1) it drops start, holds the inputs one more clock (the registers load at
// the falling edge after acceptance) and then presents the next interval with start = 1.
template <class Iv, class LenT, class MT = void>
class fd_stimulus_of : public interp_stimulus<Iv> {
public:
    using len_t = LenT;
    sc_core::sc_in<bool> valid{"valid"}, last{"last"};
    sc_core::sc_out<bool> start{"start"};
    sc_core::sc_out<len_t> len{"len"};
    typename m_pin_of<sc_core::sc_out, MT>::type m{"m"};
    sc_core::sc_out<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"};

    fd_stimulus_of(const sc_core::sc_module_name& name, item_source<Iv> ivs)
        : interp_stimulus<Iv>(name, std::move(ivs)) {}

private:
    void present(const Iv& iv) override {
        a.write(coef_word(iv.k.a)); b.write(coef_word(iv.k.b));
        c.write(coef_word(iv.k.c)); d.write(coef_word(iv.k.d));
        len.write(len_t(iv.len));
        if constexpr (!std::is_void_v<MT>) m.write(MT(iv.m));
        start.write(true);
    }
    void edge() override {
        const bool v = valid.read(), l = last.read();
        if (v && l) ++this->ended_;
        if (change_) {
            present(this->item(this->accepted_));
            change_ = false;
        } else if (start.read() && (!v || l)) {
            ++this->accepted_;
            start.write(false);
            change_ = this->accepted_ < this->size();
        }
    }
    void tail() override { this->wait(2 * interp_period()); }

    bool change_ = false;  // the next interval goes on the pins at the next edge
};
template <unsigned M>
using fd_stimulus = fd_stimulus_of<fd_interval, typename fd_ctrl<M>::len_t>;

template <class Iv, class LenT, class MT = void>
class fd_monitor_of : public sc_core::sc_module {
public:
    using len_t = LenT;
    sc_core::sc_in<bool> clk{"clk"}, start{"start"}, valid{"valid"}, last{"last"};
    sc_core::sc_in<len_t> len{"len"};
    typename m_pin_of<sc_core::sc_in, MT>::type m{"m"};
    sc_core::sc_in<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"}, i_px{"i_px"};

    SC_HAS_PROCESS(fd_monitor_of);
    fd_monitor_of(const sc_core::sc_module_name& name, std::function<void(const fd_sample_of<Iv>&)> sink)
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
            fd_sample_of<Iv> s;
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
            if constexpr (!std::is_void_v<MT>) cur_.m = m.read().to_uint();
            accepted_ = now;
            k_ = 0;
            ++index_;
        }
    }
    std::function<void(const fd_sample_of<Iv>&)> sink_;
    Iv cur_;
    std::size_t index_ = 0;
    unsigned k_ = 0;
    sc_core::sc_time accepted_;
};
template <unsigned M>
using fd_monitor = fd_monitor_of<fd_interval, typename fd_ctrl<M>::len_t>;

// An interval as the evaluator takes it (its bad-input rules applied): coefficients, m, length.
struct fd_effective {
    interp::cubic_coefs k;
    unsigned m = 0, len = 0;
};

// Every pixel against golden_fd of its interval as the evaluator takes it (`effective`, from the
// unit's documented rule, not its code), and against the Horner unit's golden result at the same t.
// per_interval_m (fd_eval_var): the m is named in mismatch reports and pixels_of() is kept.
template <class Iv>
class fd_checker_of : public checker_log<fd_sample_of<Iv>> {
public:
    using sample = fd_sample_of<Iv>;
    fd_checker_of(std::function<fd_effective(const Iv&)> effective, int frac, bool per_interval_m)
        : effective_(std::move(effective)), frac_(frac), per_interval_m_(per_interval_m) {}

    void check(const sample& s) {
        sample r = s;
        if (s.interval != golden_interval_ || golden_.empty()) {  // one golden run per interval
            e_ = effective_(s.iv);
            golden_ = interp::golden_fd(e_.k, e_.m, e_.len, frac_);
            golden_interval_ = s.interval;
            if (per_interval_m_) pixels_of_[s.interval] = 0;
        }
        if (per_interval_m_) ++pixels_of_[s.interval];
        const bool in_range = s.k < golden_.size();
        uint64_t g = in_range ? golden_[s.k] : 0;
        if (this->begin(s.accepted, s.valid)) g ^= 1;
        if (!in_range || g != s.out) {
            r.matched = false;
            ++this->mismatches_;
            std::ostringstream os;
            os << "forward differences";
            if (per_interval_m_) os << " (m = " << e_.m << ")";
            os << " at " << s.valid << " interval " << s.interval << " pixel " << s.k << ": device 0x" << std::hex
               << s.out << " golden 0x" << g << std::dec;
            report_mismatch(this->mismatches_, 10, os.str());
        }
        this->record(r);
        // Against Horner at the same t (t = k/2^m on Q1.8): FD is floor(P) of the exact polynomial,
        // Horner P minus less than 3 LSB of floors, so 0 <= FD - Horner <= 2 LSB.
        const uint64_t t = static_cast<uint64_t>(s.k) << (interp::t_fmt.frac - e_.m);
        const int64_t diff = code_value(s.out, interp::coef_fmt) -
                             code_value(interp::golden_horner(e_.k, t, false), interp::coef_fmt);
        min_vs_horner_ = std::min(min_vs_horner_, diff);
        max_vs_horner_ = std::max(max_vs_horner_, diff);
        latencies_[s.k].insert(s.valid - s.accepted);
    }
    int64_t min_vs_horner() const { return min_vs_horner_; }
    int64_t max_vs_horner() const { return max_vs_horner_; }
    bool within_horner_bound() const { return min_vs_horner_ >= 0 && max_vs_horner_ <= 2; }
    const std::map<unsigned, std::set<sc_core::sc_time>>& latencies() const { return latencies_; }
    // Pixels that came out per accepted interval (index -> count; per_interval_m only).
    const std::map<std::size_t, unsigned>& pixels_of() const { return pixels_of_; }
    double cycles_per_pixel() const { return this->cycles_per_result(); }

private:
    std::function<fd_effective(const Iv&)> effective_;
    int frac_;
    bool per_interval_m_;
    fd_effective e_;
    std::vector<uint64_t> golden_;
    std::size_t golden_interval_ = 0;
    int64_t min_vs_horner_ = INT64_MAX, max_vs_horner_ = INT64_MIN;
    std::map<unsigned, std::set<sc_core::sc_time>> latencies_;
    std::map<std::size_t, unsigned> pixels_of_;
};

// fd_eval<M>: m = M; a len outside 1..2^M is evaluated as 2^M (fd_ctrl).
template <unsigned M>
class fd_checker : public fd_checker_of<fd_interval> {
public:
    static constexpr unsigned n_pixels = 1u << M;
    explicit fd_checker(int frac = interp::fd_fmt.frac)
        : fd_checker_of<fd_interval>(
              [](const fd_interval& iv) {
                  return fd_effective{iv.k, M, (iv.len == 0 || iv.len > n_pixels) ? n_pixels : iv.len};
              },
              frac, false) {}
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
