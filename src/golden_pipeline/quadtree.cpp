// The cells' regions and runs (quadtree.h).
#include "golden_pipeline/quadtree.h"

#include "golden_pipeline/line_geometry.h"

namespace shading::pipeline::quadtree {

regions::regions(const scene::rasterised& r, const plan_config& c, scene::op_counts* decision)
    : r_(r), seg_(r.tri.size(), -1), down_(r.tri.size(), 0) {
    int32_t next = 0;
    for (unsigned y = 0; y < r.height; ++y)
        for (const auto& s : line_segments(r, y, c, decision)) {
            for (unsigned x = s[0]; x <= s[1]; ++x) seg_[r.index(x, y)] = next;
            ++next;
        }
    for (unsigned y = 0; y + 1 < r.height; ++y)
        for (unsigned x = 0; x < r.width; ++x)
            down_[r.index(x, y)] = r.covered(x, y) && r.covered(x, y + 1) &&
                                   !surface_break(r, r.index(x, y), r.index(x, y + 1), decision);
}

bool regions::whole(unsigned x0, unsigned y0, unsigned s) const {
    if (x0 + s >= r_.width || y0 + s >= r_.height) return false;
    for (unsigned y = y0; y <= y0 + s; ++y)
        for (unsigned x = x0; x <= x0 + s; ++x) {
            if (segment(x, y) < 0 || segment(x, y) != segment(x0, y)) return false;
            if (y < y0 + s && !joined_below(x, y)) return false;
        }
    return true;
}

std::vector<uint8_t> regions::column_runs(const std::vector<uint8_t>& taken, double column_ratio) const {
    const std::size_t n = r_.tri.size();
    auto rest = [&](unsigned x, unsigned y) { return r_.covered(x, y) && !taken[r_.index(x, y)]; };
    std::vector<unsigned> row_run(n, 0), col_run(n, 0);
    runs(false, rest, [&](const std::vector<pixel>& px) {
        for (const pixel& q : px) row_run[r_.index(q[0], q[1])] = unsigned(px.size());
    });
    runs(true, rest, [&](const std::vector<pixel>& px) {
        for (const pixel& q : px) col_run[r_.index(q[0], q[1])] = unsigned(px.size());
    });
    std::vector<uint8_t> out(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        out[i] = col_run[i] >= 5 && double(col_run[i]) >= column_ratio * double(row_run[i]);
    return out;
}

}  // namespace shading::pipeline::quadtree
