// The cell unit (modules/pipeline/cell_unit.h) against the golden model's cell_pixels, bit for bit:
// random lattices over the whole code range (clamps included) in cells of every size, each pixel
// written once and a cell's rows streamed back to back (s^2 - 1 clocks from its first pixel to its
// last: one pixel a clock), the cells of the head's bit-accurate plan, the scheme's whole frame with
// the shading pipeline taking the rest, and a bad size reported and taken as the nearest. One
// elaboration per test process.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "cell_unit_bench.h"
#include "flat_square.h"
#include "core/trace.h"
#include "core/report_ids.h"
#include "golden_pipeline/cells.h"
#include "scene/scene.h"
#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/common/vcd_names.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_cell_unit {

namespace {

using namespace shading;
using namespace shading::pipeline;
using tb::cell_input;

// Runs the cells through the unit in a frame of width x height under a watchdog far beyond their
// clocks (sim_guard.h; with SHADING_TRACE=DIR the waveforms go to DIR/<Suite.Test>.vcd). The bench
// stays elaborated: SystemC cannot tear a design down.
tb::cell_unit_bench& run(const std::vector<cell_input>& cells, unsigned width, unsigned height) {
    auto* bench = new tb::cell_unit_bench("tb", cells, width, height);
    uint64_t clocks = 100;
    for (const cell_input& c : cells) clocks += 2 * ((1ull << (2 * c.m)) + (1ull << c.m) + 16);
    EXPECT_TRUE(tb::run_to_completion(*bench, tb::cell_period() * double(clocks)));
    return *bench;
}

// Cells of 4, 8, 16, 32 and 64 pixels side by side (one row of the frame each), three of each size,
// lattices over the whole code range: the biquadratic overshoots and the clamps are exercised.
TEST(CellUnit, RandomLatticesBitExact) {
    std::mt19937 rng(20261204);
    std::uniform_int_distribution<uint64_t> code(0, 0xFFFF);
    std::vector<cell_input> cells;
    unsigned y = 0;
    for (unsigned m = interp::m_min; m <= interp::m_max; ++m) {
        for (unsigned k = 0; k < 3; ++k) {
            cell_input c;
            c.x0 = k << m;
            c.y0 = y;
            c.m = m;
            for (auto& v : c.lattice) v = {code(rng), code(rng), code(rng)};
            cells.push_back(c);
        }
        y += 1u << m;
    }
    auto& b = run(cells, 3u << interp::m_max, y);
    EXPECT_EQ(b.checker.mismatches(), 0u);
    EXPECT_EQ(b.checker.not_once(b.fb), 0u);
    EXPECT_EQ(b.checker.stray(), 0u);
    EXPECT_EQ(b.dut.ctl.cells(), cells.size());
    for (std::size_t k = 0; k < cells.size(); ++k) {
        const uint64_t s = 1ull << cells[k].m;
        ASSERT_TRUE(b.checker.span(k).has_value()) << k;
        EXPECT_EQ(*b.checker.span(k), s * s - 1) << k;
    }
}

// Hand-worked: a ramp of 512 codes a lattice step along x in a 4-pixel cell gives 1000, 1256, 1512,
// 1768 on every row (the golden model's hand-worked case); the unit writes exactly those.
cell_input ramp_cell() {
    cell_input c;
    c.x0 = 4;
    c.y0 = 8;
    c.m = 2;
    const uint64_t v[3] = {1000, 1512, 2024};
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) c.lattice[3 * i + j] = {v[j], v[j], v[j]};
    return c;
}

TEST(CellUnit, RampByHand) {
    auto& b = run({ramp_cell()}, 16, 16);
    EXPECT_EQ(b.checker.mismatches(), 0u);
    const uint16_t want[4] = {1000, 1256, 1512, 1768};
    for (unsigned y = 8; y < 12; ++y)
        for (unsigned x = 4; x < 8; ++x) {
            EXPECT_EQ(b.fb.written(x, y), 1u);
            EXPECT_EQ(b.fb.pixel(x, y)[0], want[x - 4]) << x << "," << y;
        }
    EXPECT_EQ(b.fb.writes(), 16u);
}

// The cells the bit-accurate plan sends on the head at 256: the unit's frame equals the golden
// frame's pixels there, except where a point's own colour replaces the biquadratic's.
TEST(CellUnit, HeadPlanCells) {
    const tb::head_cells h(256, SHADING_SOURCE_DIR);
    const scene::rasterised& r = h.r;
    const cell_plan& p = h.p;
    ASSERT_GT(p.cells.size(), 20u);
    const std::vector<cell_input> cells = tb::cell_inputs(p, h.k, h.dev);
    auto& b = run(cells, r.width, r.height);
    EXPECT_EQ(b.checker.mismatches(), 0u);
    EXPECT_EQ(b.checker.not_once(b.fb), 0u);
    const frame g = golden_cell_frame(p, h.k, h.dev, h.c);
    std::vector<uint8_t> point(r.tri.size(), 0);
    for (const auto& q : p.points) point[r.index(q[0], q[1])] = 1;
    std::size_t compared = 0;
    for (const cell_job& j : p.cells)
        for (unsigned y = j.y0; y < j.y0 + j.s; ++y)
            for (unsigned x = j.x0; x < j.x0 + j.s; ++x) {
                if (point[r.index(x, y)]) continue;
                const auto& v = b.fb.pixel(x, y);
                const rgb_codes& want = g.px[r.index(x, y)];
                ASSERT_TRUE(v[0] == want[0] && v[1] == want[1] && v[2] == want[2]) << x << "," << y;
                ++compared;
            }
    EXPECT_GT(compared, 10000u);
}

// The scheme's whole frame in SystemC, the head at 192: the planned cells through the cell unit, the
// plan's intervals (rows and columns) and the cells' points through the shading pipeline (fd, any m
// per interval), the pipeline's frame buffer folded back over the cell unit's: code for code the
// golden model's frame.
TEST(CellUnit, HeadFrameEndToEnd) {
    const tb::head_cells h(192, SHADING_SOURCE_DIR);
    const cell_plan& p = h.p;
    ASSERT_GT(p.cells.size(), 50u);
    ASSERT_GT(p.jobs.size(), 1000u);
    ASSERT_GT(p.column_jobs.size(), 20u);  // the column runs through the pipeline's stacked frame too
    const tb::cells_run run = tb::simulate_cells(h.r, p, h.k, h.dev, h.c);
    EXPECT_TRUE(run.finished);
    EXPECT_EQ(run.unit_mismatches, 0u);
    EXPECT_EQ(run.pipeline_mismatches, 0u);
    EXPECT_EQ(run.differ, 0u);
    EXPECT_EQ(run.stray, 0u);
    EXPECT_GT(run.unit_clocks, 0u);
    EXPECT_GT(run.pipeline_clocks, 0u);
}

// The flat square at 65: four 32-pixel cells, each s^2 + s + 3 clocks and one of handshake,
// 4 x (1024 + 32 + 4) = 4240 clocks, while the pipeline's part (column 64 down the column, row 64
// along it, 129 pixels) is done long before: the pipeline's bench must not stop the simulation
// until the cell unit has finished. The frame, one colour, is per-pixel shading's.
TEST(CellUnit, FlatSquareUnitOutlastsThePipeline) {
    const tb::flat_frame flat(tb::flat_square(65));
    const scene::rasterised& r = flat.r;
    const frame_constants& k = flat.k;
    const scene::device_config& dev = flat.dev;
    plan_config c;
    c.eval = evaluator::fd;
    c.length = length_policy::adaptive;
    const cell_plan p = make_cell_plan(r, k, dev, c, cell_config{});
    ASSERT_EQ(p.cells.size(), 4u);
    ASSERT_EQ(p.pixels_columns, 65u);
    const tb::cells_run run = tb::simulate_cells(r, p, k, dev, c);
    EXPECT_TRUE(run.finished);
    EXPECT_EQ(run.unit_clocks, 4240u);
    EXPECT_LT(run.pipeline_clocks, 1000u);
    EXPECT_EQ(run.unit_mismatches, 0u);
    EXPECT_EQ(run.pipeline_mismatches, 0u);
    EXPECT_EQ(run.differ, 0u);
    EXPECT_EQ(run.stray, 0u);
    EXPECT_EQ(run.f.px, per_pixel_frame(r, k, dev).px);
}

// m = 7 is no cell size: reported (shading/input) and taken as 2^6; the cell is still delivered.
TEST(CellUnit, BadSizeReported) {
    tb::report_log::get().expect(msg::input);
    cell_input c;
    c.m = 7;
    for (auto& v : c.lattice) v = {4096, 4096, 4096};
    auto& b = run({c}, 64, 64);
    EXPECT_GE(tb::report_log::get().count(msg::input), 1u);
    EXPECT_EQ(b.fb.writes(), 64u * 64u);
    EXPECT_EQ(b.fb.pixel(63, 63)[0], 4096u);
}

// traces/cell_unit.gtkw is hand-written for the VCD this test writes (SHADING_TRACE=traces: to
// traces/cell_unit.vcd, else a temporary folder) of the ramp cell: every net it lists exists, and a
// user sees it at first sight as intended (vcd_names.h, view_problems): dump file beside the view,
// marker inside the opening window and off every edge, every bus a number in its format, the pixel
// stream on top. At the marker pixel (4, 8) is on the stream: 1000 codes, valid.
TEST(CellUnitView, GtkwaveViewMatchesItsVcd) {
    const char* env = std::getenv("SHADING_TRACE");
    const std::string dir = env != nullptr && *env != '\0' ? std::string(env) : ::testing::TempDir();
    auto* bench = new tb::cell_unit_bench("tb", {ramp_cell()}, 16, 16);
    bool px_at_marker = false;
    {
        vcd_file vcd(dir + "/cell_unit");
        vcd.trace(*bench);
        sc_core::sc_start(sc_core::sc_time(177, sc_core::SC_NS));
        px_at_marker = bench->px_valid.read() && bench->px_x.read() == 4 && bench->px_y.read() == 8 &&
                       bench->px_r.read() == 1000;
        sc_core::sc_start(sc_core::sc_time(600, sc_core::SC_NS));
    }
    EXPECT_TRUE(px_at_marker);
    EXPECT_TRUE(bench->finished());
    EXPECT_EQ(bench->checker.mismatches(), 0u);
    const std::string gtkw = tb::source_path("traces/cell_unit.gtkw"), vcd = dir + "/cell_unit.vcd";
    const auto declared = tb::vcd_declared(vcd);
    const auto shown = tb::gtkw_listed(gtkw);
    EXPECT_GE(shown.size(), 30u);
    for (const auto& s : shown) EXPECT_EQ(declared.count(s), 1u) << s << " is in the view but not in the VCD";
    tb::view_formats f;
    for (const char* s : {"tb.px_r", "tb.px_g", "tb.px_b", "tb.lat_r_0", "tb.lat_r_1", "tb.lat_r_2", "tb.dut.ch_r.lat_0",
                          "tb.dut.ch_r.col_px_0", "tb.dut.ch_r.col_px_1", "tb.dut.ch_r.col_px_2", "tb.dut.ch_r.col_rd_0",
                          "tb.dut.ch_r.col_rd_1", "tb.dut.ch_r.col_rd_2"})
        f[s] = interp::sample_fmt;
    for (const char* s : {"tb.px_x", "tb.px_y", "tb.x0", "tb.y0"}) f[s] = qfmt{16, false, 0};
    f["tb.m"] = qfmt{3, false, 0};
    f["tb.dut.wa"] = f["tb.dut.ra"] = qfmt{6, false, 0};
    for (const char* s : {"tb.dut.ch_r.row_a", "tb.dut.ch_r.row_b", "tb.dut.ch_r.row_c"}) f[s] = interp::coef_fmt;
    const auto problems = tb::view_problems(gtkw, vcd, "cell_unit", f,
                                            {"tb.px_valid", "tb.px_x", "tb.px_y", "tb.px_r", "tb.px_g", "tb.px_b"});
    EXPECT_TRUE(problems.empty()) << tb::joined(problems);
}

}  // namespace

}  // namespace test_cell_unit
