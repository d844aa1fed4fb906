// Read-only memory block: 2^AW words of DW bits, combinational read (an asynchronous PROM).
// The content is a table given at elaboration (for UA 22802 a table generated at build time).
// Every address change re-reads the word, which appears after the access time (inertial, as
// comb_delay.h). An address at or beyond the table's length selects no programmed word and reads
// `blank` (default 0: an unprogrammed word of a PROM whose cells read 0); a word of the table
// wider than DW is a configuration error (shading/config), reported at elaboration.
#pragma once

#include <cstdint>
#include <sstream>
#include <systemc>
#include <vector>

#include "core/comb_delay.h"
#include "core/report_ids.h"
#include "core/timed_block.h"

namespace shading {

namespace delay_default {
// Access time of a 1K x 16 PROM. Chosen equal to MUL6 + ADD15 (multiplier + adder), so UA 22802
// and UA 60553 have the same RG1 -> a path and run with the same strobe timing.
inline const sc_core::sc_time rom_access{4000, sc_core::SC_PS};
}  // namespace delay_default

template <unsigned AW, unsigned DW>
class rom : public sc_core::sc_module, public timed_block {
    static_assert(AW >= 1 && AW <= 20 && DW >= 1 && DW <= 64, "address and data widths");

public:
    static constexpr std::size_t words = std::size_t{1} << AW;
    static constexpr unsigned bits = static_cast<unsigned>(words) * DW;  // storage, for the cost table

    sc_core::sc_in<sc_dt::sc_uint<AW>> addr{"addr"};
    sc_core::sc_out<sc_dt::sc_uint<DW>> data{"data"};

    SC_HAS_PROCESS(rom);
    rom(const sc_core::sc_module_name& name, std::vector<uint64_t> content,
        const sc_core::sc_time& access = delay_default::rom_access, uint64_t blank = 0)
        : sc_module(name), content_(std::move(content)), blank_(blank), drv_(data, access) {
        const uint64_t mask = DW >= 64 ? ~0ull : ((1ull << DW) - 1);
        std::ostringstream os;
        if (content_.size() > words)
            os << name << ": " << content_.size() << " words for a " << words << "-word ROM; ";
        for (std::size_t i = 0; i < content_.size(); ++i)
            if (content_[i] & ~mask) {
                os << name << ": word " << i << " = 0x" << std::hex << content_[i] << std::dec
                   << " is wider than " << DW << " bits";
                break;
            }
        if (!os.str().empty()) SC_REPORT_ERROR(msg::config, os.str().c_str());
        SC_METHOD(read);
        sensitive << addr;
    }

    const sc_core::sc_time& delay() const override { return drv_.delay(); }
    uint64_t word(uint64_t a) const { return a < content_.size() ? content_[a] : blank_; }

private:
    void read() { drv_.drive(sc_dt::sc_uint<DW>(word(addr.read().to_uint64()))); }

    std::vector<uint64_t> content_;
    uint64_t blank_;
    inertial_driver<sc_dt::sc_uint<DW>> drv_;
};

}  // namespace shading
