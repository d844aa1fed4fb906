// The bit-accurate cells (src/golden_pipeline/cells.h) against the real-valued emulation (cell_tree.h,
// a separate implementation) on the head at 512: the same cell decisions. The cells' own tests are
// testbenches/pipeline/test_golden_cells.cpp.
#include <gtest/gtest.h>

#include "golden_pipeline/cells.h"
#include "cell_tree.h"
#include "study_frame.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_golden_cells_emulation {

namespace {

using namespace shading;
using namespace shading::pipeline;

class GoldenCellsHead : public ::testing::Test {
protected:
    const study::study_frame head{"head", SHADING_SOURCE_DIR, 512, "squared", false};
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

// The cells decide on the sample stage's codes with integer limits; the emulation on the same colours
// in levels with real-valued ones: the same cells are sent. The fallbacks' row quadratics are fixed
// point here, so their checks may differ a little, and the rest goes to the planner, not to the
// emulated policy.
TEST_F(GoldenCellsHead, SameCellsAsTheEmulation) {
    for (double tol : {0.5, 0.9, 2.0}) {
        const cell_plan p = make_cell_plan(r, head.k, head.dev, cfg(), at(tol));
        study::cell_tree_config t;
        t.tol = tol;
        const study::cell_frame e = study::emulate_cells(r, head.colour, plan_config{}, t);
        EXPECT_EQ(p.sent, e.sent) << tol;
        EXPECT_EQ(p.fallback_rows + p.fallback_exact, e.fallback_rows + e.fallback_exact) << tol;
        EXPECT_NEAR(double(p.fallback_exact), double(e.fallback_exact), 0.05 * double(e.fallback_exact) + 2.0) << tol;
        EXPECT_NEAR(double(p.points.size()), double(e.points()), 0.05 * double(e.points())) << tol;
    }
}

}  // namespace

}  // namespace test_golden_cells_emulation
