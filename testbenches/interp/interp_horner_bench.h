// Testbench parts for the interpolation paper's iterative Horner unit (Fig. 4): requests accepted back to back
// (or with a gap), every micro-step of RG checked (stimulus, monitor, checker:
// interp_bench_common.h).
#pragma once

#include <cstdint>
#include <functional>
#include <set>
#include <sstream>
#include <systemc>
#include <vector>

#include "interp/horner_unit.h"
#include "interp/horner_unit_fast.h"
#include "testbenches/interp/interp_bench_common.h"
#include "testbenches/interp/interp_line.h"

namespace shading::tb {

struct horner_request {
    interp::cubic_coefs k;
    uint64_t t = 0;
    bool deg2 = false;
};

// The random mode's stream: random samples through a random unit's golden coefficients (the
// coefficients the Horner unit meets behind a coefficient unit), degree 2 for the quadratic, a
// random t in [0, 1]; item i from (seed, i).
inline item_source<horner_request> random_horner_requests(std::size_t n, uint64_t seed) {
    return item_source<horner_request>(n, [seed](std::size_t i) {
        split_rng r(seed, i);
        line_interval iv;
        iv.c1 = random_samples<4>(r);
        iv.c2 = random_samples<4>(r);
        iv.q = random_samples<3>(r);
        const variant v = all_variants[r.range(0, all_variants.size() - 1)];
        return horner_request{variant_coefs(v, iv), r.range(0, interp::t_one), is_quad(v)};
    });
}

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
class horner_stimulus : public interp_stimulus<horner_request> {
public:
    sc_core::sc_in<bool> busy{"busy"}, done{"done"};
    sc_core::sc_out<bool> start{"start"}, deg2{"deg2"};
    sc_core::sc_out<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"};
    sc_core::sc_out<t_t> t{"t"};

    horner_stimulus(const sc_core::sc_module_name& name, item_source<horner_request> reqs, unsigned gap = 0)
        : interp_stimulus(name, std::move(reqs)), gap_(gap) {}
    std::size_t requests() const { return size(); }

private:
    void present(const horner_request& r) override {
        a.write(coef_word(r.k.a)); b.write(coef_word(r.k.b));
        c.write(coef_word(r.k.c)); d.write(coef_word(r.k.d));
        t.write(t_t(r.t));
        deg2.write(r.deg2);
    }
    void begin() override {
        if (size() == 0) return;
        present(item(0));
        start.write(true);
    }
    void edge() override {
        const bool dn = done.read();
        const bool acc = start.read() && (!busy.read() || dn);
        if (dn) ++ended_;
        if (acc) {
            present(item(accepted_));
            ++accepted_;
            start.write(gap_ == 0 && accepted_ < size());
        } else if (gap_ > 0 && dn && accepted_ < size()) {
            gap_left_ = gap_;
        } else if (gap_left_ > 0 && --gap_left_ == 0) {
            present(item(accepted_));
            start.write(true);
        }
    }
    void tail() override { wait(2 * interp_period()); }

    unsigned gap_, gap_left_ = 0;
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

class horner_checker : public checker_log<horner_sample> {
public:
    using golden_fn = std::function<std::vector<uint64_t>(const horner_request&)>;
    static std::vector<uint64_t> golden(const horner_request& r) {
        return interp::golden_horner_steps(r.k, r.t, r.deg2);
    }
    explicit horner_checker(golden_fn g = &horner_checker::golden) : golden_(std::move(g)) {}

    void check(const horner_sample& s) {
        horner_sample r = s;
        auto g = golden_(s.req);
        if (begin(s.accepted, s.valid)) g.back() ^= 1;
        if (g.back() != s.out || g != s.steps) {
            r.matched = false;
            ++mismatches_;
            std::ostringstream os;
            os << "Horner at " << s.valid << " t=" << s.req.t << (s.req.deg2 ? " deg2" : " cubic")
               << ": device 0x" << std::hex << s.out << " golden 0x" << g.back() << std::dec << " ("
               << s.steps.size() << " steps seen, " << g.size() << " expected)";
            report_mismatch(mismatches_, 10, os.str());
        }
        record(r);
        latencies_.insert(s.valid - s.accepted);
    }
    const std::set<sc_core::sc_time>& latencies() const { return latencies_; }

private:
    golden_fn golden_;
    std::set<sc_core::sc_time> latencies_;
};

// DUT: horner_unit (block level) or horner_unit_fast (the fast pin-level abstraction): the same pins
// and the RG net, checked by the same monitor and checker.
template <class DUT>
class horner_bench_t : public sc_core::sc_module {
public:
    sc_core::sc_clock clk;
    sc_core::sc_signal<bool> start{"start"}, deg2{"deg2"}, done{"done"}, busy{"busy"};
    sc_core::sc_signal<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"}, i_t{"i_t"};
    sc_core::sc_signal<t_t> t{"t"};

    horner_checker checker;
    DUT dut{"dut"};
    horner_stimulus stim;
    horner_monitor mon;

    horner_bench_t(const sc_core::sc_module_name& name, item_source<horner_request> reqs, unsigned gap = 0,
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
using horner_bench = horner_bench_t<horner_unit>;
using horner_bench_fast = horner_bench_t<horner_unit_fast>;

}  // namespace shading::tb
