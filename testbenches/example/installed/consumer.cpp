// A consumer of the installed package: binds a specular device's pins to its own nets, shades a few
// pixels through Fig. 3's strobes, reads R, G, B at output 29's rising edge and compares every word
// with the device's golden model. Three platforms in one elaboration: device_ua60553, and
// device_squared and device_sqmul (ours), the same pins plus their stage's clock, which the
// platform's 20 ns clock drives. Built against the installed tree only (CMakeLists.txt here);
// exits 0 only if all of it matched.
#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <systemc>
#include <type_traits>

#include "arith/specular_arith.h"  // shading::floor: golden_ua60553
#include "arith/sqmul_arith.h"     // shading::floor: golden_sqmul
#include "arith/squared_arith.h"   // shading::floor: golden_squared
#include "sqmul/sqmul.h"            // shading::modules
#include "squared/squared.h"        // shading::modules
#include "ua60553/ua60553.h"        // shading::modules

using sc_core::SC_NS;
using sc_core::sc_time;
using golden_fn = std::array<uint64_t, 3> (*)(unsigned n, unsigned cos, const std::array<uint64_t, 3>& ksi);

template <class Device>
struct platform : sc_core::sc_module {
    static constexpr bool squared = std::is_same_v<Device, shading::device_squared>;
    static constexpr bool clocked = squared || std::is_same_v<Device, shading::device_sqmul>;
    static constexpr const char* label = squared ? "squared " : clocked ? "sqmul   " : "UA 60553";

    sc_core::sc_signal<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_signal<sc_dt::sc_uint<10>> n{"n"};
    sc_core::sc_signal<sc_dt::sc_uint<16>> cos{"cos"};  // Q1.15
    sc_core::sc_signal<sc_dt::sc_uint<8>> ks_r{"ks_r"}, ks_g{"ks_g"}, ks_b{"ks_b"};
    sc_core::sc_signal<sc_dt::sc_uint<17>> r{"r"}, g{"g"}, b{"b"};  // Q9.8
    sc_core::sc_signal<bool> valid{"valid"};
    std::unique_ptr<sc_core::sc_clock> clk;  // the clocked devices' only

    Device spec{"spec"};  // saturate mode; UA 60553 with the patent's constants
    golden_fn golden;
    unsigned pixels = 0, errors = 0;
    bool finished = false;

    SC_HAS_PROCESS(platform);
    platform(const sc_core::sc_module_name& name, golden_fn gold) : sc_module(name), golden(gold) {
        if constexpr (clocked) {
            clk = std::make_unique<sc_core::sc_clock>("clk", sc_time(20, SC_NS));
            spec.clk(*clk);
        }
        spec.ctl15(ctl15); spec.in16_n(n);
        spec.ctl17(ctl17); spec.in18_cos(cos);
        spec.ctl20(ctl20); spec.in19_ksi_r(ks_r);
        spec.ctl22(ctl22); spec.in21_ksi_g(ks_g);
        spec.ctl24(ctl24); spec.in23_ksi_b(ks_b);
        spec.out25_r(r); spec.out26_g(g); spec.out27_b(b); spec.out29_valid(valid);
        SC_THREAD(drive);
    }

    // A register latches on the falling edge of its strobe (Fig. 3).
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
        // Three surfaces, six pixels each: cos codes from 1.0 down, and a small LCG's inside the
        // highlight; n = 1000 is the squared device's longest case (9 squarings), 16 clocks of the
        // square-and-multiply device's.
        const std::array<std::array<unsigned, 4>, 3> surfaces{{{40, 255, 200, 90}, {7, 13, 128, 250}, {1000, 180, 180, 180}}};
        uint32_t x = 12345;
        for (const auto& s : surfaces) {
            load(ctl15, n, s[0]);
            load(ctl20, ks_r, s[1]);
            load(ctl22, ks_g, s[2]);
            load(ctl24, ks_b, s[3]);
            for (int i = 0; i < 6; ++i) {
                x = x * 1103515245u + 12345u;
                const unsigned c = i < 3 ? 0x8000u - 0x100u * i : 0x8000u - (x >> 8) % 0x0C00u;  // in the lobe
                cos.write(c);
                wait(2, SC_NS);
                ctl17.write(false);  // latch cos
                wait(15, SC_NS);     // longer than UA 60553's 11.2 ns critical path
                ctl17.write(true);   // output 29 rises with it (UA 60553) or once computed (ours)
                wait(sc_time(500, SC_NS), valid.posedge_event());
                const auto want = golden(s[0], c, {s[1], s[2], s[3]});
                const bool ok = valid.read() && r.read() == want[0] && g.read() == want[1] && b.read() == want[2];
                std::printf("%s n %4u cos 0x%04x -> R %05x G %05x B %05x  golden %05llx %05llx %05llx %s\n",
                            label, s[0], c, unsigned(r.read()), unsigned(g.read()),
                            unsigned(b.read()), (unsigned long long)want[0], (unsigned long long)want[1],
                            (unsigned long long)want[2], ok ? "ok" : "MISMATCH");
                ++pixels;
                errors += !ok;
                wait(2, SC_NS);
            }
        }
        finished = true;
    }
};

int sc_main(int, char*[]) {
    using shading::overflow_mode;
    platform<shading::device_ua60553> top("top", [](unsigned n, unsigned c, const std::array<uint64_t, 3>& k) {
        return shading::golden_ua60553(n, c, k, overflow_mode::saturate).out;
    });
    platform<shading::device_squared> top_sq("top_squared", [](unsigned n, unsigned c, const std::array<uint64_t, 3>& k) {
        return shading::golden_squared(n, c, k, overflow_mode::saturate).out;
    });
    platform<shading::device_sqmul> top_sm("top_sqmul", [](unsigned n, unsigned c, const std::array<uint64_t, 3>& k) {
        return shading::golden_sqmul(n, c, k, overflow_mode::saturate).out;
    });
    sc_core::sc_start(20, sc_core::SC_US);
    const bool finished = top.finished && top_sq.finished && top_sm.finished;
    const auto warnings = sc_core::sc_report_handler::get_count(sc_core::SC_WARNING);
    const unsigned errors = top.errors + top_sq.errors + top_sm.errors;
    std::printf("consumer: %u + %u + %u pixels, %u mismatches, %u warnings, %s\n", top.pixels, top_sq.pixels,
                top_sm.pixels, errors, unsigned(warnings), finished ? "finished" : "NOT FINISHED");
    return (top.pixels == 18 && top_sq.pixels == 18 && top_sm.pixels == 18 && errors == 0 && finished && warnings == 0)
               ? 0
               : 1;
}
