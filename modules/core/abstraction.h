// The level a unit is modelled at, chosen at construction:
//   block - the figure's blocks wired as the hardware is (registers latching on falling edges,
//           combinational blocks with their propagation delays, a waveform per block);
//   fast  - the same pins and the same timing at the pins (the same handshake, the same clocks per
//           result, every protocol-defined output at the same edges), one process computing the
//           unit's function from the floor (src/floor: the formats and the shared arithmetic), no
//           internal nets and no internal delays. Bit-exact with block, checked in the tests.
#pragma once

#include <string>

namespace shading {

enum class abstraction { block, fast };

inline const char* abstraction_name(abstraction a) { return a == abstraction::fast ? "fast" : "block"; }

// "block" or "fast"; false for anything else.
inline bool parse_abstraction(const std::string& s, abstraction& out) {
    if (s == "block") out = abstraction::block;
    else if (s == "fast") out = abstraction::fast;
    else return false;
    return true;
}

}  // namespace shading
