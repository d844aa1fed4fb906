// What every fuzz target shares: a check that aborts (libFuzzer then saves the input as a crash;
// the replay driver exits non-zero, so its ctest entry fails), and a reader of the fuzz input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#define FUZZ_CHECK(cond, ...)                                                    \
    do {                                                                         \
        if (!(cond)) {                                                           \
            std::fprintf(stderr, "fuzz check failed at %s:%d: %s: ", __FILE__,   \
                         __LINE__, #cond);                                       \
            std::fprintf(stderr, __VA_ARGS__);                                   \
            std::fprintf(stderr, "\n");                                          \
            std::abort();                                                        \
        }                                                                        \
    } while (0)

namespace shading::fuzz {

// Takes bytes off the front of the input; past its end every read gives 0 (a short input is still
// a valid sequence of operations, only a shorter one).
class input {
public:
    input(const uint8_t* d, std::size_t n) : d_(d), n_(n) {}
    bool empty() const { return at_ >= n_; }
    std::size_t left() const { return at_ < n_ ? n_ - at_ : 0; }
    uint8_t u8() { return at_ < n_ ? d_[at_++] : 0; }
    uint16_t u16() { return static_cast<uint16_t>(u8() | (u8() << 8)); }
    uint32_t u32() { return static_cast<uint32_t>(u16()) | (static_cast<uint32_t>(u16()) << 16); }
    uint64_t u64() { return static_cast<uint64_t>(u32()) | (static_cast<uint64_t>(u32()) << 32); }
    // Up to `max` bytes as a string, its length from one byte.
    std::string str(std::size_t max) {
        std::size_t len = u8() % (max + 1);
        std::string s;
        while (len-- > 0 && !empty()) s.push_back(static_cast<char>(u8()));
        return s;
    }

private:
    const uint8_t* d_;
    std::size_t n_, at_ = 0;
};

}  // namespace shading::fuzz
