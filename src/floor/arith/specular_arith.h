// The bit-exact function of the specular datapath (UA 60553 / UA 22802, Fig. 1), plain C++: the
// golden models check the SystemC blocks against it, and the fast pin-level models, the TLM
// wrappers' loosely-timed mode and the a-generators' a_word() call it (the floor, docs/layers.md).
// Written directly in integer arithmetic from the format table in specular_formats.h, not from
// the SystemC blocks, so a device-vs-golden comparison checks the wiring and the blocks.
#pragma once

#include <array>
#include <cstdint>

#include "formats/fixed_point.h"
#include "formats/ua60553_formats.h"

namespace shading {

// Every net of the datapath for one cos code, as raw bus bits.
struct datapath_nets {
    uint64_t cos2;   // MUL7
    uint64_t inv8;   // INV8
    uint64_t diff;   // ADD9, two's complement
    uint64_t prod;   // MUL10, two's complement
    uint64_t brdf;   // ADD11
    std::array<uint64_t, 3> out;  // MUL12..14 (R, G, B)
};

// The shared datapath for an `a` bus with `a_frac` fraction bits.
datapath_nets golden_datapath(uint64_t a_bits, int a_frac, uint64_t cos_bits,
                              const std::array<uint64_t, 3>& ksi, overflow_mode mode);

// UA 60553's a = n * K31 + K32 (MUL6, ADD15) on the a_fmt bus.
uint64_t golden_a_linear(uint64_t n_bits, const ua60553::linear_generator& g);

// The whole UA 60553 device.
datapath_nets golden_ua60553(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi,
                             overflow_mode mode, const ua60553::linear_generator& g = ua60553::patent);

}  // namespace shading
