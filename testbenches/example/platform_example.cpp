// How to drop UA 60553 into your own SystemC platform: your top owns the nets, binds the device's
// pins by name, drives Fig. 3's strobes and reads the outputs at the rising edge of out29.
// The squared-quadratic device (ours) is the one-line swap plus its clock:
//     shading::device_squared spec{"spec"};  sc_core::sc_clock clk{"clk", 20, SC_NS};  spec.clk(clk);
// (`platform_example squared` runs this file so; `platform_example sqmul` likewise with the
// square-and-multiply device, shading::device_sqmul). Built and run by ctest (example.platform,
// example.platform.squared, example.platform.sqmul), so this file stays true; the README quotes it.
#include <array>
#include <cstdio>
#include <cstring>
#include <systemc>
#include <type_traits>

#include "arith/specular_arith.h"  // the bit-accurate golden models, to check what we read
#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "sqmul/sqmul.h"            // shading::device_sqmul (link shading_modules)
#include "squared/squared.h"        // shading::device_squared (link shading_modules)
#include "ua60553/ua60553.h"        // shading::device_ua60553 (link shading_modules)

using sc_core::SC_NS;

template <class Device>
struct my_platform : sc_core::sc_module {
    static constexpr bool squared = std::is_same_v<Device, shading::device_squared>;
    static constexpr bool sqmul = std::is_same_v<Device, shading::device_sqmul>;
    // Nets of the platform, one per device pin.
    sc_core::sc_signal<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_signal<sc_dt::sc_uint<10>> n{"n"};
    sc_core::sc_signal<sc_dt::sc_uint<16>> cos{"cos"};  // Q1.15, 0x8000 = 1.0
    sc_core::sc_signal<sc_dt::sc_uint<8>> ks_r{"ks_r"}, ks_g{"ks_g"}, ks_b{"ks_b"};
    sc_core::sc_signal<sc_dt::sc_uint<17>> r{"r"}, g{"g"}, b{"b"};  // Q9.8
    sc_core::sc_signal<bool> valid{"valid"};
    sc_core::sc_clock clk{"clk", 20, SC_NS};  // the clocked devices' stage (UA 60553 has no clock)

    Device spec{"spec"};  // saturate mode, default delays (UA 60553: the patent's constants)
    unsigned errors = 0;

    SC_HAS_PROCESS(my_platform);
    explicit my_platform(const sc_core::sc_module_name& name) : sc_module(name) {
        if constexpr (squared || sqmul) spec.clk(clk);
        spec.ctl15(ctl15); spec.in16_n(n);
        spec.ctl17(ctl17); spec.in18_cos(cos);
        spec.ctl20(ctl20); spec.in19_ksi_r(ks_r);
        spec.ctl22(ctl22); spec.in21_ksi_g(ks_g);
        spec.ctl24(ctl24); spec.in23_ksi_b(ks_b);
        spec.out25_r(r); spec.out26_g(g); spec.out27_b(b); spec.out29_valid(valid);
        SC_THREAD(drive);
    }

    // Registers latch on the falling edge of their strobe (Fig. 3).
    template <typename T>
    void load(sc_core::sc_signal<bool>& ctl, sc_core::sc_signal<T>& data, unsigned v) {
        data.write(v);
        ctl.write(true);
        wait(5, SC_NS);
        ctl.write(false);
        wait(5, SC_NS);
    }

    void drive() {
        ctl17.write(true);
        load(ctl15, n, 40);    // per surface: the exponent ...
        load(ctl20, ks_r, 255);  // ... and k_s*I per channel
        load(ctl22, ks_g, 200);
        load(ctl24, ks_b, 90);
        for (unsigned c : {0x8000u, 0x7F00u, 0x7E00u}) {  // per pixel: cos on in18, then ctl17
            cos.write(c);
            wait(2, SC_NS);
            ctl17.write(false);  // latch
            wait(15, SC_NS);     // longer than UA 60553's 11.2 ns critical path
            ctl17.write(true);
            wait(valid.posedge_event());  // out29 rises (with ctl17, or once computed): r, g, b are valid
            const std::array<uint64_t, 3> k{255, 200, 90};
            constexpr auto sat = shading::overflow_mode::saturate;
            const auto want = squared ? shading::golden_squared(40, c, k, sat).out
                              : sqmul ? shading::golden_sqmul(40, c, k, sat).out
                                      : shading::golden_ua60553(40, c, k, sat).out;
            std::printf("cos %.4f -> R %.3f G %.3f B %.3f\n", c / 32768.0, r.read() / 256.0, g.read() / 256.0,
                        b.read() / 256.0);
            errors += (r.read() != want[0]) + (g.read() != want[1]) + (b.read() != want[2]);
            wait(3, SC_NS);
        }
        sc_core::sc_stop();
    }
};

template <class Device>
int run() {
    my_platform<Device> top("top");
    sc_core::sc_start(1, sc_core::SC_US);
    const bool stopped = sc_core::sc_get_status() == sc_core::SC_STOPPED;
    return (top.errors == 0 && stopped && sc_core::sc_report_handler::get_count(sc_core::SC_WARNING) == 0) ? 0 : 1;
}

int sc_main(int argc, char* argv[]) {
    if (argc == 1) return run<shading::device_ua60553>();
    if (argc == 2 && !std::strcmp(argv[1], "squared")) return run<shading::device_squared>();
    if (argc == 2 && !std::strcmp(argv[1], "sqmul")) return run<shading::device_sqmul>();
    std::fprintf(stderr, "usage: %s [squared|sqmul]\n", argv[0]);  // bad usage: exit 2, as every program here
    return 2;
}
