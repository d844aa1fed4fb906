// The cells' geometry-side stores (modules/pipeline/cell_stores.h) against the golden cell planner's
// worst case (src/golden_pipeline/cells.h, the race's frozen configuration): the capacities of
// formats/cell_store_formats.h are the most the plans of our scenes need, rounded up as stated there
// (the head, the sphere, make_test_obj's blob and cluster of 64 segments written at test time, at
// 512 and 1024); on each scene a replay of the geometry side's writes (cell_store_replay.h) reads
// every word back as written with no overflow; with a smaller capacity the overflow flag and the
// report fire and the lost words are seen. One elaboration per test (gtest_discover_tests).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "core/report_ids.h"
#include "golden_pipeline/frame_setup.h"
#include "golden_pipeline/race.h"
#include "scene/scanline.h"
#include "scene/scheme_state.h"
#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/pipeline/cell_store_replay.h"
#include "testbenches/scene/test_obj.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_cell_stores {

using namespace shading;

// A scene of ours at a size, its cell plan with the race's frozen configuration, what its stores need.
struct planned {
    std::unique_ptr<pipeline::frame_setup> f;
    pipeline::cell_plan p;
    unsigned words = 0;          // a triangle's stepped words
    std::size_t live = 0;        // pipeline::walker_live_triangles over the plan's points
    unsigned band_lines = 0;     // the most lines from a band's top to a cell's lowest lattice line, plus one
};

// "head" and "sphere" are built in; "blob" and "cluster" are written as OBJ files first (make_test_obj's
// shapes, 64 segments, as the race's OBJ tests).
planned plan_of(const std::string& scene, unsigned size) {
    std::string name = scene;
    if (scene == "blob" || scene == "cluster") {
        name = (std::filesystem::temp_directory_path() / ("shading_test_cell_stores_" + scene + ".obj")).string();
        EXPECT_TRUE(tb::test_obj::write_obj(tb::test_obj::make_shape(scene, 64), name, "test_cell_stores"));
    }
    planned out;
    out.f = std::make_unique<pipeline::frame_setup>(name, SHADING_SOURCE_DIR, size, "sqmul", true);
    if (name != scene) std::filesystem::remove(name);
    const pipeline::race_config c = pipeline::frozen_race_config();
    out.p = pipeline::make_cell_plan(out.f->r, out.f->k, out.f->dev, c.cell_lines, c.cells);
    out.words = scene::span_stepper(out.f->r).words_per_triangle();
    out.live = pipeline::walker_live_triangles(out.f->r, out.p.points);
    for (const auto& cell : out.p.cells)
        out.band_lines = std::max(out.band_lines, cell.y0 + cell.s - cell.y0 / c.cells.s_max * c.cells.s_max + 1);
    return out;
}

struct scene_case {
    const char* scene;
    unsigned size;
};
const scene_case ours[] = {{"head", 512}, {"head", 1024}, {"sphere", 512}, {"sphere", 1024},
                           {"blob", 512}, {"blob", 1024}, {"cluster", 512}, {"cluster", 1024}};

tb::cell_store_replay& replay(const planned& pl, unsigned slots, unsigned lines) {
    const unsigned s_max = pipeline::frozen_race_config().cells.s_max;
    auto* b = new tb::cell_store_replay("tb", tb::make_store_schedule(pl.f->r, pl.p, pl.words, s_max), pl.f->r.width,
                                        slots, lines);
    const std::size_t ops = b->schedule().walker.size() + b->schedule().band.size();
    EXPECT_TRUE(tb::run_to_completion(*b, sc_core::sc_time(20.0 * double(ops + 100), sc_core::SC_NS)));
    return *b;
}

// The format header's capacities against the plans: the most live triangles over our scenes is the
// figure cell_store_formats.h states (1492, the cluster at 1024) and fits its 2^11 slots but not
// 2^10; every scene's plan needs 33 band lines (s_max + 1: 32-pixel cells at a band's top), and a
// triangle's words fit a slot's 2^5 words of scene::state_word_bits.
TEST(CellStores, CapacitiesAreTheWorstCaseOfOurScenes) {
    std::size_t most = 0;
    unsigned lines = 0, words = 0;
    for (const scene_case& c : ours) {
        const planned pl = plan_of(c.scene, c.size);
        std::printf("%s at %u: %zu points, %zu cells, %zu live triangles x %u words, %u band lines\n", c.scene, c.size,
                    pl.p.points.size(), pl.p.cells.size(), pl.live, pl.words, pl.band_lines);
        most = std::max(most, pl.live);
        lines = std::max(lines, pl.band_lines);
        words = std::max(words, pl.words);
    }
    EXPECT_EQ(most, 1492u) << "the figure cell_store_formats.h states";
    EXPECT_LE(most, std::size_t(pipeline::walker_slots));
    EXPECT_GT(most, std::size_t(pipeline::walker_slots / 2)) << "a power of two fewer would do";
    EXPECT_EQ(pipeline::walker_slots, 2048u);
    EXPECT_EQ(lines, 33u);
    EXPECT_EQ(pipeline::band_lines, lines);
    EXPECT_EQ(pipeline::frozen_race_config().cells.s_max + 1, pipeline::band_lines);
    EXPECT_EQ(words, 28u) << "4 x (3 + 3 + 1): the perspective camera's stepped values";
    EXPECT_LE(words, 1u << pipeline::walker_word_bits);
    EXPECT_EQ(pipeline::walker_word_width, scene::state_word_bits);
}

class CellStoresReplay : public ::testing::TestWithParam<scene_case> {};

// Every word the geometry side writes read back as written, no overflow, on every scene of ours.
TEST_P(CellStoresReplay, EveryWordBackNoOverflow) {
    const planned pl = plan_of(GetParam().scene, GetParam().size);
    auto& b = replay(pl, pipeline::walker_slots, pipeline::band_lines);
    const auto& s = b.schedule();
    EXPECT_EQ(s.slots_used, pl.live) << "the lowest free slot: as many slots as triangles live at once";
    EXPECT_EQ(s.lines_used, pl.band_lines);
    EXPECT_GT(b.walker_counts.reads, 1000u);
    EXPECT_EQ(b.walker_counts.writes, b.walker_counts.reads) << "each triangle's words written once, read once";
    EXPECT_EQ(b.walker_counts.mismatches, 0u);
    EXPECT_EQ(b.band_counts.writes, 9 * pl.p.cells.size());
    EXPECT_EQ(b.band_counts.reads, 9 * pl.p.cells.size());
    EXPECT_EQ(b.band_counts.mismatches, 0u);
    EXPECT_FALSE(b.wp.overflow.read());
    EXPECT_FALSE(b.bp.overflow.read());
    EXPECT_EQ(b.walker.bits(), 2048u * 32u * 32u);
    EXPECT_EQ(b.band.bits(), 33ull * pl.f->r.width * 48u) << "our frames' widths are powers of two";
}

INSTANTIATE_TEST_SUITE_P(Ours, CellStoresReplay, ::testing::ValuesIn(ours),
                         [](const ::testing::TestParamInfo<scene_case>& i) {
                             return std::string(i.param.scene) + std::to_string(i.param.size);
                         });

// The head at 512 needs 824 slots: given 512, the triangles in slots 512 and above are dropped,
// flagged and reported, and their words do not come back; the band buffer is not touched.
TEST(CellStoresOverflow, TooFewWalkerSlotsFlagAndReport) {
    tb::report_log::get().expect(msg::input);
    const planned pl = plan_of("head", 512);
    ASSERT_GT(pl.live, 512u);
    auto& b = replay(pl, 512, pipeline::band_lines);
    EXPECT_TRUE(b.wp.overflow.read());
    EXPECT_GT(b.walker_counts.mismatches, 0u);
    EXPECT_GT(tb::report_log::get().count(msg::input), 0u);
    EXPECT_FALSE(b.bp.overflow.read());
    EXPECT_EQ(b.band_counts.mismatches, 0u);
}

// 17 band lines: lattice lines 17 and more below a band's top (a 32-pixel cell's bottom row, the lower
// 16-pixel cells' middle and bottom rows, ...) are beyond them: flagged, reported, lost.
TEST(CellStoresOverflow, TooFewBandLinesFlagAndReport) {
    tb::report_log::get().expect(msg::input);
    const planned pl = plan_of("head", 512);
    auto& b = replay(pl, pipeline::walker_slots, 17);
    EXPECT_TRUE(b.bp.overflow.read());
    EXPECT_GT(b.band_counts.mismatches, 0u);
    EXPECT_GT(tb::report_log::get().count(msg::input), 0u);
    EXPECT_FALSE(b.wp.overflow.read());
    EXPECT_EQ(b.walker_counts.mismatches, 0u);
}

}  // namespace test_cell_stores
