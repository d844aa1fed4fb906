// Built by scripts/check_package.sh with `c++ -std=c++17 pkgconfig_check.cpp $(pkg-config --cflags
// --libs shading)` against the installed tree: the include root, the generated UA 22802 ROM header,
// the squared-quadratic device's headers, libshading_golden, libshading_floor and (through Requires: systemc)
// libsystemc must all be found.
#include <cstdio>
#include <systemc>

#include "arith/squared_arith.h"     // its functions: libshading_floor
#include "arith/ua22802_arith.h"     // libshading_floor
#include "squared/squared_device.h"  // formats/squared_formats.h, the new blocks and monitors
#include "ua22802/ua22802.h"         // includes the generated ua22802_a_rom.h

int sc_main(int, char*[]) {
    // The installed ROM content (generated from ref::a_exact) against the golden model's ROM word,
    // computed from the formula in plain C++: every address.
    unsigned bad = 0;
    for (uint64_t n = 0; n < shading::ua22802::a_rom_content.size(); ++n)
        bad += shading::ua22802::a_rom_content[n] != shading::golden_a_rom(n);
    // The squared device's squarings against floor(log2 n), counted by hand here: every n >= 1.
    unsigned bad_k = 0;
    for (unsigned n = 1; n < 1024; ++n) {
        unsigned k = 0;
        while ((n >> (k + 1)) != 0) ++k;
        bad_k += shading::golden_squared_a(n).k != k;
    }
    std::printf("pkg-config check: SystemC %s, %zu ROM words, %u differ from golden_a_rom; squared device: "
                "%u of 1023 squaring counts differ from floor(log2 n)\n",
                sc_core::sc_version(), shading::ua22802::a_rom_content.size(), bad, bad_k);
    return bad == 0 && bad_k == 0 && shading::ua22802::a_rom_content.size() == 1024 ? 0 : 1;
}
