// The cell unit's Verilog twin (rtl/pipeline/cell_unit.v, verilated with --sc) co-simulated with the
// SystemC cell unit (modules/pipeline/cell_unit.h) on the same input pins and clock, driven by the
// cell unit's own bench parts (testbenches/pipeline/cell_unit_bench.h): cell_stimulus presents the
// cells, one frame_buffer and cell_checker per unit hold every pixel to the golden model's
// cell_pixels, and pipeline_pair.h's pin_comparator compares every output of the two at every edge
// (ready at every edge, px_valid / px_x / px_y at rising edges, px_r/g/b where px_valid = 1). Random
// full-range lattices in cells of every size (clamps included), in size order and shuffled (a cell of
// one size after another of any size), the head's planned cells at 256, and the sizes outside
// 2^2..2^6, taken as the nearest. The negative test wires one lattice pin of the RTL to another
// lattice position: the comparison must see it. One elaboration per test (gtest_discover_tests runs
// each in its own process).
// SHADING_TRACE=<dir>: <dir>/<Suite.Test>.vcd (the bench's SystemC signals, the model's nets) and
// <dir>/<Suite.Test>_rtl.vcd (every net inside the RTL).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/report_ids.h"
#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/pipeline/cell_unit_bench.h"
#include "testbenches/pipeline/pipeline_pair.h"
#include "testbenches/rtl/rtl_cosim_tb.h"
#include "verilated.h"

// The verilated cell unit (testbenches/rtl/cell.cmake).
#include "Vrtl_cell_unit.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_rtl_cell_unit {

using namespace shading;
using tb::cell_input;

namespace {

using sample_t = pipeline::sample_t;

// The SystemC cell unit (`dut`) and the RTL (`rtl`) on the same input signals and clock, each with its
// frame buffer and checker; the stimulus follows the model's ready (the comparator holds the RTL's to
// it). miswire: the RTL's in_lat_r_4 (the lattice centre) reads in_lat_r_0's signal.
class cell_pair_bench : public sc_core::sc_module {
public:
    using coord_t = cell_unit::coord_t;
    // One unit's outputs, named <pin>_<side> in a trace (side b: the SystemC model, o: the RTL).
    struct outs {
        explicit outs(const std::string& side)
            : ready(("ready_" + side).c_str()), valid(("px_valid_" + side).c_str()), x(("px_x_" + side).c_str()),
              y(("px_y_" + side).c_str()), r(("px_r_" + side).c_str()), g(("px_g_" + side).c_str()),
              b(("px_b_" + side).c_str()) {}
        sc_core::sc_signal<bool> ready, valid;
        sc_core::sc_signal<coord_t> x, y;
        sc_core::sc_signal<sample_t> r, g, b;
    };

    sc_core::sc_clock clk{"clk", tb::cell_period()};
    sc_core::sc_signal<bool> start{"start"};
    sc_core::sc_signal<coord_t> x0{"x0"}, y0{"y0"};
    sc_core::sc_signal<cell_unit::m_t> m{"m"};
    sc_core::sc_vector<sc_core::sc_signal<sample_t>> lat_r{"lat_r", 9}, lat_g{"lat_g", 9}, lat_b{"lat_b", 9};
    outs ob{"b"}, oo{"o"};

    tb::cell_stimulus src;
    cell_unit dut{"dut"};
    Vrtl_cell_unit rtl{"rtl"};
    frame_buffer fb_b, fb_o;
    tb::cell_checker chk_b, chk_o;
    pipeline::pin_comparator cmp{"cmp"};

    cell_pair_bench(const sc_core::sc_module_name& name, const std::vector<cell_input>& cells, unsigned width,
                    unsigned height, bool miswire = false)
        : sc_module(name), src("src", cells), fb_b("fb_b", width, height), fb_o("fb_o", width, height),
          chk_b(cells, width, height), chk_o(cells, width, height) {
        src.clk(clk); src.ready(ob.ready); src.start(start); src.x0(x0); src.y0(y0); src.m(m);
        for (std::size_t i = 0; i < 9; ++i) {
            src.lat_r[i](lat_r[i]); src.lat_g[i](lat_g[i]); src.lat_b[i](lat_b[i]);
            dut.in_lat_r[i](lat_r[i]); dut.in_lat_g[i](lat_g[i]); dut.in_lat_b[i](lat_b[i]);
        }
        dut.clk(clk); dut.start(start); dut.in_x0(x0); dut.in_y0(y0); dut.in_m(m);
        dut.ready(ob.ready); dut.px_valid(ob.valid); dut.px_x(ob.x); dut.px_y(ob.y);
        dut.px_r(ob.r); dut.px_g(ob.g); dut.px_b(ob.b);
        rtl.clk(clk); rtl.start(start); rtl.in_x0(x0); rtl.in_y0(y0); rtl.in_m(m);
        bind_lattice(rtl_lattice_r(), lat_r);
        bind_lattice(rtl_lattice_g(), lat_g);
        bind_lattice(rtl_lattice_b(), lat_b);
        if (miswire) rtl.in_lat_r_4(lat_r[0]);
        else rtl.in_lat_r_4(lat_r[4]);
        rtl.ready(oo.ready); rtl.px_valid(oo.valid); rtl.px_x(oo.x); rtl.px_y(oo.y);
        rtl.px_r(oo.r); rtl.px_g(oo.g); rtl.px_b(oo.b);
        monitor(fb_b, ob, chk_b);
        monitor(fb_o, oo, chk_o);
        cmp.clk(clk);
        cmp.ready_b(ob.ready); cmp.ready_o(oo.ready); cmp.valid_b(ob.valid); cmp.valid_o(oo.valid);
        cmp.x_b(ob.x); cmp.x_o(oo.x); cmp.y_b(ob.y); cmp.y_o(oo.y);
        cmp.px_b[0](ob.r); cmp.px_b[1](ob.g); cmp.px_b[2](ob.b);
        cmp.px_o[0](oo.r); cmp.px_o[1](oo.g); cmp.px_o[2](oo.b);
    }
    bool finished() const { return src.finished(); }

private:
    using rtl_pin = sc_core::sc_in<sample_t>;
    // The RTL's numbered lattice pins (cell_unit.v: the SystemC vectors in_lat_r/g/b[0..8]); R's
    // centre, in_lat_r_4, is bound on its own (miswire).
    std::array<rtl_pin*, 9> rtl_lattice_r() {
        return {&rtl.in_lat_r_0, &rtl.in_lat_r_1, &rtl.in_lat_r_2, &rtl.in_lat_r_3, nullptr,
                &rtl.in_lat_r_5, &rtl.in_lat_r_6, &rtl.in_lat_r_7, &rtl.in_lat_r_8};
    }
    std::array<rtl_pin*, 9> rtl_lattice_g() {
        return {&rtl.in_lat_g_0, &rtl.in_lat_g_1, &rtl.in_lat_g_2, &rtl.in_lat_g_3, &rtl.in_lat_g_4,
                &rtl.in_lat_g_5, &rtl.in_lat_g_6, &rtl.in_lat_g_7, &rtl.in_lat_g_8};
    }
    std::array<rtl_pin*, 9> rtl_lattice_b() {
        return {&rtl.in_lat_b_0, &rtl.in_lat_b_1, &rtl.in_lat_b_2, &rtl.in_lat_b_3, &rtl.in_lat_b_4,
                &rtl.in_lat_b_5, &rtl.in_lat_b_6, &rtl.in_lat_b_7, &rtl.in_lat_b_8};
    }
    static void bind_lattice(const std::array<rtl_pin*, 9>& pins,
                             sc_core::sc_vector<sc_core::sc_signal<sample_t>>& lat) {
        for (std::size_t i = 0; i < 9; ++i)
            if (pins[i] != nullptr) (*pins[i])(lat[i]);
    }
    void monitor(frame_buffer& fb, outs& o, tb::cell_checker& chk) {
        fb.clk(clk); fb.valid(o.valid); fb.x(o.x); fb.y(o.y); fb.r(o.r); fb.g(o.g); fb.b(o.b);
        fb.on_write([&chk](unsigned x, unsigned y, const frame_buffer::rgb& v) { chk.on_write(x, y, v); });
    }
};

// Cells of every size m_min..m_max, per_size of each with lattices over the whole code range, each
// size in a band of the frame (cells side by side); shuffled: presented in a random order, so a
// cell of any size follows one of any other.
struct cell_set {
    std::vector<cell_input> cells;
    unsigned width = 0, height = 0;
};
cell_set random_cells(uint32_t seed, unsigned per_size, bool shuffled) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<uint64_t> code(0, 0xFFFF);
    cell_set out;
    for (unsigned m = interp::m_min; m <= interp::m_max; ++m) {
        for (unsigned k = 0; k < per_size; ++k) {
            cell_input c;
            c.x0 = k << m;
            c.y0 = out.height;
            c.m = m;
            for (auto& v : c.lattice) v = {code(rng), code(rng), code(rng)};
            out.cells.push_back(c);
        }
        out.height += 1u << m;
    }
    out.width = per_size << interp::m_max;
    if (shuffled) std::shuffle(out.cells.begin(), out.cells.end(), rng);
    return out;
}

// Clocks a run is given before it counts as hung: twice each cell's s^2 + s + 16 (test_cell_unit's).
sc_core::sc_time watchdog(const std::vector<cell_input>& cells) {
    uint64_t clocks = 100;
    for (const cell_input& c : cells) {
        const unsigned m = std::clamp(c.m, interp::m_min, interp::m_max);
        clocks += 2 * ((1ull << (2 * m)) + (1ull << m) + 16);
    }
    return tb::cell_period() * static_cast<double>(clocks);
}

// Runs the pair to its end (the bench stays elaborated: SystemC cannot tear a design down); with
// SHADING_TRACE=<dir> it writes the test's two VCDs.
cell_pair_bench& run_pair(const cell_set& s, bool miswire = false) {
    Verilated::traceEverOn(true);
    auto* bench = new cell_pair_bench("tb", s.cells, s.width, s.height, miswire);
    const char* dir = std::getenv("SHADING_TRACE");
    const std::string stem = dir && *dir ? std::string(dir) + "/" + tb::current_test_name() : std::string();
    EXPECT_TRUE(tb::run_cosim(*bench, watchdog(s.cells), stem));
    std::printf("%zu cells: %zu pins compared over %zu edges, %zu differences; %zu pixels (RTL)\n", s.cells.size(),
                bench->cmp.valid_edges(), bench->cmp.edges(), bench->cmp.differences(), bench->fb_o.writes());
    return *bench;
}

// Every pin the same at every edge, every pixel of both the golden model's, each written once, the
// rows back to back (s^2 - 1 clocks from a cell's first pixel to its last) on both sides.
void expect_same(const cell_pair_bench& b, const cell_set& s) {
    std::size_t pixels = 0;
    for (const cell_input& c : s.cells) {
        const unsigned m = std::clamp(c.m, interp::m_min, interp::m_max);
        pixels += std::size_t(1) << (2 * m);
    }
    EXPECT_EQ(b.cmp.differences(), 0u);
    EXPECT_EQ(b.cmp.valid_edges(), pixels);
    EXPECT_EQ(b.dut.ctl.cells(), s.cells.size());
    for (const tb::cell_checker* chk : {&b.chk_b, &b.chk_o}) {
        EXPECT_EQ(chk->mismatches(), 0u);
        EXPECT_EQ(chk->stray(), 0u);
    }
    EXPECT_EQ(b.chk_b.not_once(b.fb_b), 0u);
    EXPECT_EQ(b.chk_o.not_once(b.fb_o), 0u);
    EXPECT_EQ(b.fb_o.writes(), pixels);
    for (std::size_t k = 0; k < s.cells.size(); ++k) {
        const uint64_t side = 1ull << std::clamp(s.cells[k].m, interp::m_min, interp::m_max);
        ASSERT_TRUE(b.chk_o.span(k).has_value()) << k;
        EXPECT_EQ(*b.chk_o.span(k), side * side - 1) << k;
        EXPECT_EQ(b.chk_o.span(k), b.chk_b.span(k)) << k;
    }
}

}  // namespace

// Three cells of each size, in size order (test_cell_unit's set, another seed).
TEST(RtlCellUnit, RandomLatticesEverySize) {
    const cell_set s = random_cells(20261205, 3, false);
    expect_same(run_pair(s), s);
}

// Four cells of each size in a random order: every hand-over from one size to another.
TEST(RtlCellUnit, RandomLatticesShuffled) {
    const cell_set s = random_cells(7, 4, true);
    expect_same(run_pair(s), s);
}

// The cells the bit-accurate plan sends on the head at 256 (squared device), with the lattice colours
// the sample stage forms: real cells, back to back in the planner's order.
TEST(RtlCellUnit, HeadPlanCells) {
    const tb::head_cells h(256, SHADING_SOURCE_DIR);
    ASSERT_GT(h.p.cells.size(), 20u);
    cell_set s;
    s.cells = tb::cell_inputs(h.p, h.k, h.dev);
    s.width = h.r.width;
    s.height = h.r.height;
    expect_same(run_pair(s), s);
}

// m = 0, 1 and 7 are no cell sizes: the model reports them (shading/input) and takes 2^2, 2^2 and
// 2^6; the RTL takes the same, with no report.
TEST(RtlCellUnit, BadSizesTakenAsTheNearest) {
    tb::report_log::get().expect(msg::input);
    cell_set s = random_cells(11, 1, false);
    s.cells.resize(2);  // one 4 x 4 and one 8 x 8 cell, at rows 0 and 4
    s.cells[0].m = 0;
    s.cells[1].m = 1;
    s.cells[1].x0 = 8;
    s.cells[1].y0 = 0;
    cell_input big = s.cells[0];
    big.m = 7;
    big.x0 = 0;
    big.y0 = 4;
    s.cells.push_back(big);
    s.width = 64;
    s.height = 68;
    auto& b = run_pair(s);
    EXPECT_EQ(tb::report_log::get().count(msg::input), 3u);
    expect_same(b, s);
}

// The comparison can fail: the RTL's lattice centre of channel R wired to the corner's signal.
TEST(RtlCellUnitVerdict, MiswiredLatticePinIsSeen) {
    tb::report_log::get().expect(msg::mismatch);  // the RTL's checker
    const cell_set s = random_cells(5, 1, false);
    auto& b = run_pair(s, true);
    EXPECT_GT(b.cmp.differences(), 0u);
    EXPECT_EQ(b.chk_b.mismatches(), 0u);  // the model against the golden model
    EXPECT_GT(b.chk_o.mismatches(), 10u);  // the RTL against it
}

}  // namespace test_rtl_cell_unit
