// Interpolation error inside a triangle and across its edges (edge_split.h).
#include "edge_split.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace shading::study {

const char* reconstruction_name(reconstruction k) {
    switch (k) {
        case reconstruction::linear: return "linear";
        case reconstruction::quadratic: return "quadratic";
        case reconstruction::cubic: return "cubic";
    }
    return "?";
}

namespace {

// The polynomial through samples s[first .. first + count - 1] (at nodes first .. in units of h),
// evaluated at u (same units).
rgb_levels lagrange(const std::vector<rgb_levels>& s, std::size_t first, std::size_t count, double u) {
    rgb_levels out{0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < count; ++i) {
        double w = 1.0;
        for (std::size_t j = 0; j < count; ++j)
            if (j != i) w *= (u - double(first + j)) / (double(first + i) - double(first + j));
        for (int ch = 0; ch < 3; ++ch) out[ch] += w * s[first + i][ch];
    }
    return out;
}

}  // namespace

std::vector<rgb_levels> reconstruct(const std::vector<rgb_levels>& v, unsigned h, reconstruction k,
                                    std::size_t* points) {
    if (h == 0) throw std::invalid_argument("edge_split: the sample spacing must be at least 1 pixel");
    std::vector<rgb_levels> out = v;  // exact unless rebuilt below
    const std::size_t len = v.size();
    if (len == 0) {
        if (points) *points = 0;
        return out;
    }
    const std::size_t gaps = (len - 1) / h;  // samples at 0, h, .., gaps h
    std::vector<rgb_levels> s;
    for (std::size_t i = 0; i <= gaps; ++i) s.push_back(v[i * h]);
    // Gap g (pixels g h .. g h + h - 1) from samples first .. first + count - 1.
    auto fill = [&](std::size_t g, std::size_t first, std::size_t count) {
        for (unsigned p = 0; p < h; ++p) out[g * h + p] = lagrange(s, first, count, double(g) + double(p) / h);
    };
    for (std::size_t g = 0; g < gaps; ++g) {
        switch (k) {
            case reconstruction::linear: fill(g, g, 2); break;
            case reconstruction::quadratic: {
                const std::size_t pair = g - g % 2;  // the pair of gaps g belongs to
                if (pair + 2 <= gaps)
                    fill(g, pair, 3);
                else if (g >= 1)
                    fill(g, g - 1, 3);  // a last single gap: the sample before it as the third
                else
                    fill(g, g, 2);
                break;
            }
            case reconstruction::cubic: {
                const std::size_t count = std::min<std::size_t>(4, gaps + 1);
                const std::size_t first = std::min(g > 0 ? g - 1 : 0, gaps + 1 - count);
                fill(g, first, count);
                break;
            }
        }
    }
    if (points) *points = (gaps + 1) + (len - 1 - gaps * h);
    return out;
}

std::vector<rgb_levels> reconstruct_ramped(const std::vector<rgb_levels>& v, const std::vector<slope_jump>& jumps,
                                           unsigned h, reconstruction k, std::size_t* points) {
    std::vector<rgb_levels> ramps(v.size(), rgb_levels{0.0, 0.0, 0.0});
    for (std::size_t i = 0; i < v.size(); ++i)
        for (const slope_jump& j : jumps)
            if (double(i) > j.e)
                for (int ch = 0; ch < 3; ++ch) ramps[i][ch] += j.s[ch] * (double(i) - j.e);
    std::vector<rgb_levels> rest = v;
    for (std::size_t i = 0; i < v.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) rest[i][ch] -= ramps[i][ch];
    std::vector<rgb_levels> out = reconstruct(rest, h, k, points);
    for (std::size_t i = 0; i < v.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) out[i][ch] += ramps[i][ch];
    return out;
}

edge_split& edge_split::operator+=(const edge_split& o) {
    pixels_within += o.pixels_within;
    pixels_crossing += o.pixels_crossing;
    pixels_exact += o.pixels_exact;
    points += o.points;
    se_within += o.se_within;
    se_crossing += o.se_crossing;
    pixels_past_vertex += o.pixels_past_vertex;
    se_past_vertex += o.se_past_vertex;
    ref2 += o.ref2;
    return *this;
}

edge_split split_errors(const std::vector<rgb_levels>& v, const std::vector<int32_t>& tri, unsigned h,
                        reconstruction k, const std::vector<uint8_t>& vertex_pass,
                        const std::vector<slope_jump>* jumps) {
    if (tri.size() != v.size()) throw std::invalid_argument("edge_split: one triangle per pixel");
    if (!vertex_pass.empty() && vertex_pass.size() != v.size())
        throw std::invalid_argument("edge_split: one vertex-pass flag per pixel, or none");
    edge_split out;
    const std::vector<rgb_levels> r = jumps ? reconstruct_ramped(v, *jumps, h, k, &out.points)
                                            : reconstruct(v, h, k, &out.points);
    const std::size_t len = v.size();
    const std::size_t gaps = len > 0 ? (len - 1) / h : 0;
    for (std::size_t i = 0; i < len; ++i)
        for (int ch = 0; ch < 3; ++ch) out.ref2 += v[i][ch] * v[i][ch];
    for (std::size_t g = 0; g < gaps; ++g) {
        const auto first = tri.begin() + long(g * h);
        const bool within = std::all_of(first, first + long(h) + 1, [&](int32_t t) { return t == *first; });
        bool past_vertex = false;
        for (std::size_t i = g * h + 1; i <= g * h + h && !vertex_pass.empty(); ++i) past_vertex |= vertex_pass[i] != 0;
        for (std::size_t i = g * h; i < g * h + h; ++i) {
            double e = 0.0;
            for (int ch = 0; ch < 3; ++ch) e += (r[i][ch] - v[i][ch]) * (r[i][ch] - v[i][ch]);
            (within ? out.se_within : out.se_crossing) += e;
            ++(within ? out.pixels_within : out.pixels_crossing);
            if (past_vertex && !within) {
                out.se_past_vertex += e;
                ++out.pixels_past_vertex;
            }
        }
    }
    out.pixels_exact = len - gaps * h;
    return out;
}

namespace {

// The reference's sum of squares over the covered pixels (tri >= 0) of a width x height image.
double covered_ref2(const std::vector<rgb_levels>& colour, const std::vector<int32_t>& tri, unsigned width,
                    unsigned height, const char* who) {
    const std::size_t n = static_cast<std::size_t>(width) * height;
    if (colour.size() != n || tri.size() != n) throw std::invalid_argument(std::string(who) + ": sizes differ");
    double ref2 = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        if (tri[i] >= 0)
            for (int ch = 0; ch < 3; ++ch) ref2 += colour[i][ch] * colour[i][ch];
    return ref2;
}

}  // namespace

midpoint_error midpoint_errors(const std::vector<rgb_levels>& colour, const std::vector<int32_t>& tri, unsigned width,
                               unsigned height, bool across_lines,
                               const std::function<bool(int32_t, int32_t)>& one_patch) {
    midpoint_error out;
    out.ref2 = covered_ref2(colour, tri, width, height, "midpoint_errors");
    const std::size_t step = across_lines ? width : 1;
    for (unsigned y = across_lines ? 1 : 0; y + (across_lines ? 1 : 0) < height; y += across_lines ? 2 : 1)
        for (unsigned x = across_lines ? 0 : 1; x + (across_lines ? 0 : 1) < width; x += across_lines ? 1 : 2) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            const int32_t t = tri[i], a = tri[i - step], b = tri[i + step];
            if (t < 0 || a < 0 || b < 0 || !one_patch(a, t) || !one_patch(t, b)) continue;
            ++out.pixels;
            for (int ch = 0; ch < 3; ++ch) {
                const double e = 0.5 * (colour[i - step][ch] + colour[i + step][ch]) - colour[i][ch];
                out.se += e * e;
            }
        }
    return out;
}

predicted_lines odd_lines_predicted(const std::vector<rgb_levels>& colour, const std::vector<int32_t>& tri,
                                    unsigned width, unsigned height, unsigned h, reconstruction rule,
                                    const std::function<bool(int32_t, int32_t)>& one_patch) {
    predicted_lines out;
    out.ref2 = covered_ref2(colour, tri, width, height, "odd_lines_predicted");
    std::vector<rgb_levels> v, mean;
    auto close_run = [&]() {
        if (v.empty()) return;
        std::vector<rgb_levels> residual = v;
        for (std::size_t i = 0; i < v.size(); ++i)
            for (int ch = 0; ch < 3; ++ch) residual[i][ch] -= mean[i][ch];
        std::size_t points = 0;
        const std::vector<rgb_levels> direct = reconstruct(v, h, rule, &points);
        const std::vector<rgb_levels> rebuilt = reconstruct(residual, h, rule, nullptr);
        for (std::size_t i = 0; i < v.size(); ++i)
            for (int ch = 0; ch < 3; ++ch) {
                const double d = direct[i][ch] - v[i][ch], p = rebuilt[i][ch] + mean[i][ch] - v[i][ch];
                out.se_direct += d * d;
                out.se_predicted += p * p;
            }
        out.pixels += v.size();
        out.points += points;
        v.clear();
        mean.clear();
    };
    for (unsigned y = 1; y + 1 < height; y += 2) {
        for (unsigned x = 0; x < width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            const int32_t t = tri[i], a = tri[i - width], b = tri[i + width];
            const bool ok = t >= 0 && a >= 0 && b >= 0 && one_patch(a, t) && one_patch(t, b);
            if (!ok || (!v.empty() && !one_patch(tri[i - 1], t))) close_run();
            if (!ok) continue;
            v.push_back(colour[i]);
            rgb_levels m;
            for (int ch = 0; ch < 3; ++ch) m[ch] = 0.5 * (colour[i - width][ch] + colour[i + width][ch]);
            mean.push_back(m);
        }
        close_run();
    }
    return out;
}

}  // namespace shading::study
