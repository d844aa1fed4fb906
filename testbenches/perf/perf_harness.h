// What perf_models times: a golden model's batch (plain C++) or a SystemC harness (a design under
// test with its stimulus and a check of every result against the golden model), and the small
// lean harness of the specular devices. One SystemC harness per process (perf_models.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <systemc>

#include "arith/specular_arith.h"
#include "formats/specular_formats.h"
#include "specular/block_delays.h"

namespace shading::perf {

// A SystemC design under test with its stimulus, advanced by sc_start(batch()) per benchmark
// iteration: items() results produced and checked so far, mismatches() against the golden model.
class harness {
public:
    virtual ~harness() = default;
    virtual sc_core::sc_object& root() = 0;  // traced when the case is traced
    virtual uint64_t items() const = 0;
    virtual uint64_t mismatches() const = 0;
    virtual sc_core::sc_time batch() const = 0;   // simulated time per benchmark iteration
    virtual sc_core::sc_time period() const = 0;  // one clock (or strobe) period, for clocks/s
};

// Block delays all zero: every block settles in delta cycles (the "delays off" rows).
inline block_delays zero_delays() {
    const sc_core::sc_time z = sc_core::SC_ZERO_TIME;
    return block_delays{z, z, z, z, z, z};
}

// A specular device (any specular_device<AGen> or a pin-compatible fast model) driven as Fig. 3
// with ctl17 from an sc_clock (5 ns high, 15 ns low: cos latched at the falling edge, outputs valid
// at the rising edge, as the Verilator comparison is driven). n and k_s*I are loaded once before
// the first pixel; one method at each rising edge checks the outputs of the pixel just latched
// against the golden model and presents the next cos code. Gen gives the n bus width (a Verilated
// device has no `generator`).
template <class Device, class Gen = typename Device::generator>
class specular_harness : public sc_core::sc_module, public harness {
    using n_t = sc_dt::sc_uint<Gen::n_fmt.width>;
    using cos_t = sc_dt::sc_uint<spec::cos_fmt.width>;
    using ksi_t = sc_dt::sc_uint<spec::ksi_fmt.width>;
    using out_t = sc_dt::sc_uint<spec::out_fmt.width>;

public:
    using golden_fn = std::function<datapath_nets(uint64_t n, uint64_t cos, const std::array<uint64_t, 3>& ksi)>;
    static constexpr uint64_t n = 120;
    static constexpr std::array<uint64_t, 3> ksi{255, 140, 40};

    sc_core::sc_clock ctl17;
    sc_core::sc_signal<bool> ctl15{"ctl15"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_signal<n_t> in16_n{"in16_n"};
    sc_core::sc_signal<cos_t> in18_cos{"in18_cos"};
    sc_core::sc_signal<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};
    sc_core::sc_signal<out_t> out25_r{"out25_r"}, out26_g{"out26_g"}, out27_b{"out27_b"};
    sc_core::sc_signal<bool> out29_valid{"out29_valid"};
    Device dut;

    SC_HAS_PROCESS(specular_harness);
    template <typename... DeviceArgs>
    specular_harness(const sc_core::sc_module_name& name, golden_fn golden, DeviceArgs&&... device_args)
        : sc_module(name),
          ctl17("ctl17", sc_core::sc_time(20, sc_core::SC_NS), 0.25, sc_core::sc_time(40, sc_core::SC_NS), true),
          dut("dut", std::forward<DeviceArgs>(device_args)...),
          golden_(std::move(golden)) {
        dut.ctl15(ctl15); dut.ctl17(ctl17); dut.ctl20(ctl20); dut.ctl22(ctl22); dut.ctl24(ctl24);
        dut.in16_n(in16_n); dut.in18_cos(in18_cos);
        dut.in19_ksi_r(in19_ksi_r); dut.in21_ksi_g(in21_ksi_g); dut.in23_ksi_b(in23_ksi_b);
        dut.out25_r(out25_r); dut.out26_g(out26_g); dut.out27_b(out27_b); dut.out29_valid(out29_valid);
        SC_THREAD(load);
        SC_METHOD(on_rise);
        sensitive << ctl17.posedge_event();
        dont_initialize();
    }

    sc_core::sc_object& root() override { return *this; }
    uint64_t items() const override { return items_; }
    uint64_t mismatches() const override { return mismatches_; }
    sc_core::sc_time batch() const override { return period() * 1000.0; }
    sc_core::sc_time period() const override { return ctl17.period(); }

private:
    // RG1, RG3..RG5 latch at the falling edges of their 4 ns pulses, all before ctl17 first rises.
    void load() {
        const sc_core::sc_time pulse(4, sc_core::SC_NS);
        in16_n.write(n_t(n));
        in19_ksi_r.write(ksi_t(ksi[0])); in21_ksi_g.write(ksi_t(ksi[1])); in23_ksi_b.write(ksi_t(ksi[2]));
        for (auto* ctl : {&ctl15, &ctl20, &ctl22, &ctl24}) {
            ctl->write(true);
            wait(pulse);
            ctl->write(false);
            wait(pulse);
        }
    }
    void on_rise() {
        if (pending_) {
            ++items_;
            if (out25_r.read().to_uint64() != expected_[0] || out26_g.read().to_uint64() != expected_[1] ||
                out27_b.read().to_uint64() != expected_[2]) {
                if (mismatches_ < 3) {  // the first few, for whoever reads the failed run
                    const auto u = [](uint64_t v) { return static_cast<unsigned long long>(v); };
                    std::fprintf(stderr, "%s: mismatch at %s, n %llu cos %llu: RGB %llu %llu %llu, golden %llu %llu %llu\n",
                                 name(), sc_core::sc_time_stamp().to_string().c_str(), u(n), u(prev_),
                                 u(out25_r.read().to_uint64()), u(out26_g.read().to_uint64()),
                                 u(out27_b.read().to_uint64()), u(expected_[0]), u(expected_[1]), u(expected_[2]));
                }
                ++mismatches_;
            }
        }
        // Codes walk the whole cos range in a scattered order (7919 is prime to 32769).
        prev_ = code_;
        code_ = (code_ + 7919) % (spec::cos_one + 1);
        in18_cos.write(cos_t(code_));
        expected_ = golden_(n, code_, ksi).out;
        pending_ = true;
    }

    golden_fn golden_;
    std::array<uint64_t, 3> expected_{};
    uint64_t prev_ = 0, code_ = 0, items_ = 0, mismatches_ = 0;
    bool pending_ = false;
};

// A clocked specular device (the squared-quadratic and square-and-multiply devices, ours: UA 60553's
// pins plus `clk`) driven the same way, with its 20 ns clock and strobe 17 an sc_clock of `clocks`
// clock periods, high for one of them: every result is valid when strobe 17 rises (the benches'
// squared_timing and sqmul_timing, 15 and 24 clocks). Strobe 17 falls 5 ns after a rising edge
// of clk, clear of every edge.
template <class Device>
class clocked_harness : public sc_core::sc_module, public harness {
    using n_t = typename decltype(Device::in16_n)::data_type;  // the fast models have no n_fmt
    using cos_t = sc_dt::sc_uint<spec::cos_fmt.width>;
    using ksi_t = sc_dt::sc_uint<spec::ksi_fmt.width>;
    using out_t = sc_dt::sc_uint<spec::out_fmt.width>;

public:
    using golden_fn = std::function<std::array<uint64_t, 3>(uint64_t n, uint64_t cos, const std::array<uint64_t, 3>& ksi)>;
    static constexpr uint64_t n = 120;
    static constexpr std::array<uint64_t, 3> ksi{255, 140, 40};

    sc_core::sc_clock clk;
    sc_core::sc_clock ctl17;
    sc_core::sc_signal<bool> ctl15{"ctl15"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_signal<n_t> in16_n{"in16_n"};
    sc_core::sc_signal<cos_t> in18_cos{"in18_cos"};
    sc_core::sc_signal<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};
    sc_core::sc_signal<out_t> out25_r{"out25_r"}, out26_g{"out26_g"}, out27_b{"out27_b"};
    sc_core::sc_signal<bool> out29_valid{"out29_valid"};
    Device dut;

    SC_HAS_PROCESS(clocked_harness);
    template <typename... DeviceArgs>
    clocked_harness(const sc_core::sc_module_name& name, unsigned clocks, golden_fn golden, DeviceArgs&&... device_args)
        : sc_module(name),
          clk("clk", sc_core::sc_time(20, sc_core::SC_NS)),
          ctl17("ctl17", sc_core::sc_time(20.0 * clocks, sc_core::SC_NS), 1.0 / clocks,
                sc_core::sc_time(45, sc_core::SC_NS), true),
          dut("dut", std::forward<DeviceArgs>(device_args)...),
          golden_(std::move(golden)) {
        dut.clk(clk);
        dut.ctl15(ctl15); dut.ctl17(ctl17); dut.ctl20(ctl20); dut.ctl22(ctl22); dut.ctl24(ctl24);
        dut.in16_n(in16_n); dut.in18_cos(in18_cos);
        dut.in19_ksi_r(in19_ksi_r); dut.in21_ksi_g(in21_ksi_g); dut.in23_ksi_b(in23_ksi_b);
        dut.out25_r(out25_r); dut.out26_g(out26_g); dut.out27_b(out27_b); dut.out29_valid(out29_valid);
        SC_THREAD(load);
        SC_METHOD(on_rise);
        sensitive << ctl17.posedge_event();
        dont_initialize();
    }

    sc_core::sc_object& root() override { return *this; }
    uint64_t items() const override { return items_; }
    uint64_t mismatches() const override { return mismatches_; }
    sc_core::sc_time batch() const override { return ctl17.period() * 1000.0; }
    sc_core::sc_time period() const override { return clk.period(); }

private:
    // RG1, RG3..RG5 latch at the falling edges of their 4 ns pulses, all before ctl17 first rises.
    void load() {
        const sc_core::sc_time pulse(4, sc_core::SC_NS);
        in16_n.write(n_t(n));
        in19_ksi_r.write(ksi_t(ksi[0])); in21_ksi_g.write(ksi_t(ksi[1])); in23_ksi_b.write(ksi_t(ksi[2]));
        for (auto* ctl : {&ctl15, &ctl20, &ctl22, &ctl24}) {
            ctl->write(true);
            wait(pulse);
            ctl->write(false);
            wait(pulse);
        }
    }
    // At strobe 17's rise (output 29 rises with it, a gate delay later) the pixel latched at its
    // fall is checked (the first rise has none), the next code presented.
    void on_rise() {
        if (pending_) {
            ++items_;
            mismatches_ += out25_r.read().to_uint64() != expected_[0] || out26_g.read().to_uint64() != expected_[1] ||
                           out27_b.read().to_uint64() != expected_[2];
        }
        code_ = (code_ + 7919) % (spec::cos_one + 1);  // the whole cos range, scattered
        in18_cos.write(cos_t(code_));
        expected_ = golden_(n, code_, ksi);
        pending_ = true;
    }

    golden_fn golden_;
    std::array<uint64_t, 3> expected_{};
    uint64_t code_ = 0, items_ = 0, mismatches_ = 0;
    bool pending_ = false;
};

}  // namespace shading::perf
