// What a bench's stimulus streams: either a list fixed in advance (the scene line, the tests'
// hand-picked cases) or items made one at a time by a generator (the random differential mode,
// where 10^7 stimuli must not sit in memory). Plus the random numbers the generators draw.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace shading::tb {

// Items 0..size()-1. A stimulus reads them in order and may read the current one again (the
// interp sources hold the accepted request on their inputs), so a generator is called once per
// index, in increasing order.
template <typename T>
class item_source {
public:
    item_source() = default;
    item_source(std::vector<T> items)  // NOLINT(google-explicit-constructor): a list is a source
        : size_(items.size()), list_(std::make_shared<std::vector<T>>(std::move(items))) {}
    item_source(std::size_t size, std::function<T(std::size_t)> generate)
        : size_(size), generate_(std::move(generate)) {}

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    const T& operator[](std::size_t i) {
        if (list_) return (*list_)[i];
        while (!have_ || last_ < i) {
            last_ = have_ ? last_ + 1 : 0;
            have_ = true;
            current_ = generate_(last_);
        }
        return current_;  // i == last_ (a generator never goes back)
    }
    // The whole list, when there is one (for totals computed before the run).
    const std::vector<T>* list() const { return list_.get(); }

private:
    std::size_t size_ = 0;
    std::shared_ptr<std::vector<T>> list_;
    std::function<T(std::size_t)> generate_;
    T current_{};
    std::size_t last_ = 0;
    bool have_ = false;
};

// A small, fast generator (SplitMix64), seeded per item from (seed, index): item i is the same
// whatever was drawn before it, so a random run is reproduced from --seed alone.
class split_rng {
public:
    split_rng(uint64_t seed, uint64_t index) : s_(seed * 0x9E3779B97F4A7C15ull ^ (index + 0x632BE59BD9B4E019ull)) {
        next();
    }
    uint64_t next() {
        uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // Uniform in [lo, hi] (the bias of a 64-bit modulo is below 2^-40 for these ranges).
    uint64_t range(uint64_t lo, uint64_t hi) { return lo + next() % (hi - lo + 1); }
    bool coin() { return (next() >> 63) != 0; }

private:
    uint64_t s_;
};

// Cuts `total` items into runs of 1..max_len, each length drawn from (seed, run index): the
// random surfaces of the specular benches and the random intervals of the interpolation paper's units. The last
// run is cut short so the runs add up to `total` exactly.
class random_runs {
public:
    random_runs(uint64_t total, uint64_t max_len, uint64_t seed) : max_len_(max_len), seed_(seed ^ 0x5EED0F1E7E57ull) {
        uint64_t sum = 0;
        while (sum < total) sum += drawn(count_++);
        last_ = count_ == 0 ? 0 : drawn(count_ - 1) - (sum - total);
    }
    std::size_t count() const { return count_; }
    std::size_t length(std::size_t i) const { return i + 1 == count_ ? last_ : drawn(i); }

private:
    std::size_t drawn(std::size_t i) const { return split_rng(seed_, i).range(1, max_len_); }
    uint64_t max_len_, seed_;
    std::size_t count_ = 0, last_ = 0;
};

}  // namespace shading::tb
