// Co-simulation of the interpolation paper's units: the RTL (rtl/interp, Verilated with --sc --pins-sc-uint, so
// its ports are the same sc_uint buses as ours) in the same SystemC simulation as our block-level
// units, on the same clock and the same stimulus (testbenches/interp's stimulus parts). At every
// edge where a result is valid, the RTL's outputs are compared with our unit's and with the golden
// model (src/golden/interp_golden.h); any difference is a shading/mismatch warning (which fails a
// test unless announced) and is counted.
#pragma once

#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <systemc>

#include "golden/interp_golden.h"
#include "interp/coef_unit_cubic.h"
#include "testbenches/interp/interp_coef_bench.h"
#include "testbenches/interp/interp_horner_bench.h"

namespace shading::tb {

// What both co-simulations count.
struct cosim_counts {
    std::size_t checked = 0;         // result edges compared
    std::size_t rtl_vs_golden = 0;   // RTL differs from the golden model
    std::size_t rtl_vs_ours = 0;     // RTL differs from our SystemC unit
    std::size_t ours_vs_golden = 0;  // our unit differs from the golden model
    std::size_t inject = SIZE_MAX;   // corrupt the golden value of this result (checker test)
    std::size_t mismatches() const { return rtl_vs_golden + rtl_vs_ours + ours_vs_golden; }
};

inline void cosim_report(std::size_t count, const std::string& what) { report_mismatch(count, 10, what); }

// Cubic coefficient unit: the RTL `Rtl` (coef_unit_cubic with SET, DIV) beside our
// coef_unit_cubic<SET, DIV>, both fed by coef_stimulus (one sample set per clock, the case's
// samples). The coefficients are valid at the rising edge after the samples' falling edge.
template <typename Rtl, interp::sample_set SET, interp::div3_mode DIV>
class coef_cosim : public sc_core::sc_module {
public:
    sc_core::sc_clock clk{"clk", interp_period()};
    sc_core::sc_signal<bool> sample_valid{"sample_valid"};
    sc_core::sc_vector<sc_core::sc_signal<sample_t>> c1{"c1", 4}, c2{"c2", 4}, q{"q", 3};
    sc_core::sc_signal<coef_t> ours_a{"ours_a"}, ours_b{"ours_b"}, ours_c{"ours_c"}, ours_d{"ours_d"};
    sc_core::sc_signal<coef_t> rtl_a{"rtl_a"}, rtl_b{"rtl_b"}, rtl_c{"rtl_c"}, rtl_d{"rtl_d"};

    coef_unit_cubic<SET, DIV> ours{"ours"};
    Rtl rtl{"rtl"};
    coef_stimulus stim;
    cosim_counts counts;

    SC_HAS_PROCESS(coef_cosim);
    coef_cosim(const sc_core::sc_module_name& name, item_source<coef_inputs> sets)
        : sc_module(name), stim("stim", std::move(sets)) {
        auto& in = SET == interp::sample_set::case1 ? c1 : c2;
        ours.clk(clk); ours.i1(in[0]); ours.i2(in[1]); ours.i3(in[2]); ours.i4(in[3]);
        ours.a(ours_a); ours.b(ours_b); ours.c(ours_c); ours.d(ours_d);
        rtl.clk(clk); rtl.i1(in[0]); rtl.i2(in[1]); rtl.i3(in[2]); rtl.i4(in[3]);
        rtl.a(rtl_a); rtl.b(rtl_b); rtl.c(rtl_c); rtl.d(rtl_d);
        stim.clk(clk); stim.sample_valid(sample_valid);
        for (std::size_t i = 0; i < 4; ++i) stim.c1[i](c1[i]), stim.c2[i](c2[i]);
        for (std::size_t i = 0; i < 3; ++i) stim.q[i](q[i]);
        SC_METHOD(compare);
        sensitive << clk.posedge_event();
        dont_initialize();
    }
    bool finished() const { return stim.finished(); }

private:
    // Reads give the values before this edge: the samples latched at the last falling edge (the
    // source holds them until after the edge) and the coefficients formed from them.
    void compare() {
        if (!sample_valid.read()) return;
        const auto& in = SET == interp::sample_set::case1 ? c1 : c2;
        const std::array<uint64_t, 4> s{in[0].read().to_uint64(), in[1].read().to_uint64(),
                                        in[2].read().to_uint64(), in[3].read().to_uint64()};
        auto g = interp::golden_cubic_coefs(s, SET, DIV);
        if (counts.checked++ == counts.inject) g.a ^= 1;
        const interp::cubic_coefs o{coef_code(ours_a.read()), coef_code(ours_b.read()), coef_code(ours_c.read()),
                                    coef_code(ours_d.read())};
        const interp::cubic_coefs r{coef_code(rtl_a.read()), coef_code(rtl_b.read()), coef_code(rtl_c.read()),
                                    coef_code(rtl_d.read())};
        if (r == g && o == g) return;
        counts.rtl_vs_golden += !(r == g);
        counts.rtl_vs_ours += !(r == o);
        counts.ours_vs_golden += !(o == g);
        std::ostringstream os;
        os << name() << " at " << sc_core::sc_time_stamp() << ", samples (" << s[0] << ", " << s[1] << ", " << s[2]
           << ", " << s[3] << "): RTL (" << r.a << ", " << r.b << ", " << r.c << ", " << r.d << ") ours (" << o.a
           << ", " << o.b << ", " << o.c << ", " << o.d << ") golden (" << g.a << ", " << g.b << ", " << g.c << ", "
           << g.d << ") [Q16.16 codes]";
        cosim_report(counts.mismatches(), os.str());
    }
};

// Horner unit: the RTL `Rtl` (horner_unit) on the pins of our horner_bench (its stimulus drives
// start, A..D, t, deg2 through our unit's handshake). At every rising edge the RTL's i_t (= RG,
// so every micro-step), done and busy must equal ours; at every done edge its I(t) must equal the
// golden model's for the inputs held at that edge. Our unit is checked by the bench's own checker
// against the golden micro-steps.
template <typename Rtl>
class horner_cosim : public sc_core::sc_module {
public:
    sc_core::sc_signal<coef_t> rtl_i_t{"rtl_i_t"};
    sc_core::sc_signal<bool> rtl_done{"rtl_done"}, rtl_busy{"rtl_busy"};

    horner_bench bench;
    Rtl rtl{"rtl"};
    cosim_counts counts;
    std::size_t edges = 0;  // rising edges compared

    SC_HAS_PROCESS(horner_cosim);
    horner_cosim(const sc_core::sc_module_name& name, item_source<horner_request> reqs, unsigned gap = 0)
        : sc_module(name), bench("bench", std::move(reqs), gap) {
        bench.checker.keep_samples(false);
        rtl.clk(bench.clk); rtl.start(bench.start); rtl.deg2(bench.deg2);
        rtl.a(bench.a); rtl.b(bench.b); rtl.c(bench.c); rtl.d(bench.d); rtl.t(bench.t);
        rtl.i_t(rtl_i_t); rtl.done(rtl_done); rtl.busy(rtl_busy);
        SC_METHOD(compare);
        sensitive << bench.clk.posedge_event();
        dont_initialize();
    }
    bool finished() const { return bench.finished(); }

private:
    void compare() {
        ++edges;
        const uint64_t ours = bench.i_t.read().to_uint64(), rtl_v = rtl_i_t.read().to_uint64();
        if (ours != rtl_v || bench.done.read() != rtl_done.read() || bench.busy.read() != rtl_busy.read()) {
            ++counts.rtl_vs_ours;
            std::ostringstream os;
            os << name() << " at " << sc_core::sc_time_stamp() << ": RTL i_t 0x" << std::hex << rtl_v << " done "
               << rtl_done.read() << " busy " << rtl_busy.read() << ", ours i_t 0x" << ours << " done "
               << bench.done.read() << " busy " << bench.busy.read();
            cosim_report(counts.mismatches(), os.str());
        }
        if (!rtl_done.read()) return;
        const interp::cubic_coefs k{coef_code(bench.a.read()), coef_code(bench.b.read()), coef_code(bench.c.read()),
                                    coef_code(bench.d.read())};
        const uint64_t t = bench.t.read().to_uint64();
        uint64_t g = interp::golden_horner(k, t, bench.deg2.read());
        if (counts.checked++ == counts.inject) g ^= 1;
        if (rtl_v == g) return;
        ++counts.rtl_vs_golden;
        std::ostringstream os;
        os << name() << " at " << sc_core::sc_time_stamp() << " t=" << t << (bench.deg2.read() ? " deg2" : " cubic")
           << ": RTL I(t) 0x" << std::hex << rtl_v << " golden 0x" << g;
        cosim_report(counts.mismatches(), os.str());
    }
};

}  // namespace shading::tb
