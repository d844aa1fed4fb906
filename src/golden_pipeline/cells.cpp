// The cells (cells.h): the plan, the biquadratic and the frame, on the sample stage's codes.
#include "golden_pipeline/cells.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "golden_pipeline/line_geometry.h"
#include "golden_pipeline/quadtree.h"

namespace shading::pipeline {

namespace {

bool power_of_two(unsigned v) { return v != 0 && (v & (v - 1)) == 0; }
unsigned log2_of(unsigned v) {
    unsigned m = 0;
    while ((1u << m) < v) ++m;
    return m;
}
uint64_t levels_to_codes(double levels) {
    return static_cast<uint64_t>(std::floor(levels * double(1u << colour_fmt.frac)));
}
uint64_t abs_diff(int64_t v) { return static_cast<uint64_t>(v < 0 ? -v : v); }

using quadtree::pixel;
using quadtree::raster_before;

// The golden side of the quadtree walk (quadtree.h): each point's geometry and the sample stage's
// colour formed once, the decisions adders and compares on codes, each one counted.
class cell_planner {
public:
    cell_planner(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
                 const plan_config& c, const cell_config& t, cell_plan& p)
        : r_(r), k_(k), dev_(dev), c_(c), t_(t), lim_(cell_limits_of(t)), p_(p), W(r.width), H(r.height),
          g_(r, c, &p.decision), read_(r.tri.size(), 0), smp_(r.tri.size()), col_(r.tri.size()) {}

    void run() {
        quadtree::tally w = quadtree::walk_cells(g_, t_.s_min, t_.s_max, *this);
        p_.sent = std::move(w.sent);
        p_.fallback_rows = w.fallback_rows;
        p_.fallback_exact = w.fallback_exact;
        p_.pixels_cells = w.pixels;
        taken_ = std::move(w.taken);
        lines();
        for (std::size_t i = 0; i < r_.tri.size(); ++i) p_.pixels += r_.tri[i] >= 0;
    }

    // The walk's side (quadtree::walk). The geometry side reads a point once: its geometry and the
    // sample stage's colour (down: stepped down its column, for the columns' runs).
    void read(unsigned x, unsigned y, bool down = false) {
        const std::size_t i = idx(x, y);
        if (read_[i] || !r_.covered(x, y)) return;
        read_[i] = 1;
        smp_[i] = sample_of(scene::geometry_at(r_, x, y, nullptr));
        col_[i] = golden_sample(dev_, k_, smp_[i]);
        p_.points.push_back({x, y});
        p_.point_geometry.push_back(smp_[i]);
        p_.point_down.push_back(down ? 1 : 0);
    }
    bool accept(const quadtree::cell& e) {
        return second_differences_pass(e.x0, e.y0, e.s) &&
               (!e.family || third_differences_pass(e.x0, e.y0, e.s, e.px, e.py));
    }
    void send(const quadtree::cell& e) {
        cell_job cell;
        cell.x0 = e.x0;
        cell.y0 = e.y0;
        cell.s = e.s;
        for (unsigned i = 0; i < 3; ++i)
            for (unsigned j = 0; j < 3; ++j)
                cell.lattice[3 * i + j] = smp_[idx(e.x0 + j * e.s / 2, e.y0 + i * e.s / 2)];
        p_.cells.push_back(cell);
    }
    bool reads_every_check() const { return false; }
    // The row quadratic at (k, k) against the sample stage's colour there, within the fallback limit.
    bool rows_pass(const quadtree::cell& e, unsigned k) {
        const auto px = interval_pixels(row_job(e.x0, e.y0 + k), k_, dev_, c_.eval, c_.set, c_.div);
        const rgb_codes& v = colour(e.x0 + k, e.y0 + k);
        bool ok = true;
        for (int ch = 0; ch < 3; ++ch) {
            ++p_.decision.add;
            ++p_.decision.cmp;
            if (abs_diff(int64_t(px[k][ch]) - int64_t(v[ch])) > lim_.fallback) ok = false;
        }
        return ok;
    }
    void send_fallback(const quadtree::cell& e, bool rows) {
        for (unsigned y = e.y0; y < e.y0 + e.s; ++y) {
            if (rows) {
                p_.jobs.push_back(row_job(e.x0, y));
            } else {
                for (unsigned x = e.x0; x < e.x0 + e.s; ++x) p_.jobs.push_back(exact_job(x, y));
            }
        }
    }

private:
    std::size_t idx(unsigned x, unsigned y) const { return r_.index(x, y); }
    const rgb_codes& colour(unsigned x, unsigned y) const { return col_[idx(x, y)]; }

    // (a): the lattice's second differences.
    bool second_differences_pass(unsigned x0, unsigned y0, unsigned s) {
        const unsigned h = s / 2;
        for (unsigned k = 0; k < 3; ++k)
            for (int ch = 0; ch < 3; ++ch) {
                auto d2 = [&](unsigned xa, unsigned ya, unsigned dx, unsigned dy) {
                    const int64_t a = int64_t(colour(xa, ya)[ch]), b = int64_t(colour(xa + dx, ya + dy)[ch]),
                                  c = int64_t(colour(xa + 2 * dx, ya + 2 * dy)[ch]);
                    p_.decision.add += 2;  // 2 b is a shift
                    ++p_.decision.cmp;
                    return abs_diff(a - 2 * b + c) <= lim_.d2;
                };
                if (!d2(x0, y0 + k * h, h, 0) || !d2(x0 + k * h, y0, 0, h)) return false;
            }
        return true;
    }
    // (b): the third differences through the family lattice (spacing h = s/2 over the parent at px, py).
    bool third_differences_pass(unsigned x0, unsigned y0, unsigned s, unsigned px, unsigned py) {
        const unsigned h = s / 2;
        const unsigned ci = (x0 - px) / h, ri = (y0 - py) / h;
        const unsigned c0 = ci == 0 ? 0 : 1, r0 = ri == 0 ? 0 : 1;
        auto at = [&](unsigned i, unsigned j, int ch) { return int64_t(colour(px + j * h, py + i * h)[ch]); };
        for (int ch = 0; ch < 3; ++ch) {
            auto d3 = [&](int64_t a, int64_t b, int64_t c, int64_t d) {
                p_.decision.add += 5;  // 3 c and 3 b: a shift and an add each
                ++p_.decision.cmp;
                return abs_diff(d - 3 * c + 3 * b - a) <= lim_.d3;
            };
            for (unsigned k = ri; k < ri + 3; ++k)
                if (!d3(at(k, c0, ch), at(k, c0 + 1, ch), at(k, c0 + 2, ch), at(k, c0 + 3, ch))) return false;
            for (unsigned k = ci; k < ci + 3; ++k)
                if (!d3(at(r0, k, ch), at(r0 + 1, k, ch), at(r0 + 2, k, ch), at(r0 + 3, k, ch))) return false;
        }
        return true;
    }

    interval_job row_job(unsigned x0, unsigned y) const {
        interval_job job;
        job.y = y;
        job.x0 = x0;
        job.len = t_.s_min;
        job.m = log2_of(t_.s_min);  // the quadratic through 0, s/2, s
        job.deg2 = true;
        for (unsigned i = 0; i < 3; ++i) job.s[i] = smp_[idx(x0 + i * t_.s_min / 2, y)];
        job.s[3] = job.s[2];
        return job;
    }
    interval_job exact_job(unsigned x, unsigned y) const {
        interval_job job;
        job.y = y;
        job.x0 = x;
        const sample_geometry s = smp_[idx(x, y)];
        job.s = {s, s, s, s};
        return job;
    }

    // What no cell delivered: the adaptive length policy down the columns where their runs are the
    // longer (quadtree::regions::column_runs), then over the rest of each line. The planner itself
    // plans these runs, where the cells study's emulation (cell_tree.h) cuts them with the walk's
    // regions and emulates the policy on each: that part is each side's own.
    void lines() {
        plan_config lc = c_;
        lc.length = length_policy::adaptive;
        lc.degree = degree_policy::cubic;
        lc.m_min = interp::m_min;
        lc.m_max = t_.line_m_max;
        lc.length_tol = t_.line_tol;
        lc.split_at_check = true;
        lc.exact_fallback = true;
        lc.above_slack = -1;
        lc.lit_guard = false;
        const std::size_t before = p_.points.size();
        std::vector<uint8_t> rows_taken = taken_;
        if (t_.column_ratio > 0.0) {
            const std::vector<uint8_t> by_column = g_.column_runs(taken_, t_.column_ratio);
            const scene::rasterised rt = scene::transposed(r_);
            std::vector<uint8_t> others(rt.tri.size(), 1);  // the column planner's taken map
            for (unsigned y = 0; y < H; ++y)
                for (unsigned x = 0; x < W; ++x)
                    if (by_column[idx(x, y)]) others[rt.index(y, x)] = 0;
            const plan cp = make_plan(rt, k_, dev_, lc, others);
            p_.decision += cp.decision;
            for (const pixel& q : cp.points) read(q[1], q[0], true);
            for (const interval_job& job : cp.jobs) {
                p_.column_jobs.push_back(job);
                p_.pixels_columns += job.len;
                for (unsigned i = 0; i < job.len; ++i) rows_taken[idx(job.y, job.x0 + i)] = 1;
            }
        }
        const plan lp = make_plan(r_, k_, dev_, lc, rows_taken);
        p_.decision += lp.decision;
        for (const pixel& q : lp.points) read(q[0], q[1]);
        p_.points_lines = p_.points.size() - before;
        for (const interval_job& job : lp.jobs) {
            p_.jobs.push_back(job);
            p_.pixels_rows += job.len;
        }
    }

    const scene::rasterised& r_;
    const frame_constants& k_;
    const scene::device_config& dev_;
    const plan_config& c_;
    const cell_config& t_;
    const cell_limits lim_;
    cell_plan& p_;
    const unsigned W, H;
    const quadtree::regions g_;    // each covered pixel's segment; one surface with the pixel below
    std::vector<uint8_t> read_, taken_;
    std::vector<sample_geometry> smp_;
    std::vector<rgb_codes> col_;
};

}  // namespace

void validate(const cell_config& t) {
    auto fail = [](const std::string& what) { throw scene::scene_error("cells: " + what); };
    if (!power_of_two(t.s_min) || !power_of_two(t.s_max) || t.s_min < 4 || t.s_max < t.s_min ||
        t.s_max > (1u << interp::m_max))
        fail("cell sizes must be powers of two with 4 <= s_min <= s_max <= " + std::to_string(1u << interp::m_max) +
             " (got " + std::to_string(t.s_min) + ", " + std::to_string(t.s_max) + ")");
    if (t.s_min != 4) fail("the fallback's row quadratics need s_min = 4 (got " + std::to_string(t.s_min) + ")");
    if (!(t.tol > 0.0) || !(t.d2_factor > 0.0) || !(t.d3_factor > 0.0) || !(t.fallback_tol > 0.0) || !(t.line_tol > 0.0))
        fail("tolerances and factors must be positive");
    if (!(t.tol * t.d2_factor < 1e6) || !(t.tol * t.d3_factor < 1e6) || !(t.fallback_tol < 1e6))
        fail("tolerances must be below 1e6 levels");
    if (!(t.column_ratio >= 0.0) || !(t.column_ratio < 1e6))
        fail("column_ratio must be 0 (rows only) or positive, below 1e6");
    if (t.line_m_max < interp::m_min || t.line_m_max > interp::m_max)
        fail("line_m_max must be " + std::to_string(interp::m_min) + ".." + std::to_string(interp::m_max) + " (got " +
             std::to_string(t.line_m_max) + ")");
}

cell_limits cell_limits_of(const cell_config& t) {
    cell_limits l;
    l.d2 = levels_to_codes(t.d2_factor * t.tol);
    l.d3 = levels_to_codes(t.d3_factor * t.tol / cell_k3);
    l.fallback = levels_to_codes(t.fallback_tol);
    return l;
}

cell_plan make_cell_plan(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
                         const plan_config& c, const cell_config& t) {
    validate(c);
    validate(t);
    cell_plan p;
    p.width = r.width;
    p.height = r.height;
    cell_planner(r, k, dev, c, t, p).run();
    return p;
}

std::array<rgb_codes, 9> cell_lattice_colours(const cell_job& cell, const frame_constants& k,
                                              const scene::device_config& dev) {
    std::array<rgb_codes, 9> out{};
    for (std::size_t i = 0; i < 9; ++i) out[i] = golden_sample(dev, k, cell.lattice[i]);
    return out;
}

std::vector<rgb_codes> cell_pixels(const std::array<rgb_codes, 9>& lattice, unsigned s, evaluator e) {
    if (!power_of_two(s) || s < 4 || s > (1u << interp::m_max))
        throw scene::scene_error("cell_pixels: a cell of " + std::to_string(s) + " pixels; sizes are powers of two, 4.." +
                                 std::to_string(1u << interp::m_max));
    const unsigned m = log2_of(s);
    // Down each lattice column: three colours for every row of the cell.
    std::array<std::vector<rgb_codes>, 3> column;
    for (unsigned j = 0; j < 3; ++j) column[j] = quadratic_pixels({lattice[j], lattice[3 + j], lattice[6 + j]}, m, s, e);
    std::vector<rgb_codes> out;
    out.reserve(std::size_t(s) * s);
    for (unsigned y = 0; y < s; ++y) {
        const auto row = quadratic_pixels({column[0][y], column[1][y], column[2][y]}, m, s, e);
        out.insert(out.end(), row.begin(), row.end());
    }
    return out;
}

frame golden_cell_frame(const cell_plan& p, const frame_constants& k, const scene::device_config& dev,
                        const plan_config& c) {
    frame f = empty_frame(p.width, p.height);
    auto put = [&](unsigned x, unsigned y, const rgb_codes& v, uint8_t degree, uint8_t m) {
        if (x >= p.width || y >= p.height)
            throw scene::scene_error("golden_cell_frame: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                     ") is outside the frame");
        const std::size_t i = std::size_t(y) * p.width + x;
        f.px[i] = v;
        f.covered[i] = 1;
        f.degree[i] = degree;
        f.log2_len[i] = m;
    };
    for (const cell_job& cell : p.cells) {
        const auto px = cell_pixels(cell_lattice_colours(cell, k, dev), cell.s, c.eval);
        for (unsigned y = 0; y < cell.s; ++y)
            for (unsigned x = 0; x < cell.s; ++x)
                put(cell.x0 + x, cell.y0 + y, px[std::size_t(y) * cell.s + x], 2, uint8_t(log2_of(cell.s)));
    }
    for (const interval_job& job : p.jobs) {
        const auto px = golden_interval(job, k, dev, c.eval, c.set, c.div);
        for (unsigned i = 0; i < job.len; ++i)
            put(job.x0 + i, job.y, px[i], job.m == 0 ? 1 : (job.deg2 ? 2 : 3), uint8_t(job.m));
    }
    for (const interval_job& job : p.column_jobs) {
        const auto px = golden_interval(job, k, dev, c.eval, c.set, c.div);
        for (unsigned i = 0; i < job.len; ++i)
            put(job.y, job.x0 + i, px[i], job.m == 0 ? 1 : (job.deg2 ? 2 : 3), uint8_t(job.m));
    }
    if (p.point_geometry.size() != p.points.size())
        throw scene::scene_error("golden_cell_frame: the plan lists " + std::to_string(p.points.size()) + " points and " +
                                 std::to_string(p.point_geometry.size()) + " geometries");
    for (const interval_job& job : point_jobs(p)) put(job.x0, job.y, golden_sample(dev, k, job.s[0]), 1, 0);
    return f;
}

std::vector<interval_job> point_jobs(const cell_plan& p) {
    std::vector<uint8_t> in_job(std::size_t(p.width) * p.height, 0);
    for (const interval_job& job : p.jobs)
        for (unsigned i = 0; i < job.len; ++i) in_job.at(std::size_t(job.y) * p.width + job.x0 + i) = 1;
    for (const interval_job& job : p.column_jobs)
        for (unsigned i = 0; i < job.len; ++i) in_job.at(std::size_t(job.x0 + i) * p.width + job.y) = 1;
    std::vector<interval_job> out;
    for (std::size_t i = 0; i < p.points.size(); ++i) {
        const unsigned x = p.points[i][0], y = p.points[i][1];
        if (in_job.at(std::size_t(y) * p.width + x)) continue;
        interval_job job;
        job.y = y;
        job.x0 = x;
        job.s = {p.point_geometry[i], p.point_geometry[i], p.point_geometry[i], p.point_geometry[i]};
        out.push_back(job);
    }
    return out;
}

plan pipeline_plan(const cell_plan& p) {
    plan out;
    out.width = std::max(p.width, p.height);
    out.height = p.height + p.width;
    out.jobs = p.jobs;
    for (interval_job job : p.column_jobs) {
        job.y += p.height;
        out.jobs.push_back(job);
    }
    const std::vector<interval_job> pts = point_jobs(p);
    out.jobs.insert(out.jobs.end(), pts.begin(), pts.end());
    for (const interval_job& job : out.jobs) out.pixels += job.len;
    return out;
}

frame cells_frame_of(const cell_plan& p, const frame& stacked) {
    const unsigned sw = std::max(p.width, p.height), sh = p.height + p.width;
    if (stacked.px.size() != std::size_t(sw) * sh || stacked.covered.size() != stacked.px.size() ||
        stacked.degree.size() != stacked.px.size() || stacked.log2_len.size() != stacked.px.size() ||
        stacked.zone.size() != stacked.px.size())
        throw scene::scene_error("cells_frame_of: a frame of " + std::to_string(stacked.px.size()) + " pixels; " +
                                 std::to_string(sw) + " x " + std::to_string(sh) + " expected");
    frame f = empty_frame(p.width, p.height);
    auto copy = [&](std::size_t from, unsigned x, unsigned y) {
        if (!stacked.covered[from]) return;
        const std::size_t i = std::size_t(y) * p.width + x;
        if (f.covered[i])
            throw scene::scene_error("cells_frame_of: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                     ") delivered along its row and down its column");
        f.px[i] = stacked.px[from];
        f.covered[i] = 1;
        f.degree[i] = stacked.degree[from];
        f.log2_len[i] = stacked.log2_len[from];
        f.zone[i] = stacked.zone[from];
    };
    for (unsigned y = 0; y < p.height; ++y)
        for (unsigned x = 0; x < p.width; ++x) {
            copy(std::size_t(y) * sw + x, x, y);
            copy(std::size_t(p.height + x) * sw + y, x, y);
        }
    return f;
}

cell_counts cell_ops(const scene::rasterised& r, const cell_plan& p, const scene::device_config& dev, unsigned n,
                     bool walk_edges, bool raster_order) {
    std::vector<std::array<unsigned, 2>> points = p.points;
    if (raster_order) std::sort(points.begin(), points.end(), raster_before);
    const std::vector<uint8_t> down = raster_order ? std::vector<uint8_t>{} : p.point_down;  // raster order: along rows
    const stepped_count g = stepped_geometry(r, points, walk_edges, down);
    cell_counts out;
    out.geometry = g.ops;
    out.stepping = g.stats;
    out.colours = scene::times(colour_sample_ops(dev, n), points.size());
    return out;
}

}  // namespace shading::pipeline
