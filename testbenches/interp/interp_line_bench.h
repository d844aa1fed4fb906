// Testbench parts for the raster-line interpolator (modules/interp/interp_line_unit.h), in the
// three-part style of interp_bench_common.h, reused by interp_line_tb and test_interp_line:
//   line_stimulus - presents each interval's samples I1..I4 and len with start = 1 just after a
//                   rising edge, and the next interval right after the edge that accepts it
//                   (start = 1 and ready = 1); or, with gap > 0, `gap` clocks after the edge where
//                   the previous interval's last pixel came out (the unit idle in between);
//   line_monitor  - at rising edges: the samples and len an interval was accepted with, and every
//                   pixel where valid = 1;
//   line_checker  - compares every pixel and its `last` flag with the golden chain
//                   (interp::golden_interp_line: golden_cubic_coefs + golden_fd).
#pragma once

#include <cstdint>
#include <functional>
#include <sstream>
#include <string>
#include <systemc>
#include <vector>

#include "golden/interp_golden.h"
#include "interp/fd_ctrl.h"
#include "testbenches/interp/interp_bench_common.h"
#include "testbenches/interp/interp_line.h"
#include "interp/interp_line_unit.h"
#include "interp/interp_line_unit_fast.h"

namespace shading::tb {

// The intervals of a raster line as the line unit takes them: the samples of one set, and len.
inline std::vector<interp::interval_samples> line_intervals(const line_scenario& line, interp::sample_set set) {
    std::vector<interp::interval_samples> v;
    for (const auto& iv : line.intervals)
        v.push_back({set == interp::sample_set::case1 ? iv.c1 : iv.c2, iv.len});
    return v;
}

// The random mode's stream: `pixels` pixels in intervals of random length 1..2^M, each with random
// samples I1..I4 over the whole sample bus; item i from (seed, i).
template <unsigned M>
item_source<interp::interval_samples> random_line_intervals(std::size_t pixels, uint64_t seed) {
    const random_runs runs(pixels, 1u << M, seed);
    return item_source<interp::interval_samples>(runs.count(), [seed, runs](std::size_t i) {
        split_rng r(seed, i);
        interp::interval_samples iv;
        iv.i = random_samples<4>(r);
        iv.len = static_cast<unsigned>(runs.length(i));
        return iv;
    });
}

struct line_sample {
    interp::interval_samples iv;  // what the interval was accepted with
    std::size_t interval = 0;     // index of the accepted interval
    unsigned k = 0;               // pixel index within it
    uint64_t out = 0;             // i_px, Q16.16 bus bits
    bool last = false;
    sc_core::sc_time accepted, valid;
    bool matched = true;          // set by the checker
};

template <unsigned M>
class line_stimulus : public interp_stimulus<interp::interval_samples> {
public:
    using len_t = typename fd_ctrl<M>::len_t;
    sc_core::sc_in<bool> ready{"ready"}, valid{"valid"}, last{"last"};
    sc_core::sc_out<bool> start{"start"};
    sc_core::sc_out<len_t> len{"len"};
    sc_core::sc_out<sample_t> i1{"i1"}, i2{"i2"}, i3{"i3"}, i4{"i4"};

    line_stimulus(const sc_core::sc_module_name& name, item_source<interp::interval_samples> ivs, unsigned gap = 0)
        : interp_stimulus(name, std::move(ivs)), gap_(gap) {}
    // When each interval's samples were put on the inputs (just after that rising edge).
    const std::vector<sc_core::sc_time>& presented() const { return presented_; }

private:
    void present(const interp::interval_samples& iv) override {
        i1.write(iv.i[0]); i2.write(iv.i[1]); i3.write(iv.i[2]); i4.write(iv.i[3]);
        len.write(len_t(iv.len));
        start.write(true);
        presented_.push_back(sc_core::sc_time_stamp());
    }
    void edge() override {
        if (start.read() && ready.read()) {  // accepted at this edge
            ++accepted_;
            if (accepted_ < size() && gap_ == 0) present(item(accepted_));
            else start.write(false);
        }
        if (valid.read() && last.read()) {  // the last pixel of an interval came out at this edge
            ++ended_;
            if (gap_ > 0 && accepted_ < size()) gap_left_ = gap_;
        } else if (gap_left_ > 0 && --gap_left_ == 0) {
            present(item(accepted_));
        }
    }

    unsigned gap_, gap_left_ = 0;
    std::vector<sc_core::sc_time> presented_;
};

template <unsigned M>
class line_monitor : public sc_core::sc_module {
public:
    using len_t = typename fd_ctrl<M>::len_t;
    sc_core::sc_in<bool> clk{"clk"}, start{"start"}, ready{"ready"}, valid{"valid"}, last{"last"};
    sc_core::sc_in<len_t> len{"len"};
    sc_core::sc_in<sample_t> i1{"i1"}, i2{"i2"}, i3{"i3"}, i4{"i4"};
    sc_core::sc_in<coef_t> i_px{"i_px"};

    SC_HAS_PROCESS(line_monitor);
    line_monitor(const sc_core::sc_module_name& name, std::function<void(const line_sample&)> sink)
        : sc_module(name), sink_(std::move(sink)) {
        SC_METHOD(on_edge);
        sensitive << clk.pos();
        dont_initialize();
    }

private:
    // Every read gives the value before this edge: the pixel of the clock that just ended, and the
    // samples the source held up to an accepting edge (latched by the unit half a clock earlier).
    void on_edge() {
        const auto now = sc_core::sc_time_stamp();
        if (valid.read()) {
            line_sample s;
            s.iv = cur_;
            s.interval = index_ - 1;
            s.k = k_++;
            s.out = i_px.read().to_uint64();
            s.last = last.read();
            s.accepted = accepted_;
            s.valid = now;
            sink_(s);
        }
        if (start.read() && ready.read()) {
            cur_.i = {i1.read().to_uint64(), i2.read().to_uint64(), i3.read().to_uint64(), i4.read().to_uint64()};
            cur_.len = len.read().to_uint();
            accepted_ = now;
            k_ = 0;
            ++index_;
        }
    }
    std::function<void(const line_sample&)> sink_;
    interp::interval_samples cur_;
    std::size_t index_ = 0;
    unsigned k_ = 0;
    sc_core::sc_time accepted_;
};

// Golden chain per accepted interval: its len pixels (interp::golden_interp_line of that interval).
template <unsigned M>
class line_checker : public checker_log<line_sample> {
public:
    static constexpr unsigned n_pixels = 1u << M;
    using golden_fn = std::function<std::vector<uint64_t>(const interp::interval_samples&)>;

    line_checker(interp::sample_set set, interp::div3_mode mode, golden_fn g = nullptr)
        : golden_(g ? std::move(g) : [set, mode](const interp::interval_samples& iv) {
              return interp::golden_interp_line({iv}, M, set, mode);
          }) {}

    void check(const line_sample& s) {
        line_sample r = s;
        if (s.interval != golden_interval_ || g_.empty()) {  // one golden run per interval
            g_ = golden_(s.iv);
            golden_interval_ = s.interval;
        }
        const bool in_range = s.k < g_.size();
        uint64_t g = in_range ? g_[s.k] : 0;
        if (begin(s.accepted, s.valid)) g ^= 1;
        const bool last_ok = s.last == (s.k + 1 == g_.size());
        if (!in_range || g != s.out || !last_ok) {
            r.matched = false;
            ++mismatches_;
            std::ostringstream os;
            os << "line unit at " << s.valid << " interval " << s.interval << " pixel " << s.k << ": device 0x"
               << std::hex << s.out << (s.last ? " last" : "") << " golden 0x" << g << std::dec
               << (s.k + 1 == g_.size() ? " last" : "") << " (of " << g_.size() << " pixels)";
            report_mismatch(mismatches_, 10, os.str());
        }
        record(r);
    }
    std::vector<uint64_t> pixels() const {
        std::vector<uint64_t> v;
        for (const auto& s : samples()) v.push_back(s.out);
        return v;
    }

private:
    golden_fn golden_;
    std::vector<uint64_t> g_;
    std::size_t golden_interval_ = 0;
};

// DUT: interp_line_unit (block level, default) or interp_line_unit_fast (the fast pin-level abstraction).
template <unsigned M, interp::sample_set SET, interp::div3_mode DIV, class DUT = interp_line_unit<M, SET, DIV>>
class line_bench : public sc_core::sc_module {
public:
    using len_t = typename fd_ctrl<M>::len_t;
    sc_core::sc_clock clk;
    sc_core::sc_signal<bool> start{"start"}, ready{"ready"}, valid{"valid"}, last{"last"};
    sc_core::sc_signal<len_t> len{"len"};
    sc_core::sc_signal<sample_t> i1{"i1"}, i2{"i2"}, i3{"i3"}, i4{"i4"};
    sc_core::sc_signal<coef_t> i_px{"i_px"};

    line_checker<M> checker;
    DUT dut{"dut"};
    line_stimulus<M> stim;
    line_monitor<M> mon;

    line_bench(const sc_core::sc_module_name& name, item_source<interp::interval_samples> ivs, unsigned gap = 0,
               typename line_checker<M>::golden_fn golden = nullptr, const interp_clock& ck = {})
        : sc_module(name), clk("clk", ck.period(), ck.duty()), checker(SET, DIV, std::move(golden)),
          stim("stim", std::move(ivs), gap), mon("mon", [this](const line_sample& s) { checker.check(s); }),
          period_(ck.period()) {
        dut.clk(clk); dut.start(start); dut.len(len);
        dut.i1(i1); dut.i2(i2); dut.i3(i3); dut.i4(i4);
        dut.i_px(i_px); dut.valid(valid); dut.last(last); dut.ready(ready);
        stim.clk(clk); stim.ready(ready); stim.valid(valid); stim.last(last);
        stim.start(start); stim.len(len);
        stim.i1(i1); stim.i2(i2); stim.i3(i3); stim.i4(i4);
        mon.clk(clk); mon.start(start); mon.ready(ready); mon.valid(valid); mon.last(last); mon.len(len);
        mon.i1(i1); mon.i2(i2); mon.i3(i3); mon.i4(i4); mon.i_px(i_px);
    }
    bool finished() const { return stim.finished(); }
    // Clocks from the first samples on the inputs to the last pixel on the output.
    double clocks_first_samples_to_last_pixel() const {
        if (stim.presented().empty() || checker.samples().empty()) return 0.0;
        return (checker.samples().back().valid - stim.presented().front()) / period_;
    }
    double clocks_per_pixel() const {
        const auto n = checker.samples().size();
        return n ? clocks_first_samples_to_last_pixel() / static_cast<double>(n) : 0.0;
    }

private:
    sc_core::sc_time period_;
};

}  // namespace shading::tb
