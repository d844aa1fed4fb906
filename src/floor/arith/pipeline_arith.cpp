// The sample stage and one interval (pipeline_arith.h): direct integer arithmetic on the codes of
// pipeline_formats.h's table; the interpolation units from interp_arith (the SystemC pipeline must
// match these bit for bit).
#include "arith/pipeline_arith.h"

#include <algorithm>

#include "arith/interp_arith.h"

namespace shading::pipeline {

namespace {
constexpr uint64_t pixel_max = pixel_fmt.mask();  // 0xFFFF
}  // namespace

rgb_codes golden_sample(const scene::device_config& dev, const frame_constants& k, sample_geometry g) {
    const auto spec = scene::device_specular(dev, k.n, g.cos_nh, k.ksi);  // out_fmt Q9.8
    rgb_codes out{};
    for (int c = 0; c < 3; ++c) {
        // k_d*I (Q8.8) x N.L (Q1.15) = Q9.23, diffuse_drop = 15 low wires dropped (floor) -> Q9.8.
        const uint64_t diffuse = (k.kdi[c] * g.cos_nl) >> diffuse_drop;
        const uint64_t sum = k.ambient[c] + diffuse + spec[c];  // Q.8, at most 18 bits: no wrap
        out[c] = std::min(sum, colour_fmt.mask());             // saturated to colour_fmt
    }
    return out;
}

const char* evaluator_name(evaluator e) {
    switch (e) {
        case evaluator::horner: return "horner";
        case evaluator::fd: return "fd";
    }
    return "?";
}

bool interval_valid(const interval_job& job) {
    const bool exact = job.m == 0;
    const bool m_ok = exact || (job.m >= interp::m_min && job.m <= interp::m_max);
    return m_ok && job.len >= 1 && job.len <= (1u << job.m) && !(exact && job.deg2);
}

std::string interval_problem(const interval_job& job) {
    if (interval_valid(job)) return {};
    return "invalid interval at line " + std::to_string(job.y) + ", x " + std::to_string(job.x0) + " (m " +
           std::to_string(job.m) + ", len " + std::to_string(job.len) + (job.deg2 ? ", quadratic" : "") +
           "): m must be 0 (exact pixel, len 1, cubic) or " + std::to_string(interp::m_min) + ".." +
           std::to_string(interp::m_max) + " with len 1..2^m";
}

rgb_codes::value_type golden_output_clamp(uint64_t coef_bits) {
    const int64_t v = code_value(coef_bits, interp::coef_fmt);  // signed Q16.16
    if (v < 0) return 0;
    const uint64_t q8 = static_cast<uint64_t>(v) >> (interp::coef_fmt.frac - pixel_fmt.frac);  // floor
    return std::min(q8, pixel_max);
}

namespace {

// One channel of an interval after the sample stage: the coefficient units' polynomial, every pixel
// evaluated and clamped to pixel_fmt.
void evaluate(const interp::cubic_coefs& coefs, bool deg2, unsigned m, unsigned len, evaluator e, int c,
              std::vector<rgb_codes>& out) {
    if (e == evaluator::horner) {
        for (unsigned p = 0; p < len; ++p) {
            const uint64_t t = static_cast<uint64_t>(p) << (interp::t_fmt.frac - m);  // k / 2^m in Q1.8
            out[p][c] = golden_output_clamp(interp::golden_horner(coefs, t, deg2));
        }
    } else {
        // The FD unit is a cubic evaluator: a quadratic enters as A = 0, B = a, C = b, D = c.
        const interp::cubic_coefs fd = deg2 ? interp::cubic_coefs{0, coefs.a, coefs.b, coefs.c} : coefs;
        const auto bits = interp::golden_fd(fd, m, len);
        for (unsigned p = 0; p < len; ++p) out[p][c] = golden_output_clamp(bits[p]);
    }
}

}  // namespace

std::vector<rgb_codes> interval_pixels(const interval_job& job, const frame_constants& k,
                                       const scene::device_config& dev, evaluator e, interp::sample_set set,
                                       interp::div3_mode div) {
    if (!interval_valid(job)) return {};
    const bool exact = job.m == 0;
    // The sample stage: an exact pixel's sample is evaluated once and fills all four registers.
    std::array<rgb_codes, 4> smp{};
    const unsigned n_samples = exact ? 1 : (job.deg2 ? 3 : 4);
    for (unsigned i = 0; i < n_samples; ++i) smp[i] = golden_sample(dev, k, job.s[i]);
    for (unsigned i = n_samples; i < 4; ++i) smp[i] = smp[n_samples - 1];

    std::vector<rgb_codes> out(job.len);
    for (int c = 0; c < 3; ++c) {
        interp::cubic_coefs coefs;
        if (job.deg2)
            coefs = interp::golden_quad_coefs({smp[0][c], smp[1][c], smp[2][c]});
        else
            coefs = interp::golden_cubic_coefs({smp[0][c], smp[1][c], smp[2][c], smp[3][c]}, set, div,
                                               interp::div3_grouping::whole_sum);
        evaluate(coefs, job.deg2, job.m, job.len, e, c, out);
    }
    return out;
}

std::vector<rgb_codes> quadratic_pixels(const std::array<rgb_codes, 3>& smp, unsigned m, unsigned len, evaluator e) {
    if (m < 1 || m > interp::m_max || len < 1 || len > (1u << m)) return {};
    std::vector<rgb_codes> out(len);
    for (int c = 0; c < 3; ++c)
        evaluate(interp::golden_quad_coefs({smp[0][c], smp[1][c], smp[2][c]}), true, m, len, e, c, out);
    return out;
}

}  // namespace shading::pipeline
