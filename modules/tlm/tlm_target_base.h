// What the TLM-2.0 wrappers (specular_tlm.h, line_tlm.h) share: the timing-mode choice, word
// access to a payload's bytes, the bus-error log with its warning, and the access checks every
// register map starts with (ignore command, byte enables, address, size and alignment). Each
// wrapper adds its own checks (read-only registers, readiness, its windows' contents) after
// check_access().
#pragma once

#include <tlm>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <systemc>

#include "core/report_ids.h"

namespace shading {

// Chosen at construction: the signal-level model driven pin by pin (an access costs its real
// simulated time), or the golden model with the same delay annotated.
enum class tlm_timing { loosely_timed, pin_accurate };

// The bus-error log bits both maps keep in STATUS (a wrapper may add its own above bit 5).
namespace tlm_err {
inline constexpr uint32_t address = 1u << 1, size = 1u << 2, byte_enable = 1u << 3, command = 1u << 4,
                          not_ready = 1u << 5;
}  // namespace tlm_err

// One region of a register map: [begin, end). Registers: accesses of exactly `granule` bytes at
// a granule-aligned address; windows: granule-aligned, a multiple of `granule` bytes, within end.
struct tlm_region {
    uint64_t begin, end;
    unsigned granule;
    bool registers;
    bool contains(uint64_t a) const { return a >= begin && a < end; }
};

class tlm_target_base : public sc_core::sc_module {
protected:
    tlm_target_base(const sc_core::sc_module_name& name, tlm_timing timing) : sc_module(name), timing_(timing) {}

    // Words of a payload's data, host byte order (memcpy: the data pointer has no alignment).
    static uint32_t get32(const unsigned char* d) {
        uint32_t v;
        std::memcpy(&v, d, 4);
        return v;
    }
    static uint16_t get16(const unsigned char* d) {
        uint16_t v;
        std::memcpy(&v, d, 2);
        return v;
    }
    static void put32(unsigned char* d, uint32_t v) { std::memcpy(d, &v, 4); }

    // A debug access's range: [addr, addr + len) non-empty and inside [begin, end). Written so that
    // addr + len cannot wrap: an address near 2^64 would otherwise land in the first region.
    static bool debug_within(uint64_t addr, uint64_t len, uint64_t begin, uint64_t end) {
        return len > 0 && addr >= begin && addr <= end && len <= end - addr;
    }

    static constexpr int access_ignored = -1, access_rejected = -2;

    // The checks every access goes through, in this order: TLM_IGNORE_COMMAND completes OK and
    // does nothing (access_ignored); byte enables, an address in no region, a bad size, alignment
    // or streaming width are rejected (access_rejected). Else: the index of the start's region.
    template <std::size_t N>
    int check_access(tlm::tlm_generic_payload& p, const tlm_region (&map)[N]) {
        const uint64_t addr = p.get_address();
        const uint64_t n = p.get_data_length();
        if (p.get_command() == tlm::TLM_IGNORE_COMMAND) {
            p.set_response_status(tlm::TLM_OK_RESPONSE);
            return access_ignored;
        }
        if (p.get_byte_enable_ptr() != nullptr) {
            reject(p, tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE, tlm_err::byte_enable, "byte enables are not supported");
            return access_rejected;
        }
        int r = 0;
        while (r < static_cast<int>(N) && !map[r].contains(addr)) ++r;
        if (r == static_cast<int>(N)) {
            reject(p, tlm::TLM_ADDRESS_ERROR_RESPONSE, tlm_err::address, "address outside the register map");
            return access_rejected;
        }
        const tlm_region& g = map[r];
        bool ok = p.get_streaming_width() == n && n > 0 && addr % g.granule == 0;
        ok = ok && (g.registers ? n == g.granule : n % g.granule == 0 && addr + n <= g.end);
        if (!ok) {
            reject(p, tlm::TLM_BURST_ERROR_RESPONSE, tlm_err::size,
                   "bad length, alignment or streaming width for this register or window");
            return access_rejected;
        }
        return r;
    }

    // Rejects a bad access: its response status, the error log bit and a shading/tlm warning
    // naming the access. Returns false (a check's result).
    bool reject(tlm::tlm_generic_payload& p, tlm::tlm_response_status s, uint32_t bit, const char* why) {
        errors_ |= bit;
        std::ostringstream os;
        os << name() << ": " << (p.is_write() ? "write" : "read") << " of " << p.get_data_length()
           << " bytes at 0x" << std::hex << p.get_address() << std::dec << ": " << why;
        SC_REPORT_WARNING(msg::tlm, os.str().c_str());
        p.set_response_status(s);
        return false;
    }

    tlm_timing timing_;
    sc_core::sc_mutex lock_;  // pin-accurate mode: one initiator at a time on the pins
    uint32_t errors_ = 0;     // STATUS's sticky bus-error log (the wrapper's, not the model's state)
};

}  // namespace shading
