// UA 22802's generator of `a` (the prototype UA 60553 names): RG1 addresses a
// ROM holding a(n) of the quadratic-BRDF paper formula 7, whose word drives MUL10 directly. The
// content is generated at build time by src/tools/gen_a_rom.cpp (ua22802_a_rom.h in the build
// tree; link shading_ua22802); format and rounding in src/floor/formats/ua22802_formats.h. A unit with
// the n -> a interface every specular device binds (specular/specular_device.h).
#pragma once

#include <cstdint>
#include <systemc>
#include <vector>

#include "blocks/rom.h"
#include "formats/ua22802_formats.h"
#include "specular/block_delays.h"
#include "ua22802_a_rom.h"

namespace shading {

class a_gen_rom : public sc_core::sc_module {
public:
    using config = std::vector<uint64_t>;  // the ROM's words, word n = a(n)
    static config default_config() { return {ua22802::a_rom_content.begin(), ua22802::a_rom_content.end()}; }
    static constexpr qfmt n_fmt = ua22802::addr_fmt;
    static constexpr qfmt a_fmt = ua22802::a_fmt;
    static constexpr const char* n_out_of_range =
        "n = 0 reads ROM word 0 = a 0 (q = cos, as for n = 1); n > 1000 reads words 1001..1023, "
        "programmed with the same formula a(n)";

    // For the fast pin-level model (specular/specular_fast.h): the word the ROM reads at n (a blank
    // 0 beyond the table, as blocks/rom.h) and its access time.
    static uint64_t a_word(const config& words, uint64_t n_bits) {
        const uint64_t i = n_bits & n_fmt.mask();
        return i < words.size() ? words[i] : 0;
    }
    static sc_core::sc_time path_delay(const block_delays& t) { return t.rom; }

    sc_core::sc_in<sc_dt::sc_uint<n_fmt.width>> n{"n"};
    sc_core::sc_out<sc_dt::sc_uint<a_fmt.width>> a{"a"};

    shading::rom<n_fmt.width, a_fmt.width> rom;  // n (10.0) -> a (Q10.6), 1024 words

    a_gen_rom(const sc_core::sc_module_name& name, const config& words = default_config(),
              const block_delays& t = {})
        : sc_module(name), rom("rom", words, t.rom) {
        rom.addr(n); rom.data(a);
    }
};

}  // namespace shading
