// The quadtree of biquadratic cells decided from its lattices' differences (cell_tree.h).
#include "cell_tree.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "line_kinks.h"

namespace shading::study {

namespace {

double largest(const rgb_levels& v) { return std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])}); }

// The quadratic through 0, h, 2h at t: its three Lagrange weights.
std::array<double, 3> quadratic_weights(double t, double h) {
    return {(t - h) * (t - 2.0 * h) / (2.0 * h * h), -t * (t - 2.0 * h) / (h * h), t * (t - h) / (2.0 * h * h)};
}

bool power_of_two(unsigned v) { return v != 0 && (v & (v - 1)) == 0; }

// Raster order: line by line, left to right.
bool raster_before(const std::array<unsigned, 2>& a, const std::array<unsigned, 2>& b) {
    return a[1] != b[1] ? a[1] < b[1] : a[0] < b[0];
}

}  // namespace

double lattice_second_difference(const std::vector<rgb_levels>& colour, unsigned width, unsigned x0, unsigned y0,
                                 unsigned s) {
    const unsigned h = s / 2;
    auto at = [&](unsigned i, unsigned j) -> const rgb_levels& {
        return colour[std::size_t(y0 + i * h) * width + x0 + j * h];
    };
    double d = 0.0;
    for (unsigned k = 0; k < 3; ++k)
        for (int ch = 0; ch < 3; ++ch) {
            d = std::max(d, std::abs(at(k, 0)[ch] - 2.0 * at(k, 1)[ch] + at(k, 2)[ch]));  // along row k
            d = std::max(d, std::abs(at(0, k)[ch] - 2.0 * at(1, k)[ch] + at(2, k)[ch]));  // down column k
        }
    return d;
}

double family_third_difference(const std::vector<rgb_levels>& colour, unsigned width, unsigned x0, unsigned y0,
                               unsigned s, unsigned px, unsigned py) {
    const unsigned h = s / 2;
    auto at = [&](unsigned i, unsigned j) -> const rgb_levels& {
        return colour[std::size_t(py + i * h) * width + px + j * h];
    };
    // The child's lattice lines are family lines ci..ci + 2 (rows ri..ri + 2); four points along each,
    // reaching into the sibling beside (below) it.
    const unsigned ci = (x0 - px) / h, ri = (y0 - py) / h;
    const unsigned c0 = ci == 0 ? 0 : 1, r0 = ri == 0 ? 0 : 1;
    double d = 0.0;
    for (int ch = 0; ch < 3; ++ch) {
        for (unsigned k = ri; k < ri + 3; ++k)
            d = std::max(d, std::abs(at(k, c0 + 3)[ch] - 3.0 * at(k, c0 + 2)[ch] + 3.0 * at(k, c0 + 1)[ch] - at(k, c0)[ch]));
        for (unsigned k = ci; k < ci + 3; ++k)
            d = std::max(d, std::abs(at(r0 + 3, k)[ch] - 3.0 * at(r0 + 2, k)[ch] + 3.0 * at(r0 + 1, k)[ch] - at(r0, k)[ch]));
    }
    return d * k3;
}

namespace {

using pixel = std::array<unsigned, 2>;

// A cell waiting for its decision at one level.
struct pending_cell {
    unsigned x0, y0, s;
    bool family;  // its parent was whole: the family lattice over (px, py) was read
    unsigned px, py;
};

// emulate_cells' state over one frame: the raster's segments and patches, the frame being delivered,
// the pixels delivered so far and the reads waiting for the next flush. Reads are batched: a level's
// points are read together, in raster order across the band, before any cell of the level decides
// (a geometry unit steps along each line through them).
class cell_emulator {
public:
    cell_emulator(const scene::rasterised& r, const std::vector<rgb_levels>& colour, const pipeline::plan_config& cfg,
                  const cell_tree_config& t)
        : r_(r), colour_(colour), t_(t), W(r.width), H(r.height), seg_(r.tri.size(), -1), down_(r.tri.size(), 0),
          done_(colour.size(), 0) {
        mark_segments(cfg);
        f_.out = colour;
        f_.point.assign(colour.size(), 0);
        unsigned levels = 0;
        for (unsigned s = t.s_min; s <= t.s_max; s *= 2) ++levels;
        f_.sent.assign(levels, 0);
    }

    // Band by band (s_max lines and the lattice row below them), level by level.
    void cells() {
        for (unsigned by = 0; by < H; by += t_.s_max) {
            std::vector<pending_cell> level = band_cells(by);
            for (unsigned s = t_.s_max; !level.empty(); s /= 2) level = decide_level(level, s);
        }
        for (std::size_t i = 0; i < done_.size(); ++i) f_.pixels_cells += done_[i];
    }

    // What no cell delivered: down the columns where a pixel's column run is long enough against its
    // row run, the rest along the rows, each run sent by the emulated line policy.
    void lines() {
        const std::size_t before_lines = f_.order.size();
        std::vector<std::size_t> row_run(colour_.size(), 0), col_run(colour_.size(), 0);
        auto left = [&](unsigned x, unsigned y) { return covered(x, y) && !done_[idx(x, y)]; };
        runs(false, left, [&](const std::vector<pixel>& px) {
            for (const auto& p : px) row_run[idx(p[0], p[1])] = px.size();
        });
        runs(true, left, [&](const std::vector<pixel>& px) {
            for (const auto& p : px) col_run[idx(p[0], p[1])] = px.size();
        });
        adaptive_emulation line;
        line.tol = t_.line_tol;
        line.m_max = t_.line_m_max;
        line.above_slack = -1;
        line.perfect = t_.perfect;
        std::vector<uint8_t> by_column(colour_.size(), 0);
        for (std::size_t i = 0; i < colour_.size(); ++i)
            by_column[i] = r_.tri[i] >= 0 && !done_[i] && col_run[i] >= 5 &&
                           double(col_run[i]) >= t_.column_ratio * double(row_run[i]);
        runs(true, [&](unsigned x, unsigned y) { return by_column[idx(x, y)] != 0; }, [&](const std::vector<pixel>& px) {
            f_.pixels_columns += px.size();
            send_run(px, line);
        });
        runs(false, left, [&](const std::vector<pixel>& px) {
            f_.pixels_rows += px.size();
            send_run(px, line);
        });
        f_.points_lines = f_.order.size() - before_lines;
    }

    // Every point read is delivered as read (the sample stage formed its colour); then the error.
    cell_frame finish() {
        for (std::size_t i = 0; i < colour_.size(); ++i)
            if (f_.point[i]) f_.out[i] = colour_[i];
        for (std::size_t i = 0; i < colour_.size(); ++i) {
            if (r_.tri[i] < 0) continue;
            ++f_.pixels;
            for (int ch = 0; ch < 3; ++ch) {
                const double d = f_.out[i][ch] - colour_[i][ch];
                f_.se += d * d;
                f_.ref2 += colour_[i][ch] * colour_[i][ch];
            }
        }
        return std::move(f_);
    }

private:
    std::size_t idx(unsigned x, unsigned y) const { return std::size_t(y) * W + x; }
    bool covered(unsigned x, unsigned y) const { return r_.tri[idx(x, y)] >= 0; }

    // Each covered pixel's segment (a running number over the frame) and whether it is one patch
    // with the pixel below.
    void mark_segments(const pipeline::plan_config& cfg) {
        int32_t next = 0;
        for (unsigned y = 0; y < H; ++y)
            for (const auto& s : pipeline::line_segments(r_, y, cfg, nullptr)) {
                for (unsigned x = s[0]; x <= s[1]; ++x) seg_[idx(x, y)] = next;
                ++next;
            }
        for (unsigned y = 0; y + 1 < H; ++y)
            for (unsigned x = 0; x < W; ++x) {
                const int32_t a = r_.tri[idx(x, y)], b = r_.tri[idx(x, y + 1)];
                down_[idx(x, y)] = a >= 0 && b >= 0 && one_patch(r_, a, b);
            }
    }

    // The cell at (x0, y0) of s pixels lies in the frame, each of its rows in one segment, each pixel
    // one patch with the one below.
    bool whole(unsigned x0, unsigned y0, unsigned s) const {
        if (x0 + s >= W || y0 + s >= H) return false;
        for (unsigned y = y0; y <= y0 + s; ++y)
            for (unsigned x = x0; x <= x0 + s; ++x) {
                if (seg_[idx(x, y)] < 0 || seg_[idx(x, y)] != seg_[idx(x0, y)]) return false;
                if (y < y0 + s && !down_[idx(x, y)]) return false;
            }
        return true;
    }

    void read(unsigned x, unsigned y) {
        if (covered(x, y) && !f_.point[idx(x, y)]) {
            f_.point[idx(x, y)] = 1;
            f_.order.push_back({x, y});
        }
    }
    void want(unsigned x, unsigned y) { batch_.push_back({x, y}); }
    void flush() {
        std::sort(batch_.begin(), batch_.end(), raster_before);
        for (const auto& p : batch_) read(p[0], p[1]);
        batch_.clear();
    }

    double rms(const std::vector<rgb_levels>& p, unsigned x0, unsigned y0, unsigned s) const {
        double e = 0.0;
        for (unsigned y = 0; y < s; ++y)
            for (unsigned x = 0; x < s; ++x)
                for (int ch = 0; ch < 3; ++ch) {
                    const double d = p[std::size_t(y) * s + x][ch] - colour_[idx(x0 + x, y0 + y)][ch];
                    e += d * d;
                }
        return std::sqrt(e / (3.0 * s * s));
    }
    void deliver(const std::vector<rgb_levels>& p, unsigned x0, unsigned y0, unsigned s) {
        for (unsigned y = 0; y < s; ++y)
            for (unsigned x = 0; x < s; ++x) {
                f_.out[idx(x0 + x, y0 + y)] = p[std::size_t(y) * s + x];
                done_[idx(x0 + x, y0 + y)] = 1;
            }
    }

    // The biquadratic through the lattice of the cell at (x0, y0) of s pixels.
    std::vector<rgb_levels> biquadratic(unsigned x0, unsigned y0, unsigned s) const {
        const unsigned h = s / 2;
        std::vector<rgb_levels> p(std::size_t(s) * s, rgb_levels{0.0, 0.0, 0.0});
        for (unsigned y = 0; y < s; ++y) {
            const auto wy = quadratic_weights(y, h);
            for (unsigned x = 0; x < s; ++x) {
                const auto wx = quadratic_weights(x, h);
                rgb_levels& o = p[std::size_t(y) * s + x];
                for (unsigned i = 0; i < 3; ++i)
                    for (unsigned j = 0; j < 3; ++j)
                        for (int ch = 0; ch < 3; ++ch) o[ch] += wy[i] * wx[j] * colour_[idx(x0 + j * h, y0 + i * h)][ch];
            }
        }
        return p;
    }

    // The largest cells of the band at by that cover a pixel.
    std::vector<pending_cell> band_cells(unsigned by) const {
        std::vector<pending_cell> level;
        for (unsigned x0 = 0; x0 < W; x0 += t_.s_max) {
            bool any = false;
            for (unsigned y = by; y < std::min(H, by + t_.s_max) && !any; ++y)
                for (unsigned x = x0; x < std::min(W, x0 + t_.s_max) && !any; ++x) any = covered(x, y);
            if (any) level.push_back({x0, by, t_.s_max, false, 0, 0});
        }
        return level;
    }

    // Whether the biquadratic p of whole cell e of s pixels is sent: its true error (perfect), or
    // its lattice's second differences and its family's third differences.
    bool cell_fits(const std::vector<rgb_levels>& p, const pending_cell& e, unsigned s) const {
        return t_.perfect ? rms(p, e.x0, e.y0, s) <= t_.tol
                          : lattice_second_difference(colour_, W, e.x0, e.y0, s) <= t_.d2_factor * t_.tol &&
                                (!e.family || family_third_difference(colour_, W, e.x0, e.y0, s, e.px, e.py) <=
                                                  t_.d3_factor * t_.tol);
    }

    // One level of cells of s pixels decided: a whole cell that fits is sent; the rest split into
    // their four children (the next level), or at s_min fall back to rows.
    std::vector<pending_cell> decide_level(const std::vector<pending_cell>& level, unsigned s) {
        const unsigned h = s / 2;
        std::vector<uint8_t> is_whole(level.size());
        for (std::size_t c = 0; c < level.size(); ++c) {
            is_whole[c] = whole(level[c].x0, level[c].y0, s);
            if (is_whole[c] && !level[c].family)  // with a family its lattice was read with it
                for (unsigned y = level[c].y0; y <= level[c].y0 + s; y += h)
                    for (unsigned x = level[c].x0; x <= level[c].x0 + s; x += h) want(x, y);
        }
        flush();
        std::vector<pending_cell> next, fallback;
        for (std::size_t c = 0; c < level.size(); ++c) {
            const pending_cell& e = level[c];
            if (is_whole[c]) {
                const std::vector<rgb_levels> p = biquadratic(e.x0, e.y0, s);
                if (cell_fits(p, e, s)) {
                    deliver(p, e.x0, e.y0, s);
                    unsigned k = 0;
                    while ((t_.s_min << k) < s) ++k;
                    ++f_.sent[k];
                    continue;
                }
                if (s == t_.s_min) {
                    fallback.push_back(e);
                    continue;
                }
                // The children's lattices, their family, read before any of them decides.
                for (unsigned y = e.y0; y <= e.y0 + s; y += h / 2)
                    for (unsigned x = e.x0; x <= e.x0 + s; x += h / 2) want(x, y);
            }
            if (s > t_.s_min)
                for (unsigned dy : {0u, h})
                    for (unsigned dx : {0u, h}) next.push_back({e.x0 + dx, e.y0 + dy, h, bool(is_whole[c]), e.x0, e.y0});
        }
        flush();
        if (!fallback.empty()) fall_back(fallback);
        return next;
    }

    // The smallest cells turned down: every row read at 0, 2, 4 and sent as the quadratic through
    // them, checked at (1, 1), then (3, 3); where a check misses, the pixels exact.
    void fall_back(const std::vector<pending_cell>& fallback) {
        const unsigned m = t_.s_min;
        for (const pending_cell& e : fallback)
            for (unsigned y = e.y0; y < e.y0 + m; ++y)
                for (unsigned x = e.x0; x <= e.x0 + m; x += 2) want(x, y);
        flush();
        std::vector<std::vector<rgb_levels>> q(fallback.size());
        std::vector<uint8_t> rows_ok(fallback.size(), 1);
        for (std::size_t c = 0; c < fallback.size(); ++c) {
            q[c] = row_quadratics(fallback[c], m);
            if (t_.perfect) rows_ok[c] = rms(q[c], fallback[c].x0, fallback[c].y0, m) <= t_.fallback_tol;
        }
        for (const unsigned k : {1u, 3u}) {
            for (std::size_t c = 0; c < fallback.size(); ++c)
                if (rows_ok[c] || t_.perfect) want(fallback[c].x0 + k, fallback[c].y0 + k);  // perfect: still read
            flush();
            if (t_.perfect) continue;
            for (std::size_t c = 0; c < fallback.size(); ++c) {
                if (!rows_ok[c]) continue;
                const rgb_levels& v = colour_[idx(fallback[c].x0 + k, fallback[c].y0 + k)];
                const rgb_levels& e = q[c][std::size_t(k) * m + k];
                rows_ok[c] = largest({e[0] - v[0], e[1] - v[1], e[2] - v[2]}) <= t_.fallback_tol;
            }
        }
        for (std::size_t c = 0; c < fallback.size(); ++c)
            if (!rows_ok[c])
                for (unsigned y = fallback[c].y0; y < fallback[c].y0 + m; ++y)
                    for (unsigned x = fallback[c].x0; x < fallback[c].x0 + m; ++x) want(x, y);
        flush();
        for (std::size_t c = 0; c < fallback.size(); ++c) {
            if (rows_ok[c]) {
                deliver(q[c], fallback[c].x0, fallback[c].y0, m);
                ++f_.fallback_rows;
            } else {
                std::vector<rgb_levels> exact(std::size_t(m) * m);
                for (unsigned y = 0; y < m; ++y)
                    for (unsigned x = 0; x < m; ++x)
                        exact[std::size_t(y) * m + x] = colour_[idx(fallback[c].x0 + x, fallback[c].y0 + y)];
                deliver(exact, fallback[c].x0, fallback[c].y0, m);
                ++f_.fallback_exact;
            }
        }
    }

    // Cell e of m pixels as m row quadratics, each through the row's pixels 0, 2 and 4.
    std::vector<rgb_levels> row_quadratics(const pending_cell& e, unsigned m) const {
        std::vector<rgb_levels> q(std::size_t(m) * m, rgb_levels{0.0, 0.0, 0.0});
        for (unsigned y = 0; y < m; ++y)
            for (unsigned x = 0; x < m; ++x) {
                const auto w = quadratic_weights(x, 2.0);
                for (unsigned j = 0; j < 3; ++j)
                    for (int ch = 0; ch < 3; ++ch) q[std::size_t(y) * m + x][ch] += w[j] * colour_[idx(e.x0 + 2 * j, e.y0 + y)][ch];
            }
        return q;
    }

    // Runs of the pixels where `in` holds, along rows (joined within one segment) or down columns
    // (joined where a pixel is one patch with the one below), each handed to fn in order.
    template <class In, class Fn>
    void runs(bool columns, const In& in, const Fn& fn) const {
        const unsigned outer = columns ? W : H, inner = columns ? H : W;
        for (unsigned a = 0; a < outer; ++a)
            for (unsigned b = 0; b < inner;) {
                auto at = [&](unsigned k) { return columns ? pixel{a, k} : pixel{k, a}; };
                const pixel first = at(b);
                if (!in(first[0], first[1])) {
                    ++b;
                    continue;
                }
                std::vector<pixel> px{first};
                while (b + px.size() < inner) {
                    const pixel q = at(b + unsigned(px.size())), last = px.back();
                    const bool joined = columns ? down_[idx(last[0], last[1])] != 0
                                                : seg_[idx(q[0], q[1])] == seg_[idx(first[0], first[1])];
                    if (!joined || !in(q[0], q[1])) break;
                    px.push_back(q);
                }
                fn(px);
                b += unsigned(px.size());
            }
    }

    // One run: sent by the emulated policy, its points read in the run's order.
    void send_run(const std::vector<pixel>& px, const adaptive_emulation& line) {
        std::vector<rgb_levels> v;
        for (const auto& p : px) v.push_back(colour_[idx(p[0], p[1])]);
        const emulated_run er = emulate_adaptive(v, line);
        for (std::size_t k = 0; k < px.size(); ++k) {
            if (er.point[k]) read(px[k][0], px[k][1]);
            f_.out[idx(px[k][0], px[k][1])] = er.out[k];
            done_[idx(px[k][0], px[k][1])] = 1;
        }
    }

    const scene::rasterised& r_;
    const std::vector<rgb_levels>& colour_;
    const cell_tree_config& t_;
    const unsigned W, H;
    std::vector<int32_t> seg_;
    std::vector<uint8_t> down_;
    std::vector<uint8_t> done_;  // per pixel: delivered by a cell or a run
    cell_frame f_;
    std::vector<pixel> batch_;  // reads waiting for the next flush
};

}  // namespace

cell_frame emulate_cells(const scene::rasterised& r, const std::vector<rgb_levels>& colour,
                         const pipeline::plan_config& cfg, const cell_tree_config& t) {
    if (colour.size() != r.tri.size()) throw std::invalid_argument("emulate_cells: colours and raster differ in size");
    if (!power_of_two(t.s_min) || !power_of_two(t.s_max) || t.s_min < 4 || t.s_max < t.s_min || t.s_max > 256)
        throw std::invalid_argument("emulate_cells: needs cell sizes, powers of two, 4 <= s_min <= s_max <= 256");
    if (!(t.tol > 0.0) || !(t.d2_factor > 0.0) || !(t.d3_factor > 0.0) || !(t.fallback_tol > 0.0) ||
        !(t.line_tol > 0.0) || !(t.column_ratio > 0.0))
        throw std::invalid_argument("emulate_cells: tolerances and factors must be positive");
    cell_emulator e(r, colour, cfg, t);
    e.cells();
    e.lines();
    return e.finish();
}

emulated_cost cell_long_ops(const scene::rasterised& r, const cell_frame& f, const scene::device_config& dev,
                            unsigned n, bool walk_edges, bool raster_order) {
    if (f.point.size() != r.tri.size()) throw std::invalid_argument("cell_long_ops: the frame and raster differ in size");
    std::vector<std::array<unsigned, 2>> points = f.order;
    if (raster_order) std::sort(points.begin(), points.end(), raster_before);
    return points_cost(r, points, dev, n, walk_edges, raster_order ? std::vector<uint8_t>{} : f.order_down);
}

}  // namespace shading::study
