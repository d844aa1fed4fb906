// The cells' quadtree walk, written once: which cells are tried and in what order, which points are
// read when, what is sent and what is left to the lines, and the runs the rest is cut into. The
// bit-accurate cells (cells.h) decide on the sample stage's codes; the cells study's real-valued
// emulation (cell_tree.h) decides on colours in levels, or on the true error as a yardstick. Each
// side is a `Side` below; the walk never sees a colour.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "golden_pipeline/pipeline.h"

namespace shading::pipeline::quadtree {

// A cell tried: pixels [x0, x0 + s) x [y0, y0 + s). family: its parent was whole and turned down, so
// the family lattice (spacing s/2 over the parent's pixels from (px, py)) was read before it decides.
struct cell {
    unsigned x0 = 0, y0 = 0, s = 0;
    bool family = false;
    unsigned px = 0, py = 0;
};

using pixel = std::array<unsigned, 2>;  // {x, y}

// Raster order: line by line, left to right (the geometry unit steps along each line).
inline bool raster_before(const pixel& a, const pixel& b) { return a[1] != b[1] ? a[1] < b[1] : a[0] < b[0]; }

// Where cells may lie and runs may join: each covered pixel's segment (line_segments, a running
// number over the frame) and whether it is one surface with the pixel below (both covered, no
// surface_break between them).
class regions {
public:
    // c: the segments' rules (depth_step, surface_breaks). Their compares are charged to decision
    // (null: uncounted).
    regions(const scene::rasterised& r, const plan_config& c, scene::op_counts* decision);

    const scene::rasterised& raster() const { return r_; }
    int32_t segment(unsigned x, unsigned y) const { return seg_[r_.index(x, y)]; }
    bool joined_below(unsigned x, unsigned y) const { return down_[r_.index(x, y)] != 0; }

    // The cell of s pixels at (x0, y0) is whole: every pixel of its closed box [x0, x0 + s] x
    // [y0, y0 + s] covered, each row of the box in one segment, each pixel of it one surface with
    // the one below (the lattice's last row and column are pixels of the cells beside and below).
    bool whole(unsigned x0, unsigned y0, unsigned s) const;

    // The runs of pixels where in(x, y) holds, along rows (joined within one segment) or, with
    // columns, down columns (joined where a pixel is one surface with the one below), each handed to
    // fn (a std::vector<pixel>, in order) row by row (column by column).
    template <class In, class Fn>
    void runs(bool columns, const In& in, const Fn& fn) const {
        const unsigned outer = columns ? r_.width : r_.height, inner = columns ? r_.height : r_.width;
        std::vector<pixel> px;
        for (unsigned a = 0; a < outer; ++a)
            for (unsigned b = 0; b < inner;) {
                auto at = [&](unsigned k) { return columns ? pixel{a, k} : pixel{k, a}; };
                const pixel first = at(b);
                if (!in(first[0], first[1])) {
                    ++b;
                    continue;
                }
                px.assign(1, first);
                while (b + px.size() < inner) {
                    const pixel q = at(b + unsigned(px.size())), last = px.back();
                    const bool joined = columns ? joined_below(last[0], last[1])
                                                : segment(q[0], q[1]) == segment(first[0], first[1]);
                    if (!joined || !in(q[0], q[1])) break;
                    px.push_back(q);
                }
                fn(static_cast<const std::vector<pixel>&>(px));
                b += unsigned(px.size());
            }
    }

    // The covered pixels not taken (one entry per raster pixel) whose run of such pixels down their
    // column is at least 5 and at least column_ratio x their run along their row: a strip beside a
    // silhouette that runs down the frame is long one way and a pixel or two wide the other, so it
    // goes down its columns (counters and compares on the taken map, not counted).
    std::vector<uint8_t> column_runs(const std::vector<uint8_t>& taken, double column_ratio) const;

private:
    const scene::rasterised& r_;
    std::vector<int32_t> seg_;   // -1 where not covered
    std::vector<uint8_t> down_;
};

// What the walk delivered: cells sent by size (sent[k] of s_min << k pixels), the smallest cells
// turned down and sent as row quadratics or exact, and the pixels they took (one entry per raster
// pixel; what is left is the lines').
struct tally {
    std::vector<std::size_t> sent;
    std::size_t fallback_rows = 0, fallback_exact = 0;
    std::vector<uint8_t> taken;
    std::size_t pixels = 0;  // taken
};

// The walk, band by band (s_max lines) and in each band level by level, each level's points read
// together in raster order across the band before any of its cells decides (a geometry unit steps
// along each line through them):
//  - the band's tiles of s_max pixels with a covered pixel are tried; a cell tried and whole reads
//    its lattice, the 3 x 3 pixels at (x0 + j s/2, y0 + i s/2), unless its family read it;
//  - a whole cell accepted is sent; a whole cell turned down above s_min reads its children's
//    family lattice (the 5 x 5 lattice, spacing s/4); every cell above s_min not sent has its four
//    children tried at the next level;
//  - the whole cells of s_min turned down, after the level: every row read at 0, 2 and 4 and its
//    quadratic through them checked at (1, 1), then (3, 3) (the second check where the first
//    passed); where a check misses, all the cell's pixels read, and the cell sent, rows or exact.
// The fallback's rows and checks are written for s_min = 4 (the golden cells refuse other sizes).
// Side's members, called in the walk's order:
//   void read(unsigned x, unsigned y): a point read (each side skips a point already read and one
//       not covered);
//   bool accept(const cell&): a whole cell decided, its lattice (and family) read;
//   void send(const cell&): a cell accepted, at once;
//   bool reads_every_check() const: read the second check point of a cell whose first missed (a
//       side that decides otherwise still reads every point the scheme reads);
//   bool rows_pass(const cell&, unsigned k): the fallback's row quadratic at (k, k) against the
//       colour there, the rows at 0, 2, 4 and the check point read;
//   void send_fallback(const cell&, bool rows): its pixels as row quadratics or exact, all read.
template <class Side>
class walk {
public:
    walk(const regions& g, unsigned s_min, unsigned s_max, Side& side)
        : g_(g), s_min_(s_min), s_max_(s_max), side_(side) {}

    tally run() {
        const scene::rasterised& r = g_.raster();
        t_ = tally{};
        for (unsigned s = s_min_; s <= s_max_; s *= 2) t_.sent.push_back(0);
        t_.taken.assign(r.tri.size(), 0);
        for (unsigned by = 0; by < r.height; by += s_max_) band(by);
        for (const uint8_t v : t_.taken) t_.pixels += v;
        return std::move(t_);
    }

private:
    void want(unsigned x, unsigned y) { batch_.push_back({x, y}); }
    void flush() {
        std::sort(batch_.begin(), batch_.end(), raster_before);
        for (const pixel& q : batch_) side_.read(q[0], q[1]);
        batch_.clear();
    }
    void take(const cell& e) {
        for (unsigned y = e.y0; y < e.y0 + e.s; ++y)
            for (unsigned x = e.x0; x < e.x0 + e.s; ++x) t_.taken[g_.raster().index(x, y)] = 1;
    }

    void band(unsigned by) {
        const scene::rasterised& r = g_.raster();
        std::vector<cell> level;
        for (unsigned x0 = 0; x0 < r.width; x0 += s_max_) {
            bool any = false;
            for (unsigned y = by; y < std::min(r.height, by + s_max_) && !any; ++y)
                for (unsigned x = x0; x < std::min(r.width, x0 + s_max_) && !any; ++x) any = r.covered(x, y);
            if (any) level.push_back({x0, by, s_max_, false, 0, 0});
        }
        for (unsigned s = s_max_; !level.empty(); s /= 2) {
            const unsigned h = s / 2;
            std::vector<uint8_t> is_whole(level.size());
            for (std::size_t c = 0; c < level.size(); ++c) {
                is_whole[c] = g_.whole(level[c].x0, level[c].y0, s);
                if (is_whole[c] && !level[c].family)  // with a family its lattice was read with it
                    for (unsigned y = level[c].y0; y <= level[c].y0 + s; y += h)
                        for (unsigned x = level[c].x0; x <= level[c].x0 + s; x += h) want(x, y);
            }
            flush();
            std::vector<cell> next, fallback;
            for (std::size_t c = 0; c < level.size(); ++c) {
                const cell& e = level[c];
                if (is_whole[c]) {
                    if (side_.accept(e)) {
                        side_.send(e);
                        unsigned k = 0;
                        while ((s_min_ << k) < s) ++k;
                        ++t_.sent[k];
                        take(e);
                        continue;
                    }
                    if (s == s_min_) {
                        fallback.push_back(e);
                        continue;
                    }
                    // The children's lattices, their family, read before any of them decides.
                    for (unsigned y = e.y0; y <= e.y0 + s; y += h / 2)
                        for (unsigned x = e.x0; x <= e.x0 + s; x += h / 2) want(x, y);
                }
                if (s > s_min_)
                    for (unsigned dy : {0u, h})
                        for (unsigned dx : {0u, h})
                            next.push_back({e.x0 + dx, e.y0 + dy, h, bool(is_whole[c]), e.x0, e.y0});
            }
            flush();
            if (!fallback.empty()) fallbacks(fallback);
            level = std::move(next);
        }
    }

    void fallbacks(const std::vector<cell>& fallback) {
        const unsigned m = s_min_;
        for (const cell& e : fallback)
            for (unsigned y = e.y0; y < e.y0 + m; ++y)
                for (unsigned x = e.x0; x <= e.x0 + m; x += 2) want(x, y);
        flush();
        std::vector<uint8_t> rows_ok(fallback.size(), 1);
        for (const unsigned k : {1u, 3u}) {
            for (std::size_t c = 0; c < fallback.size(); ++c)
                if (rows_ok[c] || side_.reads_every_check()) want(fallback[c].x0 + k, fallback[c].y0 + k);
            flush();
            for (std::size_t c = 0; c < fallback.size(); ++c)
                if (rows_ok[c]) rows_ok[c] = side_.rows_pass(fallback[c], k);
        }
        for (std::size_t c = 0; c < fallback.size(); ++c)
            if (!rows_ok[c])
                for (unsigned y = fallback[c].y0; y < fallback[c].y0 + m; ++y)
                    for (unsigned x = fallback[c].x0; x < fallback[c].x0 + m; ++x) want(x, y);
        flush();
        for (std::size_t c = 0; c < fallback.size(); ++c) {
            side_.send_fallback(fallback[c], rows_ok[c] != 0);
            ++(rows_ok[c] ? t_.fallback_rows : t_.fallback_exact);
            take(fallback[c]);
        }
    }

    const regions& g_;
    const unsigned s_min_, s_max_;
    Side& side_;
    tally t_;
    std::vector<pixel> batch_;
};

// The walk over the frame g covers: walk<Side>(g, s_min, s_max, side).run().
template <class Side>
tally walk_cells(const regions& g, unsigned s_min, unsigned s_max, Side& side) {
    return walk<Side>(g, s_min, s_max, side).run();
}

}  // namespace shading::pipeline::quadtree
