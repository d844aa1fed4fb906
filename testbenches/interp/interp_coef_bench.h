// Testbench parts for the interpolation paper's coefficient units: all five (case 1 / case 2 x shift-and-add /
// exact /3, and the quadratic) side by side on the same clock, one sample set per clock
// (stimulus, monitor, checker: interp_bench_common.h).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <systemc>
#include <vector>

#include "interp/coef_unit_cubic.h"
#include "interp/coef_unit_quad.h"
#include "testbenches/interp/interp_bench_common.h"

namespace shading::tb {

struct coef_inputs {
    std::array<uint64_t, 4> c1{}, c2{};
    std::array<uint64_t, 3> q{};
};

// The random mode's stream: every sample of every set uniform over the sample bus, item i from
// (seed, i), one set per clock.
inline item_source<coef_inputs> random_coef_inputs(std::size_t n, uint64_t seed) {
    return item_source<coef_inputs>(n, [seed](std::size_t i) {
        split_rng r(seed, i);
        return coef_inputs{random_samples<4>(r), random_samples<4>(r), random_samples<3>(r)};
    });
}

struct coef_sample {
    coef_inputs in;
    std::array<interp::cubic_coefs, 5> out;  // in tb::variant order (interp_line.h)
    sc_core::sc_time at;
};

// One sample set per clock, no handshake: every set presented is taken at the next edge.
class coef_stimulus : public interp_stimulus<coef_inputs> {
public:
    sc_core::sc_out<bool> sample_valid{"sample_valid"};
    sc_core::sc_vector<sc_core::sc_out<sample_t>> c1{"c1", 4}, c2{"c2", 4}, q{"q", 3};

    coef_stimulus(const sc_core::sc_module_name& name, item_source<coef_inputs> sets)
        : interp_stimulus(name, std::move(sets)) {}

private:
    void present(const coef_inputs& s) override {
        for (std::size_t i = 0; i < 4; ++i) c1[i].write(s.c1[i]), c2[i].write(s.c2[i]);
        for (std::size_t i = 0; i < 3; ++i) q[i].write(s.q[i]);
        sample_valid.write(true);
    }
    void begin() override {
        if (size() > 0) edge();
    }
    void edge() override { present(item(accepted_++)); }
    bool through() const override { return accepted_ >= size(); }
    // sample_valid drops at the edge after the last set (at the first edge when there is none).
    void tail() override {
        if (size() > 0) wait(clk.posedge_event());
        sample_valid.write(false);
        wait(clk.posedge_event());
    }
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

class coef_checker : public checker_log<coef_sample> {
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
        record(s);
        const bool inject = begin(s.at, s.at);
        for (std::size_t u = 0; u < 5; ++u) {
            auto g = golden_(u, s.in);
            if (inject && u == 0) g.a ^= 1;
            if (g == s.out[u]) continue;
            ++per_unit_[u];
            std::ostringstream os;
            os << "coefficient unit " << u << " at " << s.at << ": device (" << s.out[u].a << ", "
               << s.out[u].b << ", " << s.out[u].c << ", " << s.out[u].d << ") golden (" << g.a << ", " << g.b
               << ", " << g.c << ", " << g.d << ") [Q16.16 codes]";
            report_mismatch(mismatches(), 10, os.str());
        }
    }
    std::size_t mismatches(std::size_t unit) const {
        auto it = per_unit_.find(unit);
        return it == per_unit_.end() ? 0 : it->second;
    }
    std::size_t mismatches() const {
        std::size_t n = 0;
        for (const auto& [u, c] : per_unit_) n += c;
        return n;
    }

private:
    golden_fn golden_;
    std::map<std::size_t, std::size_t> per_unit_;  // mismatches per unit
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

    coef_bench(const sc_core::sc_module_name& name, item_source<coef_inputs> sets,
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

}  // namespace shading::tb
