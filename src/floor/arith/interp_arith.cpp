#include "arith/interp_arith.h"

namespace shading::interp {

namespace {

int64_t floor_div(int64_t a, int64_t b) {  // b > 0
    const int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

// Value of a coef_fmt bus.
int64_t coef_value(uint64_t bits) { return code_value(bits, coef_fmt); }
uint64_t coef_bits(int64_t v) { return wrap_bits(v, coef_fmt.width); }

// Horner MUL: Q16.16 x Q1.8 -> Q17.24, 8 low wires dropped (floor), kept on the coef_fmt bus.
uint64_t horner_mul(uint64_t x_bits, uint64_t t_code) {
    const __int128 p = static_cast<__int128>(coef_value(x_bits)) * static_cast<__int128>(t_code);
    return coef_bits(floor_shift(p, horner_mul_drop));
}
// Horner Sm: Q16.16 + Q16.16 -> Q16.16, two's-complement wrap.
uint64_t horner_add(uint64_t a_bits, uint64_t b_bits) {
    return coef_bits(coef_value(a_bits) + coef_value(b_bits));
}

// A term v * 2^sh of the forward-difference set-up on a `frac`-bit bus: shifted up exactly, or
// shifted down with its low wires dropped (floor).
int64_t aligned(int64_t v, int sh) {
    return sh >= 0 ? static_cast<int64_t>(static_cast<uint64_t>(v) << sh) : floor_shift(v, static_cast<unsigned>(-sh));
}
// code_value(wrap_bits(v, 56), fd_fmt) without a branch on the sign (the recurrence's hot loop):
// the bus's top wire moved to bit 63, then shifted back arithmetically.
int64_t fd_wrap(int64_t v) {
    static_assert(fd_fmt.is_signed && fd_fmt.width < 64);
    constexpr unsigned up = 64 - fd_fmt.width;
    return static_cast<int64_t>(static_cast<uint64_t>(v) << up) >> up;
}

// The set-up values of the forward differences, codes with `frac` fraction bits.
struct fd_setup {
    int64_t p = 0, d1 = 0, d2 = 0, d3 = 0;
};
fd_setup fd_setup_values(const cubic_coefs& k, unsigned m, int frac) {
    const int s = frac - coef_fmt.frac;  // alignment of a Q.16 code onto the FD bus
    const int sm = static_cast<int>(m);
    fd_setup r;
    r.p = aligned(k.d, s);
    // D3 = 6 A / N^3 = (4A + 2A) / N^3; D2 = 6 A / N^3 + 2 B / N^2; D1 = A/N^3 + B/N^2 + C/N.
    r.d3 = fd_wrap(aligned(k.a, s - 3 * sm + 2) + aligned(k.a, s - 3 * sm + 1));
    r.d2 = fd_wrap(aligned(k.a, s - 3 * sm + 2) + aligned(k.a, s - 3 * sm + 1) + aligned(k.b, s - 2 * sm + 1));
    r.d1 = fd_wrap(aligned(k.a, s - 3 * sm) + aligned(k.b, s - 2 * sm) + aligned(k.c, s - sm));
    return r;
}

}  // namespace

int64_t golden_div3(int64_t x_q8, div3_mode mode) {
    if (mode == div3_mode::exact) return floor_div(x_q8 * (1 << div3_shift), 3);
    // x/2 - x/8 - x/32 - x/128 aligned to Q.16: x<<7 - x<<5 - x<<3 - x<<1 = 86 x (exact).
    return x_q8 * 128 - x_q8 * 32 - x_q8 * 8 - x_q8 * 2;
}

cubic_coefs golden_cubic_coefs(const std::array<uint64_t, 4>& in, sample_set set, div3_mode mode,
                               div3_grouping grouping) {
    const int64_t i1 = static_cast<int64_t>(in[0] & sample_fmt.mask());
    const int64_t i2 = static_cast<int64_t>(in[1] & sample_fmt.mask());
    const int64_t i3 = static_cast<int64_t>(in[2] & sample_fmt.mask());
    const int64_t i4 = static_cast<int64_t>(in[3] & sample_fmt.mask());
    int64_t a8 = 0, b = 0, c3 = 0;  // 8*(-S_A), B, -S_C: Q.8 codes
    if (set == sample_set::case1) {
        a8 = -24 * i1 + 64 * i2 - 48 * i3 + 8 * i4;  // A = -8(3I1 - 8I2 + 6I3 - I4)/3
        b = 14 * i1 - 32 * i2 + 20 * i3 - 2 * i4;    // B = 2(7I1 - 16I2 + 10I3 - I4)
        c3 = -21 * i1 + 32 * i2 - 12 * i3 + i4;      // C = -(21I1 - 32I2 + 12I3 - I4)/3
    } else {
        a8 = -8 * i1 + 48 * i2 - 64 * i3 + 24 * i4;  // A = -8(I1 - 6I2 + 8I3 - 3I4)/3
        b = 6 * i1 - 28 * i2 + 32 * i3 - 10 * i4;    // B = 2(3I1 - 14I2 + 16I3 - 5I4)
        c3 = -13 * i1 + 36 * i2 - 32 * i3 + 9 * i4;  // C = -(13I1 - 36I2 + 32I3 - 9I4)/3
    }
    cubic_coefs k;
    k.b = b * (1 << div3_shift);
    k.d = i1 * (1 << div3_shift);
    if (grouping == div3_grouping::whole_sum) {
        k.a = golden_div3(a8, mode);
        k.c = golden_div3(c3, mode);
        return k;
    }
    // The interpolation paper's grouping: only the part whose weights are not multiples of 3 goes through /3, the
    // integer part is added on the Q.16 bus.
    const int64_t q16 = int64_t{1} << div3_shift;
    if (set == sample_set::case1) {
        k.a = golden_div3(64 * i2 + 8 * i4, mode) - (8 * i1 + 16 * i3) * q16;  // 8(8I2+I4)/3 - 8(I1+2I3)
        k.c = golden_div3(32 * i2 + i4, mode) - (7 * i1 + 4 * i3) * q16;       // (32I2+I4)/3 - 7I1 - 4I3
    } else {
        k.a = (16 * i2 + 8 * i4) * q16 - golden_div3(8 * i1 + 64 * i3, mode);   // 8(2I2+I4) - 8(I1+8I3)/3
        k.c = (12 * i2 + 3 * i4) * q16 - golden_div3(13 * i1 + 32 * i3, mode);  // 3(4I2+I4) - (13I1+32I3)/3
    }
    return k;
}

cubic_coefs golden_quad_coefs(const std::array<uint64_t, 3>& in) {
    const int64_t i1 = static_cast<int64_t>(in[0] & sample_fmt.mask());
    const int64_t i2 = static_cast<int64_t>(in[1] & sample_fmt.mask());
    const int64_t i3 = static_cast<int64_t>(in[2] & sample_fmt.mask());
    cubic_coefs k;
    k.a = (2 * i1 - 4 * i2 + 2 * i3) * (1 << div3_shift);
    k.b = (-3 * i1 + 4 * i2 - i3) * (1 << div3_shift);
    k.c = i1 * (1 << div3_shift);
    return k;
}

// The micro-steps written into rg[0..5]; returns how many (6 cubic, 4 quadratic). One sequence for
// golden_horner_steps (golden/interp_golden.cpp) and golden_horner, which needs no allocation per pixel.
std::size_t golden_horner_into(const cubic_coefs& k, uint64_t t_code, bool degree2, uint64_t* rg) {
    const uint64_t t = t_code & t_fmt.mask();
    rg[0] = coef_bits(k.b);                                  // 1: RG <- B
    rg[1] = horner_add(horner_mul(coef_bits(k.a), t), rg[0]);  // 2: A t + B
    rg[2] = horner_mul(rg[1], t);                            // 3: (A t + B) t
    rg[3] = horner_add(coef_bits(k.c), rg[2]);               // 4: + C
    if (degree2) return 4;
    rg[4] = horner_mul(rg[3], t);                            // 5: * t
    rg[5] = horner_add(coef_bits(k.d), rg[4]);               // 6: + D
    return 6;
}

namespace {
// The recurrence: out[i] = P truncated to coef_fmt bus bits, then P += D1, D1 += D2, D2 += D3.
template <class T>
void fd_run(const cubic_coefs& k, unsigned m, unsigned len, int frac, T* out) {
    fd_setup r = fd_setup_values(k, m, frac);
    const unsigned drop = static_cast<unsigned>(frac - coef_fmt.frac);
    for (unsigned i = 0; i < len; ++i) {
        out[i] = static_cast<T>(coef_bits(r.p >> drop));  // floor_shift on 64 bits: drop < 56
        r.p = fd_wrap(r.p + r.d1);
        r.d1 = fd_wrap(r.d1 + r.d2);
        r.d2 = fd_wrap(r.d2 + r.d3);
    }
}
}  // namespace

std::vector<uint64_t> golden_fd(const cubic_coefs& k, unsigned m, unsigned len, int frac) {
    std::vector<uint64_t> out(len);
    fd_run(k, m, len, frac, out.data());
    return out;
}

void golden_fd_to(const cubic_coefs& k, unsigned m, unsigned len, uint32_t* out, int frac) {
    static_assert(coef_fmt.width == 32, "golden_fd_to's uint32_t outputs hold coef_fmt codes");
    fd_run(k, m, len, frac, out);
}

std::vector<uint64_t> golden_interp_line(const std::vector<interval_samples>& intervals, unsigned m,
                                         sample_set set, div3_mode mode, div3_grouping grouping) {
    const unsigned n = 1u << m;
    const auto len_of = [n](const interval_samples& iv) { return (iv.len == 0 || iv.len > n) ? n : iv.len; };
    std::size_t total = 0;
    for (const auto& iv : intervals) total += len_of(iv);
    std::vector<uint64_t> out(total);
    std::size_t at = 0;
    for (const auto& iv : intervals) {
        fd_run(golden_cubic_coefs(iv.i, set, mode, grouping), m, len_of(iv), fd_fmt.frac, out.data() + at);
        at += len_of(iv);
    }
    return out;
}

}  // namespace shading::interp
