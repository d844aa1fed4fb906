// The specular devices as the typed test suites see them, written once: the generator of `a` and
// the signal-level device, the device's golden model (outputs 25..27 for n, cos, KSI) and its a(n).
// test_specular_devices extends them with its per-device bounds and checks; test_specular_fast
// (the UA 60553 family's fast pin-level model) uses them as they are.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "arith/specular_arith.h"
#include "arith/squared_arith.h"
#include "arith/ua22802_arith.h"
#include "arith/ua60553_tuned_arith.h"
#include "squared/squared_device.h"
#include "tuned/ua60553_tuned.h"
#include "ua22802/ua22802.h"
#include "ua60553/ua60553.h"

namespace shading::tb {

using rgb_ksi = std::array<uint64_t, 3>;

// UA 60553: a = 0.789 n + 0.5 from the patent's constants.
struct ua60553_device {
    using gen = a_gen_linear;
    using device = device_ua60553;
    static constexpr const char* name = "UA60553";
    static datapath_nets golden(uint64_t n, uint64_t c, const rgb_ksi& k, overflow_mode m) {
        return golden_ua60553(n, c, k, m);
    }
    static uint64_t a(unsigned n) { return golden_a_linear(n, ua60553::patent); }
};

// UA 22802: a(n) read from the ROM generated from the quadratic-BRDF paper's formula.
struct ua22802_device {
    using gen = a_gen_rom;
    using device = device_ua22802;
    static constexpr const char* name = "UA22802";
    static datapath_nets golden(uint64_t n, uint64_t c, const rgb_ksi& k, overflow_mode m) {
        return golden_ua22802(n, c, k, m);
    }
    static uint64_t a(unsigned n) { return golden_a_rom(n); }
};

// UA 60553's network with minimax constants (ours).
struct tuned_device {
    using gen = a_gen_tuned;
    using device = device_ua60553_tuned;
    static constexpr const char* name = "Tuned";
    static datapath_nets golden(uint64_t n, uint64_t c, const rgb_ksi& k, overflow_mode m) {
        return golden_ua60553_tuned(n, c, k, m);
    }
    static uint64_t a(unsigned n) { return golden_a_tuned(n, ua60553::minimax); }
};

// The squared-quadratic device (ours): its golden model gives the outputs only.
struct squared_device_traits {
    using device = squared_device;
    static constexpr const char* name = "Squared";
    static datapath_nets golden(uint64_t n, uint64_t c, const rgb_ksi& k, overflow_mode m) {
        datapath_nets r{};
        r.out = golden_squared(n, c, k, m).out;
        return r;
    }
    static uint64_t a(unsigned n) { return golden_squared_a(n).a; }
};

// gtest's name generator for a typed suite over these (T::name).
struct device_names {
    template <typename T>
    static std::string GetName(int) {
        return T::name;
    }
};

}  // namespace shading::tb
