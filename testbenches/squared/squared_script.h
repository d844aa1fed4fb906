// A directed bench for the squared-quadratic device's timing tests: the device on the specular
// pins, an sc_clock for its squaring stage, the specular monitor (samples at output 29's rising
// edge after a latch), and a thread that runs a test's script of pin changes and waits. Every edge
// of output 29 is logged with its time, so a test checks latencies against hand-computed instants.
#pragma once

#include <functional>
#include <systemc>
#include <vector>

#include "testbenches/specular/specular_tb.h"

namespace shading::tb {

template <typename Device>
class scripted_bench : public sc_core::sc_module {
public:
    sc_core::sc_clock clk;
    // Strobes idle high (Fig. 3): their first falling edge latches.
    sc_core::sc_signal<bool> ctl15{"ctl15", true}, ctl17{"ctl17", true}, ctl20{"ctl20", true}, ctl22{"ctl22", true},
        ctl24{"ctl24", true};
    sc_core::sc_signal<n_t> in16_n{"in16_n"};
    sc_core::sc_signal<cos_t> in18_cos{"in18_cos"};
    sc_core::sc_signal<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};
    sc_core::sc_signal<out_t> out25_r{"out25_r"}, out26_g{"out26_g"}, out27_b{"out27_b"};
    sc_core::sc_signal<bool> out29_valid{"out29_valid"};

    Device dut;
    specular_monitor mon;
    std::vector<pixel_sample> samples;
    // Every rising edge of output 29 after the power-up one (idle, output 29 follows the high
    // strobe 17 through its gate: a rise at the gate's delay, kept in power_up_rise).
    std::vector<sc_core::sc_time> valid_rises;
    std::vector<sc_core::sc_time> power_up_rise;

    using script = std::function<void(scripted_bench&)>;

    SC_HAS_PROCESS(scripted_bench);
    template <typename... DeviceArgs>
    scripted_bench(const sc_core::sc_module_name& name, const sc_core::sc_time& clk_period, script s,
                   DeviceArgs&&... device_args)
        : sc_module(name),
          clk("clk", clk_period),
          dut("dut", std::forward<DeviceArgs>(device_args)...),
          mon("mon", [this](const pixel_sample& p) { samples.push_back(p); }),
          script_(std::move(s)) {
        dut.clk(clk);
        bind(dut);
        bind(mon);
        dut.out25_r(out25_r); dut.out26_g(out26_g); dut.out27_b(out27_b); dut.out29_valid(out29_valid);
        mon.out25_r(out25_r); mon.out26_g(out26_g); mon.out27_b(out27_b); mon.out29_valid(out29_valid);
        SC_THREAD(run);
        SC_METHOD(on_valid);
        sensitive << out29_valid.posedge_event();
        dont_initialize();
    }

    bool finished() const { return finished_; }

    // Script steps: wait until an absolute time; load n and k_s*I (each strobe pulses 2 ns:
    // high at the call, falling 1 ns later, high again 1 ns after that); one strobe-17 pulse.
    void until(const sc_core::sc_time& t) {
        if (t > sc_core::sc_time_stamp()) wait(t - sc_core::sc_time_stamp());
    }
    void load(unsigned n, unsigned ksi) {
        in16_n.write(n);
        in19_ksi_r.write(ksi); in21_ksi_g.write(ksi); in23_ksi_b.write(ksi);
        pulse({&ctl15, &ctl20, &ctl22, &ctl24});
    }
    void load_n(unsigned n) {
        in16_n.write(n);
        pulse({&ctl15});
    }
    // cos on in18 1 ns before strobe 17 falls at `fall`; strobe 17 rises `low` later.
    void strobe(const sc_core::sc_time& fall, uint32_t cos, const sc_core::sc_time& low) {
        until(fall - sc_core::sc_time(1, sc_core::SC_NS));
        in18_cos.write(cos);
        until(fall);
        ctl17.write(false);
        wait(low);
        ctl17.write(true);
    }

private:
    template <typename M>
    void bind(M& m) {
        m.ctl15(ctl15); m.ctl17(ctl17); m.ctl20(ctl20); m.ctl22(ctl22); m.ctl24(ctl24);
        m.in16_n(in16_n); m.in18_cos(in18_cos);
        m.in19_ksi_r(in19_ksi_r); m.in21_ksi_g(in21_ksi_g); m.in23_ksi_b(in23_ksi_b);
    }

    void pulse(std::initializer_list<sc_core::sc_signal<bool>*> strobes) {
        wait(1, sc_core::SC_NS);
        for (auto* s : strobes) s->write(false);
        wait(1, sc_core::SC_NS);
        for (auto* s : strobes) s->write(true);
    }

    void run() {
        script_(*this);
        finished_ = true;
        sc_core::sc_stop();
    }

    void on_valid() {
        (seen_first_ ? valid_rises : power_up_rise).push_back(sc_core::sc_time_stamp());
        seen_first_ = true;
    }
    bool seen_first_ = false;

    script script_;
    bool finished_ = false;
};

}  // namespace shading::tb
