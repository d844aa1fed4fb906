// What the TLM fuzz target expects of a wrapper, written from the tables of modules/tlm/README.md
// (not from the wrappers' code): per wrapper a shadow of its documented state, the response status
// each access must get, what it changes, and the bytes a read (bus or debug) must return.
//   specular_model<V>  specular_tlm<V>: registers N..CONTROL, COS_BLOCK, RESULT_BLOCK; the results
//                      from the device's golden model (tlm_variant<V>::outputs)
//   line_model<...>    line_tlm<...>: STATUS, CONTROL, INTERVAL_BLOCK, PIXEL_BLOCK; the pixels
//                      from golden_interp_line
#pragma once

#include <tlm>

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "golden/interp_golden.h"
#include "tlm/line_tlm.h"
#include "tlm/specular_tlm.h"

namespace shading::fuzz {

// One access as the initiator built it.
struct access {
    tlm::tlm_command cmd;
    uint64_t addr;
    uint64_t len;              // data length (the buffer holds min(len, its cap) bytes)
    uint64_t streaming_width;
    bool byte_enables;
    const unsigned char* data;  // a write's bytes (len of them, when len is within the cap)
};

// The documented region rules both maps share (README, "Register map" and "Errors").
struct region {
    uint64_t begin, end;
    unsigned granule;
    bool registers;
};

// The documented status of the checks every access starts with; TLM_INCOMPLETE_RESPONSE when they
// pass (the map's own checks decide). `r` gets the start's region.
template <std::size_t N>
tlm::tlm_response_status common_status(const access& a, const region (&map)[N], int& r) {
    if (a.cmd == tlm::TLM_IGNORE_COMMAND) return tlm::TLM_OK_RESPONSE;
    if (a.byte_enables) return tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE;
    for (r = 0; r < static_cast<int>(N); ++r)
        if (a.addr >= map[r].begin && a.addr < map[r].end) break;
    if (r == static_cast<int>(N)) return tlm::TLM_ADDRESS_ERROR_RESPONSE;
    const region& g = map[r];
    const bool shape = a.len > 0 && a.streaming_width == a.len && a.addr % g.granule == 0 &&
                       (g.registers ? a.len == g.granule : a.len % g.granule == 0 && a.len <= g.end - a.addr);
    if (!shape) return tlm::TLM_BURST_ERROR_RESPONSE;
    return tlm::TLM_INCOMPLETE_RESPONSE;
}

// The STATUS log bit of each error response.
inline uint32_t error_bit(tlm::tlm_response_status s) {
    switch (s) {
        case tlm::TLM_ADDRESS_ERROR_RESPONSE: return tlm_err::address;
        case tlm::TLM_BURST_ERROR_RESPONSE: return tlm_err::size;
        case tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE: return tlm_err::byte_enable;
        case tlm::TLM_COMMAND_ERROR_RESPONSE: return tlm_err::command;
        case tlm::TLM_GENERIC_ERROR_RESPONSE: return tlm_err::not_ready;
        default: return 0;
    }
}

inline void put32(std::vector<unsigned char>& v, uint64_t at, uint32_t x) { std::memcpy(v.data() + at, &x, 4); }
inline uint32_t get32(const unsigned char* d) {
    uint32_t x;
    std::memcpy(&x, d, 4);
    return x;
}

// A debug read's documented result: len bytes if [addr, addr + len) lies inside one region, else 0.
template <std::size_t N>
int debug_region(uint64_t addr, uint64_t len, const region (&map)[N]) {
    for (int r = 0; r < static_cast<int>(N); ++r)
        if (addr >= map[r].begin && addr <= map[r].end && len <= map[r].end - addr) return r;
    return -1;
}

template <class V>
struct specular_model {
    using var = tlm_variant<V>;
    static constexpr region map[] = {{0x000, 0x028, 4, true}, {0x1000, 0x1800, 2, false}, {0x2000, 0x6000, 4, false}};
    static constexpr uint32_t control_fixed(bool pin) { return (var::code << 4) | (pin ? 1u << 8 : 0u); }

    bool pin = false;
    typename var::config cfg = var::default_config();
    uint32_t n = 0, cos_reg = 0, errors = 0;
    std::array<uint32_t, 3> ksi{}, rgb{};
    bool ready = false, wrap = false;
    std::array<uint16_t, 1024> cos{};
    std::array<std::array<uint32_t, 4>, 1024> res{};
    std::array<bool, 1024> shaded{};

    std::array<uint32_t, 3> golden(uint32_t code) const {
        const auto o = var::outputs(var::law(n, cfg), code, {ksi[0], ksi[1], ksi[2]},
                                    wrap ? overflow_mode::wrap : overflow_mode::saturate);
        return {static_cast<uint32_t>(o[0]), static_cast<uint32_t>(o[1]), static_cast<uint32_t>(o[2])};
    }
    void invalidate() {
        ready = false;
        shaded.fill(false);
    }

    tlm::tlm_response_status status(const access& a) const {
        int r = -1;
        const auto s = common_status(a, map, r);
        if (s != tlm::TLM_INCOMPLETE_RESPONSE) return s;
        const bool write = a.cmd == tlm::TLM_WRITE_COMMAND;
        const bool read_only = r == 2 || (r == 0 && a.addr >= 0x014 && a.addr <= 0x020);
        if (write && read_only) return tlm::TLM_COMMAND_ERROR_RESPONSE;
        if (!write && r == 0 && a.addr >= 0x014 && a.addr <= 0x01C && !ready) return tlm::TLM_GENERIC_ERROR_RESPONSE;
        if (!write && r == 2)
            for (uint64_t i = (a.addr - 0x2000) / 16; i <= (a.addr + a.len - 1 - 0x2000) / 16; ++i)
                if (!shaded[i]) return tlm::TLM_GENERIC_ERROR_RESPONSE;
        return tlm::TLM_OK_RESPONSE;
    }

    // An OK write's effect.
    void apply_write(const access& a) {
        if (a.addr == 0x1000 || (a.addr > 0x1000 && a.addr < 0x1800)) {
            for (uint64_t k = 0; k < a.len / 2; ++k) {
                const std::size_t i = (a.addr - 0x1000) / 2 + k;
                std::memcpy(&cos[i], a.data + 2 * k, 2);
                const auto o = golden(cos[i]);
                res[i] = {o[0], o[1], o[2], cos[i]};
                shaded[i] = true;
            }
            return;
        }
        const uint32_t v = get32(a.data);
        switch (a.addr) {
            case 0x000: n = v & 0x3FF; invalidate(); break;
            case 0x004: case 0x008: case 0x00C: ksi[(a.addr - 4) / 4] = v & 0xFF; invalidate(); break;
            case 0x010: cos_reg = v & 0xFFFF; rgb = golden(cos_reg); ready = true; break;
            case 0x024:
                if (v & (1u << 31)) errors = 0;
                if (((v & 1u) != 0) != wrap) {
                    wrap = !wrap;
                    invalidate();
                }
                break;
            default: break;
        }
    }

    // The whole map as bytes, per region (what a debug read of it must return).
    std::vector<unsigned char> image(int r) const {
        std::vector<unsigned char> v(map[r].end - map[r].begin);
        if (r == 0) {
            const uint32_t words[10] = {n, ksi[0], ksi[1], ksi[2], cos_reg, rgb[0], rgb[1], rgb[2],
                                        (ready ? 1u : 0u) | errors, (wrap ? 1u : 0u) | control_fixed(pin)};
            for (int i = 0; i < 10; ++i) put32(v, 4 * i, words[i]);
        } else if (r == 1) {
            std::memcpy(v.data(), cos.data(), v.size());
        } else {
            for (std::size_t i = 0; i < 1024; ++i)
                for (int w = 0; w < 4; ++w) put32(v, 16 * i + 4 * w, res[i][w]);
        }
        return v;
    }
};

template <unsigned M, interp::sample_set SET, interp::div3_mode DIV>
struct line_model {
    static constexpr region map[] = {{0x000, 0x008, 4, true}, {0x1000, 0x2000, 16, false}, {0x10000, 0x20000, 4, false}};
    static constexpr uint32_t length_error = 1u << 6;
    static constexpr uint32_t control(bool pin) {
        return M | (SET == interp::sample_set::case2 ? 1u << 4 : 0u) | (DIV == interp::div3_mode::exact ? 1u << 5 : 0u) |
               (pin ? 1u << 8 : 0u) | (3u << 12);
    }

    bool pin = false;
    uint32_t errors = 0;
    bool ready = false;
    std::size_t pixel_count = 0;
    std::vector<unsigned char> intervals = std::vector<unsigned char>(0x1000);
    std::vector<uint32_t> pixels = std::vector<uint32_t>(16384);

    // The status, and for a LEN outside 1..2^M the log bit of that error (length_error).
    tlm::tlm_response_status status(const access& a, uint32_t& bit) const {
        int r = -1;
        const auto s = common_status(a, map, r);
        bit = error_bit(s);
        if (s != tlm::TLM_INCOMPLETE_RESPONSE) return s;
        const bool write = a.cmd == tlm::TLM_WRITE_COMMAND;
        bit = tlm_err::command;
        if (write && (r == 2 || (r == 0 && a.addr == 0x000))) return tlm::TLM_COMMAND_ERROR_RESPONSE;
        bit = tlm_err::not_ready;
        if (!write && r == 2 && (!ready || (a.addr - 0x10000) / 4 + a.len / 4 > pixel_count))
            return tlm::TLM_GENERIC_ERROR_RESPONSE;
        if (write && r == 1)
            for (uint64_t k = 0; k < a.len; k += 16) {
                const uint32_t l = get32(a.data + k + 8);
                bit = length_error;
                if (l == 0 || l > (1u << M)) return tlm::TLM_GENERIC_ERROR_RESPONSE;
            }
        bit = 0;
        return tlm::TLM_OK_RESPONSE;
    }

    void apply_write(const access& a) {
        if (a.addr < 0x008) {
            if (get32(a.data) & (1u << 31)) errors = 0;
            return;
        }
        std::vector<interp::interval_samples> ivs(a.len / 16);
        for (std::size_t k = 0; k < ivs.size(); ++k) {
            unsigned char* slot = intervals.data() + (a.addr - 0x1000) + 16 * k;
            std::memcpy(slot, a.data + 16 * k, 12);
            std::memset(slot + 12, 0, 4);
            for (int s = 0; s < 4; ++s) {
                uint16_t x;
                std::memcpy(&x, a.data + 16 * k + 2 * s, 2);
                ivs[k].i[s] = x;
            }
            ivs[k].len = get32(a.data + 16 * k + 8);
        }
        const auto px = interp::golden_interp_line(ivs, M, SET, DIV);
        for (std::size_t p = 0; p < px.size(); ++p) pixels[p] = static_cast<uint32_t>(px[p]);
        pixel_count = px.size();
        ready = true;
    }

    std::vector<unsigned char> image(int r) const {
        std::vector<unsigned char> v(map[r].end - map[r].begin);
        if (r == 0) {
            put32(v, 0, (ready ? 1u : 0u) | errors | static_cast<uint32_t>(pixel_count << 16));
            put32(v, 4, control(pin));
        } else if (r == 1) {
            v = intervals;
        } else {
            std::memcpy(v.data(), pixels.data(), v.size());
        }
        return v;
    }
};

}  // namespace shading::fuzz
