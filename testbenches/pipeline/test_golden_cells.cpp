// The bit-accurate cells (src/golden_pipeline/cells.h): the decision unit's constants and the
// biquadratic worked by hand, the biquadratic against the real-valued one, a flat square's points
// hand-counted, the planner's map of taken pixels, and on the head at 512 every pixel delivered once
// and the interpolation target's figures. (The same cell decisions as the real-valued emulation,
// a separate implementation, are a study's check: studies/pipeline/test_golden_cells_emulation.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "golden_pipeline/cells.h"
#include "golden_pipeline/frame_setup.h"
#include "flat_square.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_golden_cells {

namespace {

using namespace shading;
using namespace shading::pipeline;

// floor(8 x 0.9 x 256) = floor(1843.2); 0.9 x 256 / k3 = 230.4 x 9 sqrt 3 = 3591.58...; 1 x 256.
TEST(GoldenCells, LimitsByHand) {
    EXPECT_NEAR(cell_k3, 1.0 / (9.0 * std::sqrt(3.0)), 1e-15);
    const cell_limits l = cell_limits_of(cell_config{});
    EXPECT_EQ(l.d2, 1843u);
    EXPECT_EQ(l.d3, 3591u);
    EXPECT_EQ(l.fallback, 256u);
}

std::array<rgb_codes, 9> lattice_of(const std::array<uint64_t, 9>& v) {
    std::array<rgb_codes, 9> out{};
    for (std::size_t i = 0; i < 9; ++i) out[i] = {v[i], v[i] / 2, v[i] / 4};
    return out;
}

// A constant lattice gives that constant everywhere. A ramp of 512 codes a lattice step (s/2 pixels)
// along x, the same on every lattice row, gives 1000 + 1024 x / s on every row: at s = 4, 1000,
// 1256, 1512, 1768 (a / 2: 500, 628, 756, 884); down y the same on every column.
TEST(GoldenCells, ConstantAndRampLatticesByHand) {
    for (evaluator e : {evaluator::fd, evaluator::horner}) {
        const auto flat = cell_pixels(lattice_of({777, 777, 777, 777, 777, 777, 777, 777, 777}), 8, e);
        ASSERT_EQ(flat.size(), 64u);
        for (const rgb_codes& p : flat) EXPECT_EQ(p, (rgb_codes{777, 388, 194}));
        const auto along_x = cell_pixels(lattice_of({1000, 1512, 2024, 1000, 1512, 2024, 1000, 1512, 2024}), 4, e);
        const auto down_y = cell_pixels(lattice_of({1000, 1000, 1000, 1512, 1512, 1512, 2024, 2024, 2024}), 4, e);
        ASSERT_EQ(along_x.size(), 16u);
        const uint64_t want[4] = {1000, 1256, 1512, 1768};
        const uint64_t half[4] = {500, 628, 756, 884};
        for (unsigned y = 0; y < 4; ++y)
            for (unsigned x = 0; x < 4; ++x) {
                EXPECT_EQ(along_x[y * 4 + x][0], want[x]) << x << "," << y;
                EXPECT_EQ(along_x[y * 4 + x][1], half[x]);
                EXPECT_EQ(down_y[y * 4 + x][0], want[y]) << x << "," << y;
            }
    }
}

// Random lattices of every size, both evaluators: each pixel within 2.5 codes (under a hundredth of a
// level) of the real-valued biquadratic through the lattice. Each stage floors to Q8.8 (under a code
// each); the row quadratic's weights have magnitudes summing to at most 1.25, so the column stage's
// floor moves a pixel by under 1.25 codes; Horner's products drop bits too. Codes 0x4000..0xA000 keep
// every column value inside the pixel format (a quadratic through three values overshoots their
// spread by at most an eighth), where the clamp would part the two.
TEST(GoldenCells, WithinCodesOfTheRealValuedBiquadratic) {
    std::mt19937 rng(20261204);
    std::uniform_int_distribution<uint64_t> code(0x4000, 0xA000);
    auto w = [](double t) {  // the quadratic through 0, 1/2, 1 at t: its Lagrange weights
        return std::array<double, 3>{2.0 * (t - 0.5) * (t - 1.0), -4.0 * t * (t - 1.0), 2.0 * t * (t - 0.5)};
    };
    double worst = 0.0;
    for (evaluator e : {evaluator::fd, evaluator::horner})
        for (unsigned s = 4; s <= 64; s *= 2)
            for (int trial = 0; trial < 20; ++trial) {
                std::array<rgb_codes, 9> lat{};
                for (auto& v : lat) v = {code(rng), code(rng), code(rng)};
                const auto px = cell_pixels(lat, s, e);
                ASSERT_EQ(px.size(), std::size_t(s) * s);
                for (unsigned y = 0; y < s; ++y)
                    for (unsigned x = 0; x < s; ++x) {
                        const auto wy = w(double(y) / s), wx = w(double(x) / s);
                        for (int ch = 0; ch < 3; ++ch) {
                            double v = 0.0;
                            for (unsigned i = 0; i < 3; ++i)
                                for (unsigned j = 0; j < 3; ++j) v += wy[i] * wx[j] * double(lat[3 * i + j][ch]);
                            worst = std::max(worst, std::abs(double(px[y * s + x][ch]) - v));
                        }
                    }
            }
    EXPECT_LE(worst, 2.5);
    EXPECT_GT(worst, 0.0);  // the floors are there: the test can see them
}

cell_config rows_only() {
    cell_config t;
    t.column_ratio = 0.0;
    return t;
}

// Every covered pixel of the frame delivered by exactly one cell or job; none outside.
std::vector<unsigned> deliveries(const cell_plan& p) {
    std::vector<unsigned> n(std::size_t(p.width) * p.height, 0);
    for (const cell_job& c : p.cells)
        for (unsigned y = c.y0; y < c.y0 + c.s; ++y)
            for (unsigned x = c.x0; x < c.x0 + c.s; ++x) ++n[std::size_t(y) * p.width + x];
    for (const interval_job& j : p.jobs)
        for (unsigned i = 0; i < j.len; ++i) ++n[std::size_t(j.y) * p.width + j.x0 + i];
    for (const interval_job& j : p.column_jobs)
        for (unsigned i = 0; i < j.len; ++i) ++n[std::size_t(j.x0 + i) * p.width + j.y];
    return n;
}

// The flat square at 65 x 65, one colour throughout: the four 32-pixel tiles whose closed boxes end
// at pixel 64 are whole and sent (second differences 0), reading the lattice {0, 16, 32, 48, 64}^2
// (25 points). Column 64 and row 64 are no cell's. Along rows only (column_ratio 0): row 64 is one
// segment of 65 pixels, four 16-pixel intervals read at 0, 4, 8, 16 and checked at 12 (every fourth
// pixel, 17 points, 5 of them the lattice's), and each pixel of column 64 above it is a run of one,
// an exact pixel (64 points, 4 of them the lattice's): 25 + 12 + 60 = 97 points. With the columns,
// column 64's 65 pixels run down the column (65 against a run of 1 along each row, and 65 against
// row 64's 65 at the corner): read every fourth line as row 64 was, 12 points beside the lattice's,
// and row 64 keeps pixels 0..63 for the rows. Either way the frame is per-pixel shading's, code for
// code.
TEST(GoldenCells, FlatSquareHandCounted) {
    const tb::flat_frame flat(tb::flat_square(65));
    const scene::rasterised& r = flat.r;
    const frame_constants& k = flat.k;
    const scene::device_config& dev = flat.dev;
    const cell_plan p = make_cell_plan(r, k, dev, plan_config{}, rows_only());
    ASSERT_EQ(p.sent.size(), 4u);
    EXPECT_EQ(p.sent[3], 4u);
    EXPECT_EQ(p.sent[0] + p.sent[1] + p.sent[2], 0u);
    EXPECT_EQ(p.pixels, 65u * 65u);
    EXPECT_EQ(p.pixels_cells, 64u * 64u);
    EXPECT_EQ(p.pixels_columns, 0u);
    EXPECT_EQ(p.pixels_rows, 129u);
    EXPECT_EQ(p.points.size(), 97u);
    EXPECT_EQ(p.points_lines, 72u);
    EXPECT_TRUE(p.column_jobs.empty());

    const cell_plan q = make_cell_plan(r, k, dev, plan_config{}, cell_config{});
    EXPECT_EQ(q.sent, p.sent);
    EXPECT_EQ(q.pixels_columns, 65u);
    EXPECT_EQ(q.pixels_rows, 64u);
    for (const interval_job& j : q.column_jobs) EXPECT_EQ(j.y, 64u);  // the column, in the transposed frame
    std::size_t down = 0;
    for (std::size_t i = 0; i < q.points.size(); ++i)
        if (q.point_down[i]) {
            EXPECT_EQ(q.points[i][0], 64u);
            EXPECT_EQ(q.points[i][1] % 4, 0u);
            ++down;
        }
    EXPECT_EQ(down, 12u);
    for (unsigned v : deliveries(q)) EXPECT_EQ(v, 1u);
    EXPECT_EQ(golden_cell_frame(q, k, dev, plan_config{}).px, per_pixel_frame(r, k, dev).px);
    for (unsigned v : deliveries(p)) EXPECT_EQ(v, 1u);
    plan_config fd;
    fd.eval = evaluator::fd;
    const frame f = golden_cell_frame(p, k, dev, fd);
    const frame ref = per_pixel_frame(r, k, dev);
    EXPECT_EQ(f.px, ref.px);
    EXPECT_EQ(f.covered, ref.covered);
}

// A flat strip one pixel wide, column 32 of a 65 x 65 frame: no cell fits. Along rows only each line
// is a run of one, an exact pixel: 65 points. Down the column it is one segment of 65 pixels, read
// every fourth line as the flat square's row 64 (0, 4, 8, 16 and the check at 12 in each 16-pixel
// interval): 17 points, each stepped from the one above where both lie on one triangle. The strip's
// two triangles meet on its diagonal, so 2 set-ups and 2 run starts. Counted (orthographic,
// directional light: only U_N is stepped): set-up 3 components x 3 coefficients x 3 mul = 27 mul a
// triangle; run start 3 x 2 mul; a point 12 mul (normalise N and H), 2 div, 2 sqrt and the dot
// products N.L and N.H, 6 mul: 2 x 27 + 2 x 6 + 17 x 18 = 372 mul, 34 div, 34 sqrt. Not stepped down
// (every point a run start): 15 x 6 = 90 mul more.
TEST(GoldenCells, FlatStripDownItsColumn) {
    const tb::flat_frame flat(tb::flat_strip(65));
    const scene::rasterised& r = flat.r;
    const frame_constants& k = flat.k;
    const scene::device_config& dev = flat.dev;
    ASSERT_EQ(r.covered_pixels(), 65u);
    for (unsigned y = 0; y < 65; ++y) ASSERT_TRUE(r.covered(32, y));
    const cell_plan p = make_cell_plan(r, k, dev, plan_config{}, rows_only());
    EXPECT_TRUE(p.cells.empty());
    EXPECT_EQ(p.pixels_rows, 65u);
    EXPECT_EQ(p.points.size(), 65u);

    const cell_plan q = make_cell_plan(r, k, dev, plan_config{}, cell_config{});
    EXPECT_TRUE(q.cells.empty());
    EXPECT_TRUE(q.jobs.empty());
    EXPECT_EQ(q.pixels_columns, 65u);
    EXPECT_EQ(q.pixels_rows, 0u);
    ASSERT_EQ(q.points.size(), 17u);
    EXPECT_EQ(q.points_lines, 17u);
    for (std::size_t i = 0; i < q.points.size(); ++i) {
        EXPECT_EQ(q.points[i][0], 32u);
        EXPECT_EQ(q.points[i][1], 4 * i);
        EXPECT_EQ(q.point_down[i], 1u);
    }
    for (unsigned v : deliveries(q)) EXPECT_LE(v, 1u);
    EXPECT_EQ(deliveries(q)[r.index(32, 64)], 1u);
    const frame f = golden_cell_frame(q, k, dev, plan_config{});
    EXPECT_EQ(f.px, per_pixel_frame(r, k, dev).px);
    EXPECT_EQ(f.covered, per_pixel_frame(r, k, dev).covered);

    const cell_counts n = cell_ops(r, q, dev, k.n, false);
    EXPECT_EQ(n.stepping.triangle_setups, 2u);
    EXPECT_EQ(n.stepping.run_starts, 2u);
    EXPECT_EQ(n.stepping.steps, 15u);
    EXPECT_EQ(n.geometry.mul, 372u);
    EXPECT_EQ(n.geometry.div, 34u);
    EXPECT_EQ(n.geometry.sqrt, 34u);
    const stepped_count across = stepped_geometry(r, q.points, false);  // no column flags
    EXPECT_EQ(across.ops.mul, 372u + 90u);
    EXPECT_EQ(across.stats.run_starts, 17u);
    // An edge walker holds one triangle at a time here (the upper one's points all come first); top,
    // bottom, top again holds both.
    EXPECT_EQ(walker_live_triangles(r, q.points), 1u);
    EXPECT_EQ(walker_live_triangles(r, {q.points[0], q.points[16], q.points[1]}), 2u);
    EXPECT_THROW(walker_live_triangles(r, {{0u, 0u}}), std::invalid_argument);
}

bool same_jobs(const std::vector<interval_job>& a, const std::vector<interval_job>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].y != b[i].y || a[i].x0 != b[i].x0 || a[i].len != b[i].len || a[i].m != b[i].m ||
            a[i].deg2 != b[i].deg2 || a[i].s != b[i].s)
            return false;
    return true;
}

class GoldenCellsHead : public ::testing::Test {
protected:
    const frame_setup head{"head", SHADING_SOURCE_DIR, 512, "squared", false};
    const scene::rasterised& r = head.r;
    plan_config cfg() const {
        plan_config c;
        c.eval = evaluator::fd;
        return c;
    }
    cell_config at(double tol) const {
        cell_config t;
        t.tol = tol;
        return t;
    }
};

// make_plan with a map of taken pixels: an empty map plans as make_plan does; a taken block ends the
// segments around it, no job covers it and every other covered pixel is still some job's, once.
TEST_F(GoldenCellsHead, PlannerLeavesTakenPixels) {
    plan_config c = cfg();
    c.length = length_policy::adaptive;
    c.split_at_check = true;
    const plan whole = make_plan(r, head.k, head.dev, c);
    EXPECT_TRUE(same_jobs(make_plan(r, head.k, head.dev, c, std::vector<uint8_t>(r.tri.size(), 0)).jobs, whole.jobs));
    EXPECT_EQ(whole.points.size(), whole.geometry_points);
    std::vector<uint8_t> taken(r.tri.size(), 0);
    for (unsigned y = 200; y < 264; ++y)
        for (unsigned x = 230; x < 290; ++x) taken[r.index(x, y)] = 1;
    const plan p = make_plan(r, head.k, head.dev, c, taken);
    std::vector<unsigned> n(r.tri.size(), 0);
    for (const interval_job& j : p.jobs)
        for (unsigned i = 0; i < j.len; ++i) ++n[r.index(j.x0 + i, j.y)];
    std::size_t taken_covered = 0;
    for (std::size_t i = 0; i < n.size(); ++i) {
        if (taken[i]) {
            EXPECT_EQ(n[i], 0u);
            taken_covered += r.tri[i] >= 0;
        } else {
            EXPECT_EQ(n[i], r.tri[i] >= 0 ? 1u : 0u);
        }
    }
    EXPECT_GT(taken_covered, 3000u);  // the block lies on the face
    for (const auto& q : p.points) EXPECT_FALSE(taken[r.index(q[0], q[1])]);
    EXPECT_THROW(make_plan(r, head.k, head.dev, c, std::vector<uint8_t>(5, 0)), scene::scene_error);
}

// On the head at 512 at T = 0.89: every covered pixel delivered once; the points distinct and
// covered, those inside cells per-pixel shading's colour there (and no other point outside a job);
// the pipeline's part is the jobs and those points; the bookkeeping adds up; against per-pixel
// shading through the device the NMSE is within the target's 1e-5; counted with edges walked (where
// the order is free) the long operations are at least 3x fewer than the scan-line Phong's.
TEST_F(GoldenCellsHead, FrameAndTarget) {
    const cell_plan p = make_cell_plan(r, head.k, head.dev, cfg(), at(0.89));
    const std::vector<unsigned> n = deliveries(p);
    for (std::size_t i = 0; i < n.size(); ++i) ASSERT_EQ(n[i], r.tri[i] >= 0 ? 1u : 0u) << i;
    for (const interval_job& j : p.jobs) EXPECT_TRUE(interval_valid(j));
    for (const interval_job& j : p.column_jobs) EXPECT_TRUE(interval_valid(j));
    EXPECT_EQ(p.pixels, head.pixels);
    EXPECT_EQ(p.pixels_cells + p.pixels_columns + p.pixels_rows, p.pixels);
    EXPECT_GT(p.pixels_columns, 1000u);  // the strips beside the silhouette
    EXPECT_EQ(p.point_down.size(), p.points.size());
    std::set<std::pair<unsigned, unsigned>> once;
    for (const auto& q : p.points) {
        ASSERT_TRUE(r.covered(q[0], q[1]));
        once.insert({q[0], q[1]});
    }
    EXPECT_EQ(once.size(), p.points.size());
    const frame f = golden_cell_frame(p, head.k, head.dev, cfg());
    std::vector<uint8_t> in_cell(r.tri.size(), 0);
    for (const cell_job& c : p.cells)
        for (unsigned y = c.y0; y < c.y0 + c.s; ++y)
            for (unsigned x = c.x0; x < c.x0 + c.s; ++x) in_cell[r.index(x, y)] = 1;
    std::size_t cell_points = 0;
    for (const auto& q : p.points)
        if (in_cell[r.index(q[0], q[1])]) {
            EXPECT_EQ(f.px[r.index(q[0], q[1])], head.per_pixel.px[r.index(q[0], q[1])]);
            ++cell_points;
        }
    EXPECT_EQ(point_jobs(p).size(), cell_points);  // the points no job covers are the cells' own
    const plan pp = pipeline_plan(p);
    EXPECT_EQ(pp.jobs.size(), p.jobs.size() + p.column_jobs.size() + cell_points);
    EXPECT_EQ(pp.width, 512u);
    EXPECT_EQ(pp.height, 1024u);
    // Its frame buffer, the stacked part folded back, is the scheme's frame but for the cells' pixels
    // that are no point (the cell unit's).
    std::vector<uint8_t> pointed(r.tri.size(), 0);
    for (const interval_job& j : point_jobs(p)) pointed[r.index(j.x0, j.y)] = 1;
    frame piped = f;
    for (std::size_t i = 0; i < piped.px.size(); ++i)
        if (in_cell[i] && !pointed[i]) piped.px[i] = rgb_codes{};
    EXPECT_EQ(cells_frame_of(p, golden_frame(pp, head.k, head.dev, cfg())).px, piped.px);
    EXPECT_THROW(cells_frame_of(p, f), scene::scene_error);  // a frame of the wrong size
    const std::size_t cell_pixels_total = std::size_t(std::count(in_cell.begin(), in_cell.end(), uint8_t(1)));
    EXPECT_EQ(pp.pixels, p.pixels - cell_pixels_total + cell_points);
    EXPECT_EQ(f.covered, head.per_pixel.covered);
    const error_stats e = compare(to_image(f), to_image(head.per_pixel));
    EXPECT_LE(e.nmse, 1e-5);
    EXPECT_GT(e.nmse, 1e-6);  // an interpolation, not a copy

    // Walked in the scheme's order the walker jumps (a multiplication by a small integer per jump,
    // scanline.h), dearer than the additions of raster order.
    const cell_counts walked = cell_ops(r, p, head.dev, head.k.n, true);
    EXPECT_GT(walked.long_ops(), cell_ops(r, p, head.dev, head.k.n, true, true).long_ops());
    EXPECT_EQ(walked.colours.long_ops(), colour_sample_ops(head.dev, head.k.n).long_ops() * p.points.size());
    // At least 2.5x fewer long operations than the edge-walking Phong 1975 (2.78x measured).
    const frame_setup walk{"head", SHADING_SOURCE_DIR, 512, "squared", true};
    EXPECT_GE(walk.scanline / (walked.long_ops() / double(p.pixels)), 2.5);
    // Not walked, the scheme's order starts more runs than raster order.
    EXPECT_GT(cell_ops(r, p, head.dev, head.k.n, false).long_ops(), cell_ops(r, p, head.dev, head.k.n, false, true).long_ops());
}

TEST(GoldenCells, BadInputRefused) {
    auto with = [](auto change) {
        cell_config t;
        change(t);
        return t;
    };
    EXPECT_NO_THROW(validate(cell_config{}));
    EXPECT_THROW(validate(with([](auto& t) { t.s_min = 8; })), scene::scene_error);
    EXPECT_THROW(validate(with([](auto& t) { t.s_max = 128; })), scene::scene_error);
    EXPECT_THROW(validate(with([](auto& t) { t.s_max = 24; })), scene::scene_error);
    EXPECT_THROW(validate(with([](auto& t) { t.tol = 0.0; })), scene::scene_error);
    EXPECT_THROW(validate(with([](auto& t) { t.d2_factor = std::nan(""); })), scene::scene_error);
    EXPECT_THROW(validate(with([](auto& t) { t.line_m_max = 7; })), scene::scene_error);
    EXPECT_THROW(validate(with([](auto& t) { t.column_ratio = -1.0; })), scene::scene_error);
    EXPECT_THROW(validate(with([](auto& t) { t.column_ratio = std::nan(""); })), scene::scene_error);
    EXPECT_NO_THROW(validate(with([](auto& t) { t.column_ratio = 0.0; })));
    EXPECT_THROW(cell_pixels({}, 3, evaluator::fd), scene::scene_error);
    EXPECT_THROW(cell_pixels({}, 128, evaluator::fd), scene::scene_error);
    EXPECT_TRUE(quadratic_pixels({}, 0, 1, evaluator::fd).empty());
    EXPECT_TRUE(quadratic_pixels({}, 2, 5, evaluator::fd).empty());
    cell_plan bad;
    bad.width = bad.height = 4;
    bad.points.push_back({1, 1});
    EXPECT_THROW(golden_cell_frame(bad, frame_constants{}, scene::device_config{}, plan_config{}), scene::scene_error);
}

}  // namespace

}  // namespace test_golden_cells
