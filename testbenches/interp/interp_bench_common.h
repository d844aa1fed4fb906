// What the benches of the interpolation paper's units share (interp_coef_bench.h, interp_horner_bench.h,
// interp_fd_bench.h, interp_line_bench.h), each in three pieces the programs and the GoogleTest suites reuse:
//   *_stimulus - drives the unit's pins synchronously (writes just after rising edges), from a list or a
//                generator (item_source: the random mode streams 10^7 requests), in one loop (interp_stimulus);
//   *_monitor  - samples the pins at rising edges: the inputs a request was evaluated with and
//                the result at the edge where the unit says it is valid;
//   *_checker  - compares every sample with the golden model (src/golden/interp_golden.h).
// Clock: 20 ns, rising edge first at 0, unless a bench is given other phases (interp_clock).
// Registers latch on the falling edge (blocks/reg.h).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <systemc>
#include <utility>
#include <vector>

#include "testbenches/common/bench_source.h"
#include "core/report_ids.h"
#include "formats/interp_formats.h"
#include "golden/interp_golden.h"

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

inline int64_t coef_code(const coef_t& v) { return code_value(v.to_uint64(), interp::coef_fmt); }
inline coef_t coef_word(int64_t code) { return coef_t(wrap_bits(code, interp::coef_fmt.width)); }

// Reports a mismatch through SystemC (shading/mismatch), the first `max` of them.
inline void report_mismatch(std::size_t count, std::size_t max, const std::string& what) {
    if (count <= max) SC_REPORT_WARNING(msg::mismatch, what.c_str());
}

// What every interp checker keeps: the samples (unless a long random run drops them), how many
// it checked and how many differed, the first acceptance and the last valid edge (for clocks per
// result), and which sample's golden value to corrupt (the tests of the verdict).
template <typename Sample>
class checker_log {
public:
    void inject_mismatch(std::size_t k, std::size_t count = 1) {
        inject_ = k;
        inject_count_ = count;
    }
    void keep_samples(bool keep) { keep_ = keep; }
    std::size_t checked() const { return checked_; }
    std::size_t mismatches() const { return mismatches_; }
    const std::vector<Sample>& samples() const { return samples_; }
    void set_period(const sc_core::sc_time& p) { period_ = p; }
    // Clocks per result over the run: (last valid edge - first acceptance edge) / results.
    double cycles_per_result() const {
        if (checked_ == 0) return 0.0;
        return (last_valid_ - first_accepted_) / period_ / static_cast<double>(checked_);
    }

protected:
    // Call once per sample, before comparing: true when this sample's golden value is corrupted.
    bool begin(const sc_core::sc_time& accepted, const sc_core::sc_time& valid) {
        if (checked_ == 0) first_accepted_ = accepted;
        last_valid_ = valid;
        const bool corrupt = checked_ >= inject_ && checked_ - inject_ < inject_count_;
        ++checked_;
        return corrupt;
    }
    void record(const Sample& s) {
        if (keep_) samples_.push_back(s);
    }
    std::size_t mismatches_ = 0;

private:
    std::size_t checked_ = 0, inject_ = std::numeric_limits<std::size_t>::max(), inject_count_ = 1;
    bool keep_ = true;
    std::vector<Sample> samples_;
    sc_core::sc_time first_accepted_, last_valid_, period_ = interp_period();
};

// The stimulus loop of every interp bench (coef_stimulus, horner_stimulus, fd_stimulus_of,
// line_stimulus), written once: a thread on the rising edges of clk that writes just after them. At
// the first edge it presents item 0 (begin); at each later edge the bench's handshake, reading the
// pins as they were before it, takes its step (edge) until every item is through (through: the unit
// finished all of them); then the bench's tail (two rising edges unless it says otherwise), the run
// marked finished and the simulation stopped.
template <typename Item>
class interp_stimulus : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> clk{"clk"};

    bool finished() const { return finished_; }
    std::size_t size() const { return items_.size(); }

protected:
    SC_HAS_PROCESS(interp_stimulus);
    interp_stimulus(const sc_core::sc_module_name& name, item_source<Item> items)
        : sc_module(name), items_(std::move(items)) {
        SC_THREAD(run);
    }

    // Item i (a generator's items in increasing order; the current one may be read again).
    const Item& item(std::size_t i) { return items_[i]; }
    virtual void present(const Item& it) = 0;  // put an item on the pins
    virtual void begin() {
        if (size() > 0) present(item(0));
    }
    virtual void edge() = 0;
    virtual bool through() const { return ended_ >= size(); }
    virtual void tail() {
        wait(clk.posedge_event());
        wait(clk.posedge_event());
    }

    std::size_t accepted_ = 0, ended_ = 0;  // items the unit took, and finished

private:
    void run() {
        wait(clk.posedge_event());
        begin();
        while (!through()) {
            wait(clk.posedge_event());
            edge();
        }
        tail();
        finished_ = true;
        sc_core::sc_stop();
    }

    item_source<Item> items_;
    bool finished_ = false;
};

// Random sample codes over the whole sample bus (what the coefficient units must take).
template <std::size_t N>
std::array<uint64_t, N> random_samples(split_rng& r) {
    std::array<uint64_t, N> a{};
    for (auto& x : a) x = r.range(0, interp::sample_fmt.mask());
    return a;
}

}  // namespace shading::tb
