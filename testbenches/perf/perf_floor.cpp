// perf_models' floor rows: what a harness costs with nothing inside, so the table shows
// which targets no model can reach in SystemC on this machine. Every floor counts clocks (or
// strobes) per CPU second; a device in the same harness can only be slower.
//   floor/sc_clock            one sc_clock (20 ns, the specular harness's duty) and nothing else
//   floor/specular_harness    specular_harness (perf_harness.h: ctl17 from an sc_clock, the golden
//                             check and the next cos code at each rising edge) around a null device
//                             with the specular pins whose one method echoes ctl17 to out29; its
//                             outputs stay 0, so mismatches are reported, not failed (strict = false)
//   floor/horner_bench        the Horner bench's skeleton (interp_horner_bench.h) with no work: a
//                             20 ns clock, a thread waking at every rising edge (the stimulus), a
//                             method at every rising edge reading the pins (the monitor), and a
//                             method at every falling edge writing two changing 32-bit signals (RG
//                             and i_t: the least a Horner unit switches per clock)
#include <cstdint>
#include <memory>
#include <string>
#include <systemc>

#include "arith/specular_arith.h"
#include "perf_cases.h"
#include "perf_floor.h"
#include "perf_harness.h"
#include "ua60553/ua60553.h"

namespace shading::perf {

namespace {

// The specular devices' pins (specular_device.h) and no datapath: out29 follows ctl17.
class null_specular : public sc_core::sc_module {
    using n_t = sc_dt::sc_uint<a_gen_linear::n_fmt.width>;
    using cos_t = sc_dt::sc_uint<spec::cos_fmt.width>;
    using ksi_t = sc_dt::sc_uint<spec::ksi_fmt.width>;
    using out_t = sc_dt::sc_uint<spec::out_fmt.width>;

public:
    sc_core::sc_in<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_in<n_t> in16_n{"in16_n"};
    sc_core::sc_in<cos_t> in18_cos{"in18_cos"};
    sc_core::sc_in<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};
    sc_core::sc_out<out_t> out25_r{"out25_r"}, out26_g{"out26_g"}, out27_b{"out27_b"};
    sc_core::sc_out<bool> out29_valid{"out29_valid"};

    SC_HAS_PROCESS(null_specular);
    explicit null_specular(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(echo);
        sensitive << ctl17;
        dont_initialize();
    }

private:
    void echo() { out29_valid.write(ctl17.read()); }
};

// A clock alone: items are its cycles.
struct clock_floor : sc_core::sc_module, harness {
    sc_core::sc_clock clk;
    explicit clock_floor(const sc_core::sc_module_name& n)
        : sc_module(n),
          clk("clk", sc_core::sc_time(20, sc_core::SC_NS), 0.25, sc_core::sc_time(40, sc_core::SC_NS), true) {}
    sc_core::sc_object& root() override { return *this; }
    uint64_t items() const override {
        const sc_core::sc_time now = sc_core::sc_time_stamp();
        return now < clk.start_time() ? 0 : static_cast<uint64_t>((now - clk.start_time()) / clk.period());
    }
    uint64_t mismatches() const override { return 0; }
    sc_core::sc_time batch() const override { return period() * 1000.0; }
    sc_core::sc_time period() const override { return clk.period(); }
};

// The Horner bench's processes with nothing to do (see the file's comment).
struct horner_floor : sc_core::sc_module, harness {
    using word = sc_dt::sc_uint<32>;
    sc_core::sc_clock clk{"clk", sc_core::sc_time(20, sc_core::SC_NS)};
    sc_core::sc_signal<bool> done{"done"}, busy{"busy"};
    sc_core::sc_signal<word> rg{"rg"}, i_t{"i_t"};

    SC_HAS_PROCESS(horner_floor);
    explicit horner_floor(const sc_core::sc_module_name& n) : sc_module(n) {
        SC_THREAD(stimulus);
        SC_METHOD(monitor);
        sensitive << clk.posedge_event();
        dont_initialize();
        SC_METHOD(unit);
        sensitive << clk.negedge_event();
        dont_initialize();
    }
    sc_core::sc_object& root() override { return *this; }
    uint64_t items() const override { return clocks_; }
    uint64_t mismatches() const override { return 0; }
    sc_core::sc_time batch() const override { return period() * 1000.0; }
    sc_core::sc_time period() const override { return clk.period(); }

private:
    void stimulus() {
        for (;;) {
            wait(clk.posedge_event());
            ++clocks_;
        }
    }
    void monitor() { seen_ += done.read() + busy.read() + rg.read().to_uint64() + i_t.read().to_uint64(); }
    void unit() {
        ++value_;
        rg.write(word(value_));
        i_t.write(word(value_));
    }
    uint64_t clocks_ = 0, seen_ = 0, value_ = 0;
};

}  // namespace

void register_floor_cases() {
    add_sc("floor/sc_clock", "", "clocks", module<clock_floor>());
    add_sc("floor/specular_harness", "golden/ua60553", "evaluations", [] {
        using H = specular_harness<null_specular, a_gen_linear>;
        return std::unique_ptr<harness>(new H("top", [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
            return golden_ua60553(n, c, k, overflow_mode::saturate);
        }));
    }).strict = false;
    add_sc("floor/horner_bench", "", "clocks", module<horner_floor>());
}

}  // namespace shading::perf
