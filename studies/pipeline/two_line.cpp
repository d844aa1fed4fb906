// The planner's adaptive policy emulated on any signal, and the two-line scheme over a frame (two_line.h).
#include "two_line.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "line_kinks.h"

namespace shading::study {

namespace {

// The polynomial through v at pixels x0 + nodes[i], evaluated at x0 + p.
template <std::size_t K>
rgb_levels through(const std::vector<rgb_levels>& v, std::size_t x0, const std::array<unsigned, K>& nodes, double p) {
    rgb_levels out{0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < K; ++i) {
        double w = 1.0;
        for (std::size_t j = 0; j < K; ++j)
            if (j != i) w *= (p - double(nodes[j])) / (double(nodes[i]) - double(nodes[j]));
        for (int ch = 0; ch < 3; ++ch) out[ch] += w * v[x0 + nodes[i]][ch];
    }
    return out;
}

double largest_miss(const rgb_levels& a, const rgb_levels& b) {
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

}  // namespace

emulated_run emulate_adaptive(const std::vector<rgb_levels>& v, const adaptive_emulation& e, const uint8_t* above) {
    const unsigned m_min = e.m_min, m_max = e.m_max;
    if (m_min < 2 || m_max < m_min || m_max > 16)
        throw std::invalid_argument("emulate_adaptive: needs 2 <= m_min <= m_max <= 16");
    emulated_run r;
    r.out = v;
    r.level.assign(v.size(), 0);
    r.point.assign(v.size(), 0);
    auto touch = [&](std::size_t x) {
        r.points += !r.point[x];
        r.point[x] = 1;
    };
    // The line-above limit (plan.cpp, within_above): every pixel of the candidate at most K levels
    // below the line before's level there.
    auto within_above = [&](std::size_t pos, unsigned m) {
        if (e.above_slack < 0 || !above) return true;
        for (std::size_t x = pos; x < pos + (std::size_t{1} << m); ++x)
            if (above[x] != no_level && unsigned(above[x]) + unsigned(e.above_slack) < m) return false;
        return true;
    };
    const std::size_t len = v.size();
    std::size_t pos = 0;
    unsigned grow = m_max;
    while (len > 0 && len - 1 - pos >= (std::size_t{1} << m_min)) {
        const std::size_t room = len - 1 - pos;
        unsigned top = m_min;
        while (top < grow && (std::size_t{1} << (top + 1)) <= room) ++top;
        bool sent = false;
        for (unsigned m = top; !sent && m >= m_min; --m) {
            if (m > m_min && !within_above(pos, m)) continue;
            const unsigned n = 1u << m;
            const std::array<unsigned, 4> cubic{0, n / 4, n / 2, n};
            for (unsigned t : cubic) touch(pos + t);
            // What the interval sends: split at the check point, the halves' quadratics (2^m_min: the cubic).
            auto sends = [&](unsigned p) {
                if (m == m_min) return through(v, pos, cubic, double(p));
                const unsigned h = n / 2, half = p / h;
                return through(v, pos + half * h, std::array<unsigned, 3>{0, h / 2, h}, double(p - half * h));
            };
            bool ok = false;
            if (e.perfect) {
                // The planner's perfect decisions: every estimate and the check point paid, the decision
                // taken on the true RMS of what is sent (levels, the three channels).
                touch(pos + 3 * n / 4);
                double se = 0.0;
                for (unsigned p = 0; p < n; ++p) {
                    const rgb_levels o = sends(p);
                    for (int ch = 0; ch < 3; ++ch) se += (o[ch] - v[pos + p][ch]) * (o[ch] - v[pos + p][ch]);
                }
                ok = std::sqrt(se / (3.0 * n)) <= e.tol;
            } else {
                ok = largest_miss(through(v, pos, std::array<unsigned, 3>{0, n / 2, n}, n / 4), v[pos + n / 4]) <=
                     2.0 * e.tol;
                if (ok) {
                    touch(pos + 3 * n / 4);
                    ok = largest_miss(through(v, pos, cubic, 3 * n / 4), v[pos + 3 * n / 4]) <= e.tol;
                }
            }
            if (ok) {
                for (unsigned p = 0; p < n; ++p) r.out[pos + p] = sends(p);
                std::fill_n(r.level.begin() + std::ptrdiff_t(pos), n, uint8_t(m > m_min ? m - 1 : m));
                pos += n;
                grow = std::min(m + 1, m_max);
                sent = true;
            }
            if (m == m_min) break;
        }
        if (!sent) {
            for (unsigned p = 0; p < (1u << m_min); ++p) touch(pos + p);
            pos += 1u << m_min;
            grow = std::min(m_min + 1, m_max);
        }
    }
    for (std::size_t x = pos; x < len; ++x) touch(x);
    return r;
}

emulated_frame emulate_lines(const scene::rasterised& r, const std::vector<rgb_levels>& colour,
                             const pipeline::plan_config& cfg, const std::vector<double>& tols, bool first_exact,
                             bool perfect) {
    if (colour.size() != r.tri.size()) throw std::invalid_argument("emulate_lines: colours and raster differ in size");
    if (tols.empty() || tols.size() > 5) throw std::invalid_argument("emulate_lines: needs 1 to 5 tolerances, one a pass");
    const unsigned passes = unsigned(tols.size()), top = 1u << (passes - 1);
    emulated_frame f;
    f.out = colour;
    f.point.assign(colour.size(), 0);
    for (std::size_t i = 0; i < colour.size(); ++i)
        if (r.tri[i] >= 0)
            for (int ch = 0; ch < 3; ++ch) f.ref2 += colour[i][ch] * colour[i][ch];
    // The line before's levels in each pass, and this line's as it is rendered.
    std::vector<std::vector<uint8_t>> before(passes);
    std::vector<uint8_t> now(r.width, no_level);
    // One run [x0, x1] of line y, predicted by `mean` (null: the colour itself).
    auto run = [&](unsigned y, bool first, unsigned x0, unsigned x1, double tol, const std::vector<rgb_levels>* mean,
                   const std::vector<uint8_t>& above) {
        std::vector<rgb_levels> v(colour.begin() + r.index(x0, y), colour.begin() + r.index(x1, y) + 1);
        if (mean)
            for (unsigned x = x0; x <= x1; ++x)
                for (int ch = 0; ch < 3; ++ch) v[x - x0][ch] -= (*mean)[x][ch];
        adaptive_emulation e;
        e.tol = tol;
        e.m_min = cfg.m_min;
        e.m_max = cfg.m_max;
        e.above_slack = cfg.above_slack;
        e.perfect = perfect;
        const emulated_run er = emulate_adaptive(v, e, above.empty() ? nullptr : above.data() + x0);
        for (unsigned x = x0; x <= x1; ++x) {
            rgb_levels& o = f.out[r.index(x, y)];
            o = er.out[x - x0];
            if (mean)
                for (int ch = 0; ch < 3; ++ch) o[ch] += (*mean)[x][ch];
            for (int ch = 0; ch < 3; ++ch) {
                const double d = o[ch] - colour[r.index(x, y)][ch];
                (first ? f.se_first : f.se_rest) += d * d;
            }
            now[x] = er.level[x - x0];
            f.point[r.index(x, y)] = er.point[x - x0];
        }
        (first ? f.points_first : f.points_rest) += er.points;
        (first ? f.pixels_first : f.pixels_rest) += x1 - x0 + 1;
        f.pixels_predicted += mean ? x1 - x0 + 1 : 0;
    };
    // Line y of pass `pass`, predicted from the lines d above and below (d = 0: from its colours).
    auto line = [&](unsigned y, unsigned pass, unsigned d) {
        f.lines.push_back(y);
        std::vector<rgb_levels> mean;
        std::vector<uint8_t> on_patch(r.width, 0);
        if (d > 0) {
            mean.assign(r.width, rgb_levels{0.0, 0.0, 0.0});
            for (unsigned x = 0; x < r.width; ++x) {
                const int32_t t = r.tri[r.index(x, y)], a = r.tri[r.index(x, y - d)], b = r.tri[r.index(x, y + d)];
                on_patch[x] = t >= 0 && a >= 0 && b >= 0 && one_patch(r, a, t) && one_patch(r, t, b);
                for (int ch = 0; ch < 3; ++ch)
                    mean[x][ch] = 0.5 * (f.out[r.index(x, y - d)][ch] + f.out[r.index(x, y + d)][ch]);
            }
        }
        now.assign(r.width, no_level);
        for (const auto& s : pipeline::line_segments(r, y, cfg, nullptr)) {
            unsigned x0 = s[0];
            for (unsigned x = s[0] + 1; x <= s[1] + 1; ++x)
                if (x == s[1] + 1 || on_patch[x] != on_patch[x0]) {
                    run(y, pass == 0, x0, x - 1, tols[pass], on_patch[x0] ? &mean : nullptr, before[pass]);
                    x0 = x;
                }
        }
        before[pass] = now;  // this line's levels are the line above of the pass's next line
    };
    for (unsigned y = 0; y < r.height; y += top) {
        if (!first_exact) {
            line(y, 0, 0);
            continue;
        }
        f.lines.push_back(y);
        for (unsigned x = 0; x < r.width; ++x) {
            const bool covered = r.tri[r.index(x, y)] >= 0;
            f.point[r.index(x, y)] = covered;
            f.points_first += covered;
            f.pixels_first += covered;
        }
    }
    for (unsigned pass = 1; pass < passes; ++pass) {
        const unsigned d = top >> pass;
        for (unsigned y = d; y < r.height; y += 2 * d) line(y, pass, y + d < r.height ? d : 0);
    }
    return f;
}

std::vector<std::array<unsigned, 2>> points_in_order(const emulated_frame& f, unsigned width) {
    std::vector<std::array<unsigned, 2>> out;
    for (unsigned y : f.lines) {
        if (std::size_t(y + 1) * width > f.point.size())
            throw std::invalid_argument("points_in_order: line " + std::to_string(y) + " is outside the frame's points");
        for (unsigned x = 0; x < width; ++x)
            if (f.point[std::size_t(y) * width + x]) out.push_back({x, y});
    }
    return out;
}

emulated_cost emulated_long_ops(const scene::rasterised& r, const emulated_frame& f, const scene::device_config& dev,
                                unsigned n, bool walk_edges) {
    if (f.point.size() != r.tri.size()) throw std::invalid_argument("emulated_long_ops: the frame and raster differ in size");
    return points_cost(r, points_in_order(f, r.width), dev, n, walk_edges);
}

emulated_cost points_cost(const scene::rasterised& r, const std::vector<std::array<unsigned, 2>>& points,
                          const scene::device_config& dev, unsigned n, bool walk_edges,
                          const std::vector<uint8_t>& down) {
    const pipeline::stepped_count g = pipeline::stepped_geometry(r, points, walk_edges, down);
    emulated_cost c;
    c.geometry = g.ops;
    c.stepping = g.stats;
    c.colours = scene::times(pipeline::colour_sample_ops(dev, n), points.size());
    return c;
}

}  // namespace shading::study
