// A consumer of the installed package: binds device_ua60553's pins to its own nets, shades a few
// pixels through Fig. 3's strobes and compares every R, G, B word with the golden model.
// Built against the installed tree only (CMakeLists.txt here); exits 0 only if all of it matched.
#include <array>
#include <cstdint>
#include <cstdio>
#include <systemc>

#include "golden/specular_golden.h"  // shading::golden
#include "ua60553/ua60553.h"          // shading::modules

using sc_core::SC_NS;

struct platform : sc_core::sc_module {
    sc_core::sc_signal<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_signal<sc_dt::sc_uint<10>> n{"n"};
    sc_core::sc_signal<sc_dt::sc_uint<16>> cos{"cos"};  // Q1.15
    sc_core::sc_signal<sc_dt::sc_uint<8>> ks_r{"ks_r"}, ks_g{"ks_g"}, ks_b{"ks_b"};
    sc_core::sc_signal<sc_dt::sc_uint<17>> r{"r"}, g{"g"}, b{"b"};  // Q9.8
    sc_core::sc_signal<bool> valid{"valid"};

    shading::device_ua60553 spec{"spec"};  // saturate mode, the patent's constants
    unsigned pixels = 0, errors = 0;

    SC_HAS_PROCESS(platform);
    explicit platform(const sc_core::sc_module_name& name) : sc_module(name) {
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
        // Two surfaces, six pixels each: cos codes from 1.0 down, and a small LCG's inside the highlight.
        const std::array<std::array<unsigned, 4>, 2> surfaces{{{40, 255, 200, 90}, {7, 13, 128, 250}}};
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
                wait(15, SC_NS);     // longer than the 11.2 ns critical path
                ctl17.write(true);   // out29 (ctl17 through a wire) rises: R, G, B valid
                wait(1, SC_NS, valid.posedge_event());
                const auto want = shading::golden_ua60553(s[0], c, {s[1], s[2], s[3]}, shading::overflow_mode::saturate);
                const bool ok = valid.read() && r.read() == want.out[0] && g.read() == want.out[1] &&
                                b.read() == want.out[2];
                std::printf("n %3u cos 0x%04x -> R %05x G %05x B %05x  golden %05llx %05llx %05llx %s\n", s[0], c,
                            unsigned(r.read()), unsigned(g.read()), unsigned(b.read()),
                            (unsigned long long)want.out[0], (unsigned long long)want.out[1],
                            (unsigned long long)want.out[2], ok ? "ok" : "MISMATCH");
                ++pixels;
                errors += !ok;
                wait(2, SC_NS);
            }
        }
        sc_core::sc_stop();
    }
};

int sc_main(int, char*[]) {
    platform top("top");
    sc_core::sc_start(2, sc_core::SC_US);
    const bool stopped = sc_core::sc_get_status() == sc_core::SC_STOPPED;
    const auto warnings = sc_core::sc_report_handler::get_count(sc_core::SC_WARNING);
    std::printf("consumer: %u pixels, %u mismatches, %u warnings, %s\n", top.pixels, top.errors, unsigned(warnings),
                stopped ? "stopped" : "NOT STOPPED");
    return (top.pixels == 12 && top.errors == 0 && stopped && warnings == 0) ? 0 : 1;
}
