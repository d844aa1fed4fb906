// Message ids of this project's SystemC reports. Tests and testbenches filter on them.
#pragma once

namespace shading::msg {
inline constexpr const char* setup = "shading/setup";        // data changed at a latching edge
inline constexpr const char* input = "shading/input";        // input outside its documented range
inline constexpr const char* timing = "shading/timing";      // strobe phase shorter than a path
inline constexpr const char* mismatch = "shading/mismatch";  // DUT differs from the golden model
inline constexpr const char* config = "shading/config";      // bad elaboration-time parameter
inline constexpr const char* tlm = "shading/tlm";            // bad TLM-2.0 access to a wrapper
inline constexpr const char* trace = "shading/trace";        // VCD writer: unopenable file, untraceable type
}  // namespace shading::msg
