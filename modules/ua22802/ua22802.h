// UA 22802, the prototype UA 60553 names (SPEC section 4): the shared specular datapath with RG1
// addressing a ROM that holds a(n) (seed 001, formula 7) instead of MUL6/ADD15. The ROM content
// is generated at build time by src/tools/gen_a_rom.cpp (header ua22802_a_rom.h in the build tree);
// format and rounding in src/ua22802_formats.h.
#pragma once

#include <systemc>
#include <vector>

#include "formats/ua22802_formats.h"
#include "blocks/rom.h"
#include "specular/specular_datapath.h"
#include "ua22802_a_rom.h"

namespace shading {

class device_ua22802
    : public specular_datapath<ua22802::addr_fmt.width, ua22802::a_fmt.width, ua22802::a_fmt.frac> {
public:
    shading::rom<ua22802::addr_fmt.width, ua22802::a_fmt.width> rom;  // n (10.0) -> a (Q10.6), 1024 words

    device_ua22802(const sc_core::sc_module_name& name, overflow_mode mode = overflow_mode::saturate,
                   const block_delays& t = {},
                   const sc_core::sc_time& rom_access = delay_default::rom_access)
        : specular_datapath(name, mode, t, ua60553::n_min, ua60553::n_max,
                            "n = 0 reads ROM word 0 = a 0 (q = cos, as for n = 1); n > 1000 reads "
                            "words 1001..1023, programmed with the same formula a(n)"),
          rom("rom", std::vector<uint64_t>(ua22802::a_rom_content.begin(), ua22802::a_rom_content.end()),
              rom_access) {
        rom.addr(rg1_n); rom.data(a_coef);
    }
};

}  // namespace shading
