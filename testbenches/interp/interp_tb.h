// Testbench parts for seed 004's interpolation units, each in three pieces reused by the
// testbench programs and the GoogleTest suites:
//   *_stimulus - drives the unit's pins synchronously (writes just after rising edges);
//   *_monitor  - samples the pins at rising edges: the inputs a request was evaluated with and
//                the result at the edge where the unit says it is valid;
//   *_checker  - compares every sample with the golden model (src/interp_golden.h).
// Clock: 20 ns, rising edge first at 0, unless a bench is given other phases (interp_clock).
// Registers latch on the falling edge (reg.h).
#pragma once

#include <array>
#include <cstdint>
#include <fstream>
#include <functional>
#include <iomanip>
#include <string>
#include <map>
#include <set>
#include <sstream>
#include <systemc>
#include <vector>

#include "formats/interp_formats.h"
#include "golden/interp_golden.h"
#include "interp/coef_unit_cubic.h"
#include "interp/coef_unit_quad.h"
#include "interp/fd_eval.h"
#include "interp/horner_unit.h"
#include "core/report_ids.h"

namespace shading::tb {

inline sc_core::sc_time interp_period() { return sc_core::sc_time(20, sc_core::SC_NS); }

// A bench's clock by its phases: high first (rising edge at 0), then low. The default is the
// 20 ns, 50 % clock every program and most tests use; the timing tests shorten one phase.
struct interp_clock {
    sc_core::sc_time high = interp_period() / 2;
    sc_core::sc_time low = interp_period() / 2;
    sc_core::sc_time period() const { return high + low; }
    double duty() const { return high / period(); }  // sc_clock rounds period * duty back to high
};

using sample_t = sc_dt::sc_uint<interp::sample_fmt.width>;
using coef_t = sc_dt::sc_uint<interp::coef_fmt.width>;
using t_t = sc_dt::sc_uint<interp::t_fmt.width>;

// One row of the run summary (scripts/run.sh): appended to the TSV file at `path` if not empty.
// max_error is written as a percentage when `relative`, else in intensity levels (0..255).
inline void append_summary(const std::string& path, const std::string& bench, const std::string& case_name,
                           std::size_t samples, std::size_t mismatches, double max_error, bool relative,
                           double cycles_per_pixel, const std::string& note) {
    if (path.empty()) return;
    std::ofstream f(path, std::ios::app);
    f << bench << '\t' << case_name << '\t' << samples << '\t' << mismatches << '\t' << std::fixed
      << std::setprecision(relative ? 4 : 2) << (relative ? 100.0 * max_error : max_error)
      << (relative ? "%" : " lv") << std::defaultfloat << std::setprecision(4) << '\t' << cycles_per_pixel << '\t' << note << '\n';
}

inline int64_t coef_code(const coef_t& v) { return code_value(v.to_uint64(), interp::coef_fmt); }
inline coef_t coef_word(int64_t code) { return coef_t(wrap_bits(code, interp::coef_fmt.width)); }

// Reports a mismatch through SystemC (shading/mismatch), the first `max` of them.
inline void report_mismatch(std::size_t count, std::size_t max, const std::string& what) {
    if (count <= max) SC_REPORT_WARNING(msg::mismatch, what.c_str());
}

// ---------------------------------------------------------------------------------------------
// Coefficient units: all five (case 1/2 x shift-add/exact, quadratic) side by side.

struct coef_inputs {
    std::array<uint64_t, 4> c1{}, c2{};
    std::array<uint64_t, 3> q{};
};

struct coef_sample {
    coef_inputs in;
    std::array<interp::cubic_coefs, 5> out;  // in tb::variant order (interp_line.h)
    sc_core::sc_time at;
};

class coef_stimulus : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_out<bool> sample_valid{"sample_valid"};
    sc_core::sc_vector<sc_core::sc_out<sample_t>> c1{"c1", 4}, c2{"c2", 4}, q{"q", 3};

    SC_HAS_PROCESS(coef_stimulus);
    coef_stimulus(const sc_core::sc_module_name& name, std::vector<coef_inputs> sets)
        : sc_module(name), sets_(std::move(sets)) {
        SC_THREAD(run);
    }
    bool finished() const { return finished_; }

private:
    void run() {
        for (const auto& s : sets_) {
            wait(clk.posedge_event());
            for (std::size_t i = 0; i < 4; ++i) c1[i].write(s.c1[i]), c2[i].write(s.c2[i]);
            for (std::size_t i = 0; i < 3; ++i) q[i].write(s.q[i]);
            sample_valid.write(true);
        }
        wait(clk.posedge_event());
        sample_valid.write(false);
        wait(clk.posedge_event());
        finished_ = true;
        sc_core::sc_stop();
    }
    std::vector<coef_inputs> sets_;
    bool finished_ = false;
};

class coef_monitor : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> clk{"clk"}, sample_valid{"sample_valid"};
    sc_core::sc_vector<sc_core::sc_in<sample_t>> c1{"c1", 4}, c2{"c2", 4}, q{"q", 3};
    // Outputs of the five units: a, b, c, d per unit (the quadratic's d is not connected).
    sc_core::sc_vector<sc_core::sc_in<coef_t>> coef{"coef", 19};

    SC_HAS_PROCESS(coef_monitor);
    coef_monitor(const sc_core::sc_module_name& name, std::function<void(const coef_sample&)> sink)
        : sc_module(name), sink_(std::move(sink)) {
        SC_METHOD(on_edge);
        sensitive << clk.pos();
        dont_initialize();
    }

private:
    // Samples presented after edge e are latched at the falling edge and the coefficients are
    // valid at edge e + T, where the inputs still hold: one sample per edge, latency one clock.
    void on_edge() {
        if (!sample_valid.read()) return;
        coef_sample s;
        for (std::size_t i = 0; i < 4; ++i) s.in.c1[i] = c1[i].read(), s.in.c2[i] = c2[i].read();
        for (std::size_t i = 0; i < 3; ++i) s.in.q[i] = q[i].read();
        for (std::size_t u = 0; u < 4; ++u)
            s.out[u] = {coef_code(coef[4 * u].read()), coef_code(coef[4 * u + 1].read()),
                        coef_code(coef[4 * u + 2].read()), coef_code(coef[4 * u + 3].read())};
        s.out[4] = {coef_code(coef[16].read()), coef_code(coef[17].read()), coef_code(coef[18].read()), 0};
        s.at = sc_core::sc_time_stamp();
        sink_(s);
    }
    std::function<void(const coef_sample&)> sink_;
};

class coef_checker {
public:
    using golden_fn = std::function<interp::cubic_coefs(std::size_t unit, const coef_inputs&)>;
    static interp::cubic_coefs golden(std::size_t unit, const coef_inputs& in) {
        using interp::div3_mode;
        using interp::sample_set;
        switch (unit) {
            case 0: return interp::golden_cubic_coefs(in.c1, sample_set::case1, div3_mode::shift_add);
            case 1: return interp::golden_cubic_coefs(in.c1, sample_set::case1, div3_mode::exact);
            case 2: return interp::golden_cubic_coefs(in.c2, sample_set::case2, div3_mode::shift_add);
            case 3: return interp::golden_cubic_coefs(in.c2, sample_set::case2, div3_mode::exact);
            default: return interp::golden_quad_coefs(in.q);
        }
    }

    explicit coef_checker(golden_fn g = &coef_checker::golden) : golden_(std::move(g)) {}

    void check(const coef_sample& s) {
        samples_.push_back(s);
        for (std::size_t u = 0; u < 5; ++u) {
            const auto g = golden_(u, s.in);
            if (g == s.out[u]) continue;
            ++mismatches_[u];
            std::ostringstream os;
            os << "coefficient unit " << u << " at " << s.at << ": device (" << s.out[u].a << ", "
               << s.out[u].b << ", " << s.out[u].c << ", " << s.out[u].d << ") golden (" << g.a << ", " << g.b
               << ", " << g.c << ", " << g.d << ") [Q16.16 codes]";
            report_mismatch(mismatches(), 10, os.str());
        }
    }
    std::size_t mismatches(std::size_t unit) const {
        auto it = mismatches_.find(unit);
        return it == mismatches_.end() ? 0 : it->second;
    }
    std::size_t mismatches() const {
        std::size_t n = 0;
        for (const auto& [u, c] : mismatches_) n += c;
        return n;
    }
    const std::vector<coef_sample>& samples() const { return samples_; }

private:
    golden_fn golden_;
    std::map<std::size_t, std::size_t> mismatches_;
    std::vector<coef_sample> samples_;
};

class coef_bench : public sc_core::sc_module {
public:
    sc_core::sc_clock clk;
    sc_core::sc_signal<bool> sample_valid{"sample_valid"};
    // Nets named for the waveform: c1_i1 .. c1_i4 (case-1 samples), c2_i*, q_i*; and per unit
    // c1sa_a .. quad_c (unit: c1sa, c1ex, c2sa, c2ex, quad; then the coefficient).
    sc_core::sc_vector<sc_core::sc_signal<sample_t>> c1{"c1"}, c2{"c2"}, q{"q"};
    sc_core::sc_vector<sc_core::sc_signal<coef_t>> coef{"coef"};

    coef_checker checker;
    coef_unit_cubic<interp::sample_set::case1, interp::div3_mode::shift_add> dut_c1_sa{"dut_c1_sa"};
    coef_unit_cubic<interp::sample_set::case1, interp::div3_mode::exact> dut_c1_ex{"dut_c1_ex"};
    coef_unit_cubic<interp::sample_set::case2, interp::div3_mode::shift_add> dut_c2_sa{"dut_c2_sa"};
    coef_unit_cubic<interp::sample_set::case2, interp::div3_mode::exact> dut_c2_ex{"dut_c2_ex"};
    coef_unit_quad dut_quad{"dut_quad"};
    coef_stimulus stim;
    coef_monitor mon;

    coef_bench(const sc_core::sc_module_name& name, std::vector<coef_inputs> sets,
               coef_checker::golden_fn golden = &coef_checker::golden, const interp_clock& ck = {})
        : sc_module(name), clk("clk", ck.period(), ck.duty()), checker(std::move(golden)),
          stim("stim", std::move(sets)),
          mon("mon", [this](const coef_sample& s) { checker.check(s); }) {
        auto named = [](const std::string& prefix) {
            return [prefix](const char*, std::size_t i) {
                return new sc_core::sc_signal<sample_t>((prefix + std::to_string(i + 1)).c_str());
            };
        };
        c1.init(4, named("c1_i"));
        c2.init(4, named("c2_i"));
        q.init(3, named("q_i"));
        coef.init(19, [](const char*, std::size_t i) {
            constexpr const char* unit[] = {"c1sa", "c1ex", "c2sa", "c2ex", "quad"};
            constexpr const char* name[] = {"a", "b", "c", "d"};
            return new sc_core::sc_signal<coef_t>((std::string(unit[i / 4]) + "_" + name[i % 4]).c_str());
        });
        bind_cubic(dut_c1_sa, c1, 0);
        bind_cubic(dut_c1_ex, c1, 4);
        bind_cubic(dut_c2_sa, c2, 8);
        bind_cubic(dut_c2_ex, c2, 12);
        dut_quad.clk(clk);
        dut_quad.i1(q[0]); dut_quad.i2(q[1]); dut_quad.i3(q[2]);
        dut_quad.a(coef[16]); dut_quad.b(coef[17]); dut_quad.c(coef[18]);
        stim.clk(clk); stim.sample_valid(sample_valid);
        mon.clk(clk); mon.sample_valid(sample_valid);
        for (std::size_t i = 0; i < 4; ++i) stim.c1[i](c1[i]), stim.c2[i](c2[i]), mon.c1[i](c1[i]), mon.c2[i](c2[i]);
        for (std::size_t i = 0; i < 3; ++i) stim.q[i](q[i]), mon.q[i](q[i]);
        for (std::size_t i = 0; i < coef.size(); ++i) mon.coef[i](coef[i]);
    }
    bool finished() const { return stim.finished(); }

private:
    template <typename Unit>
    void bind_cubic(Unit& u, sc_core::sc_vector<sc_core::sc_signal<sample_t>>& s, std::size_t k) {
        u.clk(clk);
        u.i1(s[0]); u.i2(s[1]); u.i3(s[2]); u.i4(s[3]);
        u.a(coef[k]); u.b(coef[k + 1]); u.c(coef[k + 2]); u.d(coef[k + 3]);
    }
};

// ---------------------------------------------------------------------------------------------
// Horner unit.

struct horner_request {
    interp::cubic_coefs k;
    uint64_t t = 0;
    bool deg2 = false;
};

struct horner_sample {
    horner_request req;
    uint64_t out = 0;
    std::vector<uint64_t> steps;  // RG after every micro-step, as seen at the rising edges
    sc_core::sc_time accepted, valid;
    bool matched = true;          // set by the checker
};

// Moore source: presents request 0 with start = 1; at each acceptance edge (start = 1 and
// busy = 0 or done = 1) it presents the accepted request's inputs and keeps start high while more
// requests follow (back to back). With gap > 0 it instead waits `gap` clocks after each done.
class horner_stimulus : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> clk{"clk"}, busy{"busy"}, done{"done"};
    sc_core::sc_out<bool> start{"start"}, deg2{"deg2"};
    sc_core::sc_out<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"};
    sc_core::sc_out<t_t> t{"t"};

    SC_HAS_PROCESS(horner_stimulus);
    horner_stimulus(const sc_core::sc_module_name& name, std::vector<horner_request> reqs, unsigned gap = 0)
        : sc_module(name), reqs_(std::move(reqs)), gap_(gap) {
        SC_THREAD(run);
    }
    bool finished() const { return finished_; }
    std::size_t requests() const { return reqs_.size(); }

private:
    void present(const horner_request& r) {
        a.write(coef_word(r.k.a)); b.write(coef_word(r.k.b));
        c.write(coef_word(r.k.c)); d.write(coef_word(r.k.d));
        t.write(t_t(r.t));
        deg2.write(r.deg2);
    }
    void run() {
        const std::size_t n = reqs_.size();
        wait(clk.posedge_event());
        if (n > 0) {
            present(reqs_[0]);
            start.write(true);
        }
        std::size_t accepted = 0, dones = 0;
        unsigned gap_left = 0;
        while (dones < n) {
            wait(clk.posedge_event());
            const bool dn = done.read();
            const bool acc = start.read() && (!busy.read() || dn);
            if (dn) ++dones;
            if (acc) {
                present(reqs_[accepted]);
                ++accepted;
                start.write(gap_ == 0 && accepted < n);
            } else if (gap_ > 0 && dn && accepted < n) {
                gap_left = gap_;
            } else if (gap_left > 0 && --gap_left == 0) {
                present(reqs_[accepted]);
                start.write(true);
            }
        }
        wait(2 * interp_period());
        finished_ = true;
        sc_core::sc_stop();
    }
    std::vector<horner_request> reqs_;
    unsigned gap_;
    bool finished_ = false;
};

class horner_monitor : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> clk{"clk"}, start{"start"}, busy{"busy"}, done{"done"}, deg2{"deg2"};
    sc_core::sc_in<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"}, i_t{"i_t"}, rg_value{"rg_value"};
    sc_core::sc_in<t_t> t{"t"};

    SC_HAS_PROCESS(horner_monitor);
    horner_monitor(const sc_core::sc_module_name& name, std::function<void(const horner_sample&)> sink)
        : sc_module(name), sink_(std::move(sink)) {
        SC_METHOD(on_edge);
        sensitive << clk.pos();
        dont_initialize();
    }

private:
    // Every read gives the value before this edge: RG after the step that just ended, and the
    // inputs the source holds until the done edge.
    void on_edge() {
        const auto now = sc_core::sc_time_stamp();
        const bool dn = done.read(), bz = busy.read();
        if (bz) steps_.push_back(rg_value.read().to_uint64());
        if (dn) {
            horner_sample s;
            s.req.k = {coef_code(a.read()), coef_code(b.read()), coef_code(c.read()), coef_code(d.read())};
            s.req.t = t.read().to_uint64();
            s.req.deg2 = deg2.read();
            s.out = i_t.read().to_uint64();
            s.steps = steps_;
            s.accepted = accepted_;
            s.valid = now;
            sink_(s);
        }
        if (start.read() && (!bz || dn)) {
            accepted_ = now;
            steps_.clear();
        }
    }
    std::function<void(const horner_sample&)> sink_;
    std::vector<uint64_t> steps_;
    sc_core::sc_time accepted_;
};

class horner_checker {
public:
    using golden_fn = std::function<std::vector<uint64_t>(const horner_request&)>;
    static std::vector<uint64_t> golden(const horner_request& r) {
        return interp::golden_horner_steps(r.k, r.t, r.deg2);
    }
    explicit horner_checker(golden_fn g = &horner_checker::golden) : golden_(std::move(g)) {}

    void check(const horner_sample& s) {
        samples_.push_back(s);
        const auto g = golden_(s.req);
        if (g.back() != s.out || g != s.steps) {
            samples_.back().matched = false;
            ++mismatches_;
            std::ostringstream os;
            os << "Horner at " << s.valid << " t=" << s.req.t << (s.req.deg2 ? " deg2" : " cubic")
               << ": device 0x" << std::hex << s.out << " golden 0x" << g.back() << std::dec << " ("
               << s.steps.size() << " steps seen, " << g.size() << " expected)";
            report_mismatch(mismatches_, 10, os.str());
        }
        latencies_.insert(s.valid - s.accepted);
    }
    std::size_t mismatches() const { return mismatches_; }
    const std::vector<horner_sample>& samples() const { return samples_; }
    const std::set<sc_core::sc_time>& latencies() const { return latencies_; }
    // Clocks per result over the run: (last valid edge - first acceptance edge) / results.
    double cycles_per_result() const {
        if (samples_.empty()) return 0.0;
        return (samples_.back().valid - samples_.front().accepted) / period_ /
               static_cast<double>(samples_.size());
    }
    void set_period(const sc_core::sc_time& p) { period_ = p; }

private:
    golden_fn golden_;
    sc_core::sc_time period_ = interp_period();
    std::size_t mismatches_ = 0;
    std::vector<horner_sample> samples_;
    std::set<sc_core::sc_time> latencies_;
};

class horner_bench : public sc_core::sc_module {
public:
    sc_core::sc_clock clk;
    sc_core::sc_signal<bool> start{"start"}, deg2{"deg2"}, done{"done"}, busy{"busy"};
    sc_core::sc_signal<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"}, i_t{"i_t"};
    sc_core::sc_signal<t_t> t{"t"};

    horner_checker checker;
    horner_unit dut{"dut"};
    horner_stimulus stim;
    horner_monitor mon;

    horner_bench(const sc_core::sc_module_name& name, std::vector<horner_request> reqs, unsigned gap = 0,
                 horner_checker::golden_fn golden = &horner_checker::golden, const interp_clock& ck = {})
        : sc_module(name), clk("clk", ck.period(), ck.duty()), checker(std::move(golden)),
          stim("stim", std::move(reqs), gap), mon("mon", [this](const horner_sample& s) { checker.check(s); }) {
        checker.set_period(ck.period());
        dut.clk(clk); dut.start(start); dut.deg2(deg2);
        dut.a(a); dut.b(b); dut.c(c); dut.d(d); dut.t(t);
        dut.i_t(i_t); dut.done(done); dut.busy(busy);
        stim.clk(clk); stim.busy(busy); stim.done(done); stim.start(start); stim.deg2(deg2);
        stim.a(a); stim.b(b); stim.c(c); stim.d(d); stim.t(t);
        mon.clk(clk); mon.start(start); mon.busy(busy); mon.done(done); mon.deg2(deg2);
        mon.a(a); mon.b(b); mon.c(c); mon.d(d); mon.t(t); mon.i_t(i_t); mon.rg_value(dut.rg_value);
    }
    bool finished() const { return stim.finished(); }
};

// ---------------------------------------------------------------------------------------------
// Forward-difference evaluator.

struct fd_interval {
    interp::cubic_coefs k;
    unsigned len = 0;
};

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
    fd_stimulus(const sc_core::sc_module_name& name, std::vector<fd_interval> ivs)
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
    std::vector<fd_interval> ivs_;
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
class fd_checker {
public:
    static constexpr unsigned n_pixels = 1u << M;
    explicit fd_checker(int frac = interp::fd_fmt.frac) : frac_(frac) {}

    void check(const fd_sample& s) {
        samples_.push_back(s);
        const unsigned len = (s.iv.len == 0 || s.iv.len > n_pixels) ? n_pixels : s.iv.len;
        const auto g = interp::golden_fd(s.iv.k, M, len, frac_);
        const bool in_range = s.k < g.size();
        if (!in_range || g[s.k] != s.out) {
            samples_.back().matched = false;
            ++mismatches_;
            std::ostringstream os;
            os << "forward differences at " << s.valid << " interval " << s.interval << " pixel " << s.k
               << ": device 0x" << std::hex << s.out << " golden 0x" << (in_range ? g[s.k] : 0) << std::dec;
            report_mismatch(mismatches_, 10, os.str());
        }
        // Against Horner at the same t (t = k/N on Q1.8): FD is floor(P) of the exact polynomial,
        // Horner P minus less than 3 LSB of floors, so 0 <= FD - Horner <= 2 LSB.
        const uint64_t t = static_cast<uint64_t>(s.k) << (interp::t_fmt.frac - M);
        const int64_t diff = code_value(s.out, interp::coef_fmt) -
                             code_value(interp::golden_horner(s.iv.k, t, false), interp::coef_fmt);
        min_vs_horner_ = std::min(min_vs_horner_, diff);
        max_vs_horner_ = std::max(max_vs_horner_, diff);
        latencies_[s.k].insert(s.valid - s.accepted);
    }
    std::size_t mismatches() const { return mismatches_; }
    const std::vector<fd_sample>& samples() const { return samples_; }
    int64_t min_vs_horner() const { return min_vs_horner_; }
    int64_t max_vs_horner() const { return max_vs_horner_; }
    const std::map<unsigned, std::set<sc_core::sc_time>>& latencies() const { return latencies_; }
    double cycles_per_pixel() const {
        if (samples_.empty()) return 0.0;
        return (samples_.back().valid - samples_.front().accepted) / period_ /
               static_cast<double>(samples_.size());
    }
    void set_period(const sc_core::sc_time& p) { period_ = p; }

private:
    int frac_;
    sc_core::sc_time period_ = interp_period();
    std::size_t mismatches_ = 0;
    std::vector<fd_sample> samples_;
    int64_t min_vs_horner_ = INT64_MAX, max_vs_horner_ = INT64_MIN;
    std::map<unsigned, std::set<sc_core::sc_time>> latencies_;
};

template <unsigned M>
class fd_bench : public sc_core::sc_module {
public:
    using len_t = typename fd_ctrl<M>::len_t;
    sc_core::sc_clock clk;
    sc_core::sc_signal<bool> start{"start"}, valid{"valid"}, last{"last"};
    sc_core::sc_signal<len_t> len{"len"};
    sc_core::sc_signal<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"}, i_px{"i_px"};

    fd_checker<M> checker;
    fd_eval<M> dut{"dut"};
    fd_stimulus<M> stim;
    fd_monitor<M> mon;

    fd_bench(const sc_core::sc_module_name& name, std::vector<fd_interval> ivs, const interp_clock& ck = {})
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
