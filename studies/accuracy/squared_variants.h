// The squared-quadratic device (ours; formats/squared_formats.h) with its two design choices made
// parameters, for the study that fixed them (studies/accuracy/README.md, "The fit"). A golden
// model of the variants, plain C++ from the law, not a change to the device: with the device's
// parameters (bend shifts {2}, 18 fraction bits) it gives golden_squared's words bit for bit
// (test_squared_variants checks every n and code).
//   the bend: a = f + sum over s in `bend_shifts` of floor(f (1 - f - 2^-9) / 2^(k + s)) on the
//             device's Q0.12 a bus (each shifted copy is its own 12-wire bus, its low wires left
//             open, then summed), none: a = f;
//   q_frac:   the fraction bits of the q word (ADD11) and of the squaring register, Q1.q_frac;
//             MUL10's product is floored onto it, cos (Q1.15) is aligned onto it, each square is
//             floored back onto it.
// Saturate mode only (the study's measure is in range).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace shading::study {

struct squared_variant {
    std::string id, label;
    std::vector<unsigned> bend_shifts{2};
    unsigned q_frac = 18;
};

// The device, and the variants of the fit: a = f, the bend's shift s = 1, 2, 3, 3/8 as s = {2, 3};
// and the q/square word at 16..20 fraction bits (the device's bend).
squared_variant squared_device_variant();
std::vector<squared_variant> bend_variants();
std::vector<squared_variant> fraction_variants();

// a on the Q0.12 bus, and the number of squarings k, for n (n = 0 read as 1).
uint64_t variant_a(const squared_variant& v, unsigned n);
unsigned variant_k(unsigned n);
// The squaring register after the k-th square, Q1.q_frac, for a Q1.15 cos code.
uint64_t variant_word(const squared_variant& v, unsigned n, uint64_t cos_code);
double variant_value(const squared_variant& v, unsigned n, uint64_t cos_code);
// out25..27 as the device forms them: the word's 16 high wires (Q1.15) times the 8-bit k_s*I.
std::array<uint64_t, 3> variant_out(const squared_variant& v, unsigned n, uint64_t cos_code,
                                    const std::array<uint64_t, 3>& ksi);

}  // namespace shading::study
