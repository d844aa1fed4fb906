// A double that counts the arithmetic done on it: the references' operation counts come from the
// code that computes, never from hand-entered constants. Each value carries a pointer to the
// op_counts it charges (the caller's, so no global state); constants enter with cnum(x, &ops).
#pragma once

#include <cmath>
#include <cstdint>
#include <ostream>

namespace shading::scene {

struct op_counts {
    uint64_t mul = 0;   // multiplications
    uint64_t div = 0;   // divisions
    uint64_t sqrt = 0;  // square roots
    uint64_t add = 0;   // additions and subtractions
    uint64_t cmp = 0;   // comparisons (max/clamp), reported apart, not "long" operations
    // Of the divisions and square roots above, the pairs that form one reciprocal length 1/sqrt(x)
    // (normalize): a reciprocal square root unit performs each pair as one long operation.
    uint64_t rsqrt = 0;
    // The long operations the paper's speed claim is about, in the textbook convention (a square
    // root and a division per normalisation) and with a reciprocal square root as one operation.
    uint64_t long_ops() const { return mul + div + sqrt; }
    uint64_t long_ops_rsqrt() const { return long_ops() - rsqrt; }
    op_counts& operator+=(const op_counts& o) {
        mul += o.mul;
        div += o.div;
        sqrt += o.sqrt;
        add += o.add;
        cmp += o.cmp;
        rsqrt += o.rsqrt;
        return *this;
    }
    bool operator==(const op_counts& o) const {
        return mul == o.mul && div == o.div && sqrt == o.sqrt && add == o.add && cmp == o.cmp && rsqrt == o.rsqrt;
    }
};

// k times the same operations (k samples, k pixels).
inline op_counts times(op_counts c, uint64_t k) {
    c.mul *= k;
    c.div *= k;
    c.sqrt *= k;
    c.add *= k;
    c.cmp *= k;
    c.rsqrt *= k;
    return c;
}

inline std::ostream& operator<<(std::ostream& os, const op_counts& c) {
    return os << "mul " << c.mul << ", div " << c.div << ", sqrt " << c.sqrt << ", add " << c.add
              << ", cmp " << c.cmp << ", of which 1/sqrt pairs " << c.rsqrt;
}

class cnum {
public:
    cnum() = default;
    cnum(double v, op_counts* c) : v_(v), c_(c) {}
    double value() const { return v_; }
    op_counts* counts() const { return c_; }

    friend cnum operator+(cnum a, cnum b) { return a.charge(b, &op_counts::add, a.v_ + b.v_); }
    friend cnum operator-(cnum a, cnum b) { return a.charge(b, &op_counts::add, a.v_ - b.v_); }
    friend cnum operator*(cnum a, cnum b) { return a.charge(b, &op_counts::mul, a.v_ * b.v_); }
    friend cnum operator/(cnum a, cnum b) { return a.charge(b, &op_counts::div, a.v_ / b.v_); }
    friend cnum operator-(cnum a) { return {-a.v_, a.c_}; }  // a sign flip: free in hardware
    cnum& operator+=(cnum b) { return *this = *this + b; }
    cnum& operator*=(cnum b) { return *this = *this * b; }
    friend cnum sqrt(cnum a) {
        if (a.c_) ++a.c_->sqrt;
        return {std::sqrt(a.v_), a.c_};
    }
    friend cnum max(cnum a, cnum b) { return a.charge(b, &op_counts::cmp, a.v_ > b.v_ ? a.v_ : b.v_); }
    friend bool operator>(cnum a, cnum b) {
        a.charge(b, &op_counts::cmp, 0.0);
        return a.v_ > b.v_;
    }

private:
    cnum charge(cnum b, uint64_t op_counts::*field, double result) const {
        op_counts* c = c_ ? c_ : b.c_;
        if (c) ++(c->*field);
        return {result, c};
    }
    double v_ = 0.0;
    op_counts* c_ = nullptr;
};

// A vector of counted numbers, with the operations the references use.
struct cvec3 {
    cnum x, y, z;
    friend cvec3 operator+(const cvec3& a, const cvec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
    friend cvec3 operator-(const cvec3& a, const cvec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
    friend cvec3 operator*(cnum s, const cvec3& a) { return {s * a.x, s * a.y, s * a.z}; }
};
inline cnum dot(const cvec3& a, const cvec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
// One square root, one division (the reciprocal length: one 1/sqrt pair) and three multiplications.
inline cvec3 normalize(const cvec3& a) {
    cnum one(1.0, a.x.counts());
    if (op_counts* c = a.x.counts()) ++c->rsqrt;
    return (one / sqrt(dot(a, a))) * a;
}

}  // namespace shading::scene
