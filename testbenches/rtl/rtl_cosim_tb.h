// Co-simulation of a specular device's RTL twin (rtl/, compiled by `verilator --sc`) with the
// SystemC model in one simulation: the stimulus of testbenches/specular drives both devices'
// pins through the same signals; one monitor per device samples its outputs at every rising edge
// of its own out29_valid (specular_monitor), each sample is checked against the golden model
// (specular_checker), and the RTL's k-th sample is compared with the model's k-th: the same
// latched inputs, the same instant, the same three outputs. The instant: the RTL has no delays,
// so the model's sample comes later by its output-29 block's delay (0 for UA 60553's wire; the
// squared-quadratic device's AND gate) and by nothing else, as every other path settles earlier.
// Rtl is any module with the device's pins: a Verilated class built with --pins-sc-uint (pins of
// 2..64 wires are sc_uint<W>, as ours), or a user's own RTL the same way (README). A device with a
// clk pin (the squared-quadratic device) gets an sc_clock of the timing's period, shared by both.
// Stimulus is the specular stimulus or any module with its pins and a (name, items, strobe_timing)
// constructor (its `items` type, if it names one: the squared device's restart stimulus);
// ModelMonitor samples the model's pins (the specular monitor, or a faulty one for negative tests).
#pragma once

#include <deque>
#include <memory>
#include <sstream>
#include <string>
#include <systemc>
#include <type_traits>
#include <utility>

#include "core/report_ids.h"
#include "core/trace.h"
#include "testbenches/specular/specular_tb.h"
#include "verilated_vcd_sc.h"

namespace shading::tb {

// The stream a stimulus takes: its own `items` type, or the specular stimulus's surfaces.
template <typename S, typename = void>
struct stimulus_items {
    using type = item_source<surface>;
};
template <typename S>
struct stimulus_items<S, std::void_t<typename S::items>> {
    using type = typename S::items;
};

template <typename Device, typename Rtl, typename Stimulus = specular_stimulus,
          typename ModelMonitor = specular_monitor>
// The Fig. 1 bundle (specular/fig1_pins.h): the inputs both devices read, the SystemC model's outputs.
class rtl_cosim_bench : public sc_core::sc_module, public fig1_signals {
public:
    using items = typename stimulus_items<Stimulus>::type;
    // The RTL's outputs.
    sc_core::sc_signal<out_t> rtl_out25_r{"rtl_out25_r"}, rtl_out26_g{"rtl_out26_g"}, rtl_out27_b{"rtl_out27_b"};
    sc_core::sc_signal<bool> rtl_out29_valid{"rtl_out29_valid"};

    specular_checker checker, rtl_checker;  // the model's samples and the RTL's, against golden
    std::unique_ptr<sc_core::sc_clock> clk;  // devices with a clk pin only
    Device dut;
    Rtl rtl;
    Stimulus stim;
    ModelMonitor mon;
    specular_monitor rtl_mon;

    // `golden` checks both devices; `rtl_golden` (for the negative tests) replaces it for the RTL.
    // Fig. 3's default strobe timing.
    template <typename... DeviceArgs>
    rtl_cosim_bench(const sc_core::sc_module_name& name, items surfaces,
                    specular_checker::golden_fn golden, specular_checker::golden_fn rtl_golden,
                    DeviceArgs&&... device_args)
        : rtl_cosim_bench(name, std::move(surfaces), strobe_timing{}, std::move(golden), std::move(rtl_golden),
                          std::forward<DeviceArgs>(device_args)...) {}

    // The same with a strobe timing (and its clock period, for a device with a clk pin).
    template <typename... DeviceArgs>
    rtl_cosim_bench(const sc_core::sc_module_name& name, items surfaces, const strobe_timing& t,
                    specular_checker::golden_fn golden, specular_checker::golden_fn rtl_golden,
                    DeviceArgs&&... device_args)
        : sc_module(name),
          checker(std::move(golden)),
          rtl_checker(std::move(rtl_golden)),
          clk(has_clk<Device>::value || has_clk<Rtl>::value
                  ? std::make_unique<sc_core::sc_clock>("clk", t.clk_period, t.clk_duty)
                  : nullptr),
          dut("dut", std::forward<DeviceArgs>(device_args)...),
          rtl("rtl"),
          stim("stim", std::move(surfaces), t),
          mon("mon", [this](const pixel_sample& s) { on_sample(s, ours_, theirs_, false); }),
          rtl_mon("rtl_mon", [this](const pixel_sample& s) { on_sample(s, theirs_, ours_, true); }) {
        if constexpr (has_clk<Device>::value) dut.clk(*clk);
        if constexpr (has_clk<Rtl>::value) rtl.clk(*clk);
        bind_fig1_inputs(dut, *this);
        bind_fig1_inputs(rtl, *this);
        bind_fig1_inputs(stim, *this);
        bind_fig1_inputs(mon, *this);
        bind_fig1_inputs(rtl_mon, *this);
        bind_fig1_outputs(dut, *this);
        bind_fig1_outputs(mon, *this);
        rtl.out25_r(rtl_out25_r); rtl.out26_g(rtl_out26_g); rtl.out27_b(rtl_out27_b);
        rtl.out29_valid(rtl_out29_valid);
        rtl_mon.out25_r(rtl_out25_r); rtl_mon.out26_g(rtl_out26_g); rtl_mon.out27_b(rtl_out27_b);
        rtl_mon.out29_valid(rtl_out29_valid);
    }

    bool finished() const { return stim.finished(); }
    std::size_t pairs() const { return pairs_; }             // samples compared RTL against model
    std::size_t cross_mismatches() const { return cross_mismatches_; }
    std::size_t unpaired() const { return ours_.size() + theirs_.size(); }  // samples one side lacks

private:
    // Both monitors fire in the same instant, or the model's after the RTL's by its output-29 delay
    // (in either order): a sample waits in its queue until the other side's arrives.
    void on_sample(const pixel_sample& s, std::deque<pixel_sample>& mine, std::deque<pixel_sample>& other,
                   bool is_rtl) {
        (is_rtl ? rtl_checker : checker).check(s);
        if (other.empty()) {
            mine.push_back(s);
            return;
        }
        const pixel_sample o = other.front();
        other.pop_front();
        compare(is_rtl ? o : s, is_rtl ? s : o);
    }

    void compare(const pixel_sample& model, const pixel_sample& rtl_s) {
        ++pairs_;
        if (model.out == rtl_s.out && model.at == rtl_s.at + dut.out29.delay() && model.n == rtl_s.n &&
            model.cos == rtl_s.cos && model.ksi == rtl_s.ksi)
            return;
        if (++cross_mismatches_ > 10) return;
        std::ostringstream os;
        os << "RTL against the SystemC model, sample " << pairs_ - 1 << " n=" << model.n << " cos=0x" << std::hex
           << model.cos << std::dec << ": model (" << model.out[0] << "," << model.out[1] << "," << model.out[2]
           << ") at " << model.at << ", RTL (" << rtl_s.out[0] << "," << rtl_s.out[1] << "," << rtl_s.out[2]
           << ") at " << rtl_s.at << " [Q9.8 codes]";
        SC_REPORT_WARNING(msg::mismatch, os.str().c_str());
    }

    std::deque<pixel_sample> ours_, theirs_;
    std::size_t pairs_ = 0, cross_mismatches_ = 0;
};

// Runs a co-simulation bench until its stimulus ends (false if `limit` passes first). With a
// non-empty `vcd_stem`, <stem>.vcd gets every SystemC signal of the bench (our model's nets and the
// RTL's pins, modules/core/trace.h) and <stem>_rtl.vcd every net inside the RTL (Verilator's
// writer: a Verilated model's internals are not SystemC signals).
template <typename Bench>
bool run_cosim(Bench& bench, const sc_core::sc_time& limit, const std::string& vcd_stem = {}) {
    std::unique_ptr<vcd_file> vcd;
    std::unique_ptr<VerilatedVcdSc> rtl_vcd;
    if (!vcd_stem.empty()) {
        vcd = std::make_unique<vcd_file>(vcd_stem);
        vcd->trace(bench);
    }
    sc_core::sc_start(sc_core::SC_ZERO_TIME);  // Verilator traces an elaborated, initialised model
    if (!vcd_stem.empty()) {
        rtl_vcd = std::make_unique<VerilatedVcdSc>();
        bench.rtl.trace(rtl_vcd.get(), 99);
        rtl_vcd->open((vcd_stem + "_rtl.vcd").c_str());
    }
    sc_core::sc_start(limit);
    if (rtl_vcd) rtl_vcd->close();
    return bench.finished();
}

}  // namespace shading::tb
