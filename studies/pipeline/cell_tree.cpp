// The quadtree of biquadratic cells decided from its lattices' differences (cell_tree.h).
#include "cell_tree.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "golden_pipeline/quadtree.h"

namespace shading::study {

namespace {

double largest(const rgb_levels& v) { return std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])}); }

// The quadratic through 0, h, 2h at t: its three Lagrange weights.
std::array<double, 3> quadratic_weights(double t, double h) {
    return {(t - h) * (t - 2.0 * h) / (2.0 * h * h), -t * (t - 2.0 * h) / (h * h), t * (t - h) / (2.0 * h * h)};
}

bool power_of_two(unsigned v) { return v != 0 && (v & (v - 1)) == 0; }

using pipeline::quadtree::raster_before;

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

// The emulation's side of the quadtree walk (golden_pipeline/quadtree.h): the colours per-pixel
// shading gives, decided in levels on the lattices' differences, or with perfect on the true RMS of
// what a cell would send.
class emulated_side {
public:
    emulated_side(const scene::rasterised& r, const std::vector<rgb_levels>& colour, const cell_tree_config& t,
                  cell_frame& f)
        : r_(r), colour_(colour), t_(t), f_(f), W(r.width) {}

    void read(unsigned x, unsigned y) {
        if (r_.covered(x, y) && !f_.point[idx(x, y)]) {
            f_.point[idx(x, y)] = 1;
            f_.order.push_back({x, y});
        }
    }
    bool accept(const pipeline::quadtree::cell& e) const {
        if (t_.perfect) return rms(biquadratic(e.x0, e.y0, e.s), e.x0, e.y0, e.s) <= t_.tol;
        return lattice_second_difference(colour_, W, e.x0, e.y0, e.s) <= t_.d2_factor * t_.tol &&
               (!e.family || family_third_difference(colour_, W, e.x0, e.y0, e.s, e.px, e.py) <= t_.d3_factor * t_.tol);
    }
    void send(const pipeline::quadtree::cell& e) { deliver(biquadratic(e.x0, e.y0, e.s), e.x0, e.y0, e.s); }
    // perfect: the check points are read all the same.
    bool reads_every_check() const { return t_.perfect; }
    bool rows_pass(const pipeline::quadtree::cell& e, unsigned k) const {
        const std::vector<rgb_levels> q = rows(e);
        if (t_.perfect) return rms(q, e.x0, e.y0, e.s) <= t_.fallback_tol;
        const rgb_levels& v = colour_[idx(e.x0 + k, e.y0 + k)];
        const rgb_levels& p = q[std::size_t(k) * e.s + k];
        return largest({p[0] - v[0], p[1] - v[1], p[2] - v[2]}) <= t_.fallback_tol;
    }
    void send_fallback(const pipeline::quadtree::cell& e, bool with_rows) {
        if (with_rows) {
            deliver(rows(e), e.x0, e.y0, e.s);
            return;
        }
        std::vector<rgb_levels> exact(std::size_t(e.s) * e.s);
        for (unsigned y = 0; y < e.s; ++y)
            for (unsigned x = 0; x < e.s; ++x) exact[std::size_t(y) * e.s + x] = colour_[idx(e.x0 + x, e.y0 + y)];
        deliver(exact, e.x0, e.y0, e.s);
    }

private:
    std::size_t idx(unsigned x, unsigned y) const { return std::size_t(y) * W + x; }

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
            for (unsigned x = 0; x < s; ++x) f_.out[idx(x0 + x, y0 + y)] = p[std::size_t(y) * s + x];
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
                        for (int ch = 0; ch < 3; ++ch)
                            o[ch] += wy[i] * wx[j] * colour_[idx(x0 + j * h, y0 + i * h)][ch];
            }
        }
        return p;
    }
    // A fallback's rows: each the quadratic through its pixels 0, 2 and 4.
    std::vector<rgb_levels> rows(const pipeline::quadtree::cell& e) const {
        const unsigned m = e.s;
        std::vector<rgb_levels> q(std::size_t(m) * m, rgb_levels{0.0, 0.0, 0.0});
        for (unsigned y = 0; y < m; ++y)
            for (unsigned x = 0; x < m; ++x) {
                const auto w = quadratic_weights(x, 2.0);
                for (unsigned j = 0; j < 3; ++j)
                    for (int ch = 0; ch < 3; ++ch)
                        q[std::size_t(y) * m + x][ch] += w[j] * colour_[idx(e.x0 + 2 * j, e.y0 + y)][ch];
            }
        return q;
    }

    const scene::rasterised& r_;
    const std::vector<rgb_levels>& colour_;
    const cell_tree_config& t_;
    cell_frame& f_;
    const unsigned W;
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
    const unsigned W = r.width;
    auto idx = [W](unsigned x, unsigned y) { return std::size_t(y) * W + x; };
    auto covered = [&](unsigned x, unsigned y) { return r.tri[idx(x, y)] >= 0; };

    // The cells: the walk the bit-accurate cells take, on these colours.
    const pipeline::quadtree::regions g(r, cfg, nullptr);
    cell_frame f;
    f.out = colour;
    f.point.assign(colour.size(), 0);
    emulated_side side(r, colour, t, f);
    pipeline::quadtree::tally w = pipeline::quadtree::walk_cells(g, t.s_min, t.s_max, side);
    f.sent = std::move(w.sent);
    f.fallback_rows = w.fallback_rows;
    f.fallback_exact = w.fallback_exact;
    f.pixels_cells = w.pixels;
    std::vector<uint8_t> done = std::move(w.taken);

    // What no cell delivered, in runs down the columns where their runs are the longer (the same
    // pixels as the bit-accurate cells'), then along the rows. Kept apart from the bit-accurate cells,
    // which hand these pixels to the planner itself (make_plan, on the transposed frame for the
    // columns): here each run goes to the emulated adaptive policy, in the runs the walk's regions
    // cut. Along rows they are the planner's; down a column the planner also cuts at depth steps, and
    // at folds only with surface_breaks.
    using pixel = pipeline::quadtree::pixel;
    const std::size_t before_lines = f.order.size();
    adaptive_emulation line;
    line.tol = t.line_tol;
    line.m_max = t.line_m_max;
    line.above_slack = -1;
    line.perfect = t.perfect;
    // One run: sent by the emulated policy, its points read in the run's order.
    auto run = [&](const std::vector<pixel>& px) {
        std::vector<rgb_levels> v;
        for (const auto& p : px) v.push_back(colour[idx(p[0], p[1])]);
        const emulated_run er = emulate_adaptive(v, line);
        for (std::size_t k = 0; k < px.size(); ++k) {
            if (er.point[k]) side.read(px[k][0], px[k][1]);
            f.out[idx(px[k][0], px[k][1])] = er.out[k];
            done[idx(px[k][0], px[k][1])] = 1;
        }
    };
    const std::vector<uint8_t> by_column = g.column_runs(done, t.column_ratio);
    g.runs(true, [&](unsigned x, unsigned y) { return by_column[idx(x, y)] != 0; }, [&](const std::vector<pixel>& px) {
        f.pixels_columns += px.size();
        run(px);
    });
    auto left = [&](unsigned x, unsigned y) { return covered(x, y) && !done[idx(x, y)]; };
    g.runs(false, left, [&](const std::vector<pixel>& px) {
        f.pixels_rows += px.size();
        run(px);
    });
    f.points_lines = f.order.size() - before_lines;
    // Every point read is delivered as read: the sample stage formed its colour.
    for (std::size_t i = 0; i < colour.size(); ++i)
        if (f.point[i]) f.out[i] = colour[i];

    for (std::size_t i = 0; i < colour.size(); ++i) {
        if (r.tri[i] < 0) continue;
        ++f.pixels;
        for (int ch = 0; ch < 3; ++ch) {
            const double d = f.out[i][ch] - colour[i][ch];
            f.se += d * d;
            f.ref2 += colour[i][ch] * colour[i][ch];
        }
    }
    return f;
}

emulated_cost cell_long_ops(const scene::rasterised& r, const cell_frame& f, const scene::device_config& dev,
                            unsigned n, bool walk_edges, bool raster_order) {
    if (f.point.size() != r.tri.size()) throw std::invalid_argument("cell_long_ops: the frame and raster differ in size");
    std::vector<std::array<unsigned, 2>> points = f.order;
    if (raster_order) std::sort(points.begin(), points.end(), raster_before);
    return points_cost(r, points, dev, n, walk_edges, raster_order ? std::vector<uint8_t>{} : f.order_down);
}

}  // namespace shading::study
