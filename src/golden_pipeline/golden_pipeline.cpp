// The golden model of the interpolation paper's shading system (pipeline.h): the frame constants of a
// scene, the sample points' codes, one checked interval, a whole frame, and the hardware path's
// operation counts. The sample stage and an interval's arithmetic are the floor's
// (arith/pipeline_arith.cpp), shared with the pipeline's fast model (the SystemC pipeline must match
// them bit for bit).
#include <algorithm>
#include <cmath>

#include "golden_pipeline/pipeline.h"
#include "scene/scene.h"

namespace shading::pipeline {

namespace {

bool same_material(const scene::material& a, const scene::material& b) {
    return a.ambient == b.ambient && a.k_d == b.k_d && a.k_s == b.k_s && a.n == b.n;
}

// An interval the hardware cannot take: a programming error of the plan, reported clearly.
void check_job(const interval_job& job) {
    if (!interval_valid(job)) throw scene::scene_error("golden_interval: " + interval_problem(job));
}

}  // namespace

uint64_t kdi_code(double kd_times_i) {
    const double v = std::round(255.0 * std::clamp(kd_times_i, 0.0, 1.0) * (1u << kdi_fmt.frac));
    return std::min<uint64_t>(static_cast<uint64_t>(v), kdi_fmt.mask());
}

frame_constants frame_constants_of(const scene::world& s) {
    // Zero lights is refused too: the sample stage reads light 0's N.L and N.H.
    if (s.lights.size() != 1)
        throw scene::scene_error("scene '" + s.name + "': the hardware path shades exactly one light, the scene has " +
                                 std::to_string(s.lights.size()));
    if (s.objects.empty()) throw scene::scene_error("scene '" + s.name + "': no objects, so no material to shade");
    const scene::material& m = s.objects.front().mat;
    for (const auto& o : s.objects)
        if (!same_material(o.mat, m))
            throw scene::scene_error("scene '" + s.name + "': the hardware path shades one material, object '" +
                                     o.name + "' differs from object '" + s.objects.front().name + "'");
    const scene::light& l = s.lights.front();
    frame_constants k;
    k.n = m.n;
    for (int c = 0; c < 3; ++c) {
        k.ksi[c] = scene::ksi_code(m.k_s[c] * l.intensity[c]);
        k.kdi[c] = kdi_code(m.k_d[c] * l.intensity[c]);
        // 255 * ambient in Q8.8, rounded to nearest, clamped to the largest code.
        const double a = std::round(255.0 * std::clamp(m.ambient[c], 0.0, 1.0) * (1u << ambient_fmt.frac));
        k.ambient[c] = std::min<uint64_t>(static_cast<uint64_t>(a), ambient_fmt.mask());
    }
    return k;
}

sample_geometry sample_of(const scene::pixel_geometry& g) {
    if (g.l.empty() || g.h.empty()) throw scene::scene_error("sample_of: the pixel's geometry has no light");
    // The same gate as shade.cpp: no diffuse and no highlight unless N.L > 0.
    const double ndl = dot(g.n, g.l[0]).value();
    if (!(ndl > 0.0)) return {};
    const double ndh = dot(g.n, g.h[0]).value();
    sample_geometry s;
    s.cos_nh = scene::cos_code(std::max(ndh, 0.0));
    s.cos_nl = scene::cos_code(ndl);
    return s;
}

std::vector<rgb_codes> golden_interval(const interval_job& job, const frame_constants& k,
                                       const scene::device_config& dev, evaluator e, interp::sample_set set,
                                       interp::div3_mode div) {
    check_job(job);
    return interval_pixels(job, k, dev, e, set, div);
}

frame empty_frame(unsigned w, unsigned h) {
    frame f;
    f.width = w;
    f.height = h;
    const std::size_t n = static_cast<std::size_t>(w) * h;
    f.px.assign(n, rgb_codes{});
    f.covered.assign(n, 0);
    f.degree.assign(n, 0);
    f.log2_len.assign(n, 0);
    f.zone.assign(n, 0);
    return f;
}

frame golden_frame(const plan& p, const frame_constants& k, const scene::device_config& dev, const plan_config& c) {
    frame f = empty_frame(p.width, p.height);
    for (const interval_job& job : p.jobs) {
        if (job.y >= p.height || job.x0 + job.len > p.width)
            throw scene::scene_error("golden_frame: an interval at line " + std::to_string(job.y) + ", x " +
                                     std::to_string(job.x0) + " leaves the " + std::to_string(p.width) + "x" +
                                     std::to_string(p.height) + " frame");
        const auto px = golden_interval(job, k, dev, c.eval, c.set, c.div);
        const uint8_t degree = job.m == 0 ? 1 : (job.deg2 ? 2 : 3);
        for (unsigned i = 0; i < job.len; ++i) {
            const std::size_t at = static_cast<std::size_t>(job.y) * p.width + job.x0 + i;
            f.px[at] = px[i];
            f.covered[at] = 1;
            f.degree[at] = degree;
            f.log2_len[at] = static_cast<uint8_t>(job.m);
            f.zone[at] = job.zone;
        }
    }
    return f;
}

frame per_pixel_frame(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev) {
    // Every pixel exact: degree 1, log2_len 0; zone left 0 (the caller may fill it with head_zone).
    frame f = empty_frame(r.width, r.height);
    for (unsigned y = 0; y < r.height; ++y)
        for (unsigned x = 0; x < r.width; ++x) {
            if (!r.covered(x, y)) continue;
            const std::size_t at = r.index(x, y);
            f.px[at] = golden_sample(dev, k, sample_of(scene::geometry_at(r, x, y, nullptr)));
            f.covered[at] = 1;
            f.degree[at] = 1;
        }
    return f;
}

}  // namespace shading::pipeline

// ---- Operation counts of the hardware path ----
namespace shading::pipeline {

namespace {

// The sample stage per colour sample (one N.H, N.L pair): the specular device's datapath
// (scene::device_sample_ops), then per channel the diffuse multiplier (k_d*I x N.L) and two adders
// (ambient + diffuse + specular).
constexpr scene::op_counts diffuse_per_sample{3, 0, 0, 6, 0};

// The coefficient units per interval and channel, adders of their shift-and-add networks
// (shift_add_network: one adder per term but the first, the subtraction's included):
//   cubic case 1: A 6 terms (5), B 6 (5), C 7 (6); case 2: A 6 (5), B 7 (6), C 8 (7);
//   /3 of A and C: Fig. 2's x/2 - x/8 - x/32 - x/128, 4 terms (3) each, or the exact constant divider
//   (const_div.h), counted as one division each;
//   quadratic: a 3 terms (2), b 4 (3); c = I1 and D = I1 are wiring.
// So a cubic (and an exact pixel, which goes through the cubic unit) costs 16 (case 1) or 18 (case 2)
// network adders plus 6 for the two /3 (or 2 divisions); a quadratic 5 adders.
scene::op_counts cubic_unit_ops(interp::sample_set set, interp::div3_mode div) {
    scene::op_counts c;
    c.add = set == interp::sample_set::case1 ? 5 + 5 + 6 : 5 + 6 + 7;
    if (div == interp::div3_mode::shift_add)
        c.add += 2 * 3;
    else
        c.div += 2;
    return c;
}
constexpr scene::op_counts quad_unit_ops{0, 0, 0, 2 + 3, 0};
// Forward differences' set-up per interval and channel (fd_eval.h): D1 = A/N^3 + B/N^2 + C/N
// (3 terms, 2 adders), D2 = (4A + 2A)/N^3 + 2B/N^2 (3 terms, 2), D3 = (4A + 2A)/N^3 (2 terms, 1);
// P = D is wiring. Per pixel: P += D1, D1 += D2, D2 += D3.
constexpr scene::op_counts fd_setup_ops{0, 0, 0, 5, 0};
constexpr scene::op_counts fd_pixel_ops{0, 0, 0, 3, 0};
// The Horner unit (Fig. 4) per pixel and channel: cubic steps 2..6 are A t + B, x t, + C, x t, + D
// (3 MUL, 3 Sm, 6 clocks); degree 2 stops after + C (2 MUL, 2 Sm, 4 clocks).
constexpr scene::op_counts horner_cubic_ops{3, 0, 0, 3, 0};
constexpr scene::op_counts horner_quad_ops{2, 0, 0, 2, 0};
constexpr unsigned horner_cubic_clocks = 6, horner_quad_clocks = 4, fd_clocks = 1;

using scene::times;

}  // namespace

scene::op_counts colour_sample_ops(const scene::device_config& dev, unsigned n) {
    scene::op_counts ops = scene::device_sample_ops(dev, n);
    ops += diffuse_per_sample;
    return ops;
}

hardware_counts hardware_ops(const plan& p, const plan_config& c) {
    return hardware_ops(p, c, scene::device_config{}, 0);
}

hardware_counts hardware_ops(const plan& p, const plan_config& c, const scene::device_config& dev, unsigned n) {
    const scene::op_counts per_colour = colour_sample_ops(dev, n);
    hardware_counts h;
    h.geometry = c.unit == geometry_unit::stepped ? p.geometry_stepped : p.geometry;
    h.geometry += p.decision;
    // The adaptive policies' check points: colours formed by the sample stage for the decision only
    // (plan.check_samples), charged to the geometry side's decision, not to `samples`.
    h.geometry += times(per_colour, p.check_samples);
    const scene::op_counts cubic_unit = cubic_unit_ops(c.set, c.div);
    const sample_geometry* last = nullptr;  // the codes of the last sample formed or carried
    for (const interval_job& job : p.jobs) {
        const bool exact = job.m == 0;
        const bool quad = job.deg2 && !exact;
        uint64_t samples = exact ? 1 : (quad ? 3 : 4);  // an exact pixel's sample fills all four
        if (c.carry_samples && last && job.s[0] == *last) {
            --samples;
            ++h.carried;
        }
        last = &job.s[exact ? 0 : (quad ? 2 : 3)];
        h.samples += samples;
        h.sample_stage += times(per_colour, samples);
        ++h.intervals;
        h.pixels += job.len;
        // Three channels, each with its own coefficient unit and evaluator.
        h.interpolation += times(quad ? quad_unit_ops : cubic_unit, 3);
        if (c.eval == evaluator::fd) {
            h.interpolation += times(fd_setup_ops, 3);
            h.interpolation += times(fd_pixel_ops, 3ull * job.len);
            h.clocks += static_cast<uint64_t>(fd_clocks) * job.len;
        } else {
            h.interpolation += times(quad ? horner_quad_ops : horner_cubic_ops, 3ull * job.len);
            h.clocks += static_cast<uint64_t>(quad ? horner_quad_clocks : horner_cubic_clocks) * job.len;
        }
    }
    return h;
}

}  // namespace shading::pipeline
