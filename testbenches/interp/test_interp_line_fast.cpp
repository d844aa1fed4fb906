// The fast pin-level raster-line interpolator (interp/interp_line_unit_fast.h): alone in the line
// bench against the golden model (random intervals of every length, back to back and with gaps), and
// side by side with the block-level interp_line_unit on the same pins, valid / last / ready / i_px
// compared at every rising edge. One elaboration per test (its own process).
#include <gtest/gtest.h>

#include <cstdio>

#include "testbenches/common/pin_compare.h"
#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/interp/interp_line_bench.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_interp_line_fast {

using namespace shading;
using namespace shading::tb;
using interp::div3_mode;
using interp::sample_set;

namespace {

const sc_core::sc_time limit(1, sc_core::SC_SEC);

template <unsigned M, sample_set SET, div3_mode DIV>
void run_alone(std::size_t pixels, uint64_t seed, unsigned gap) {
    line_bench<M, SET, DIV, interp_line_unit_fast<M, SET, DIV>> bench("tb", random_line_intervals<M>(pixels, seed), gap);
    bench.checker.keep_samples(false);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.checked(), pixels);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
}

template <unsigned M, sample_set SET, div3_mode DIV>
class line_pair_bench : public sc_core::sc_module {
public:
    using len_t = typename fd_ctrl<M>::len_t;
    sc_core::sc_clock clk{"clk", interp_period()};
    sc_core::sc_signal<bool> start{"start"}, valid_b{"valid_b"}, last_b{"last_b"}, ready_b{"ready_b"},
        valid_f{"valid_f"}, last_f{"last_f"}, ready_f{"ready_f"};
    sc_core::sc_signal<len_t> len{"len"};
    sc_core::sc_signal<sample_t> i1{"i1"}, i2{"i2"}, i3{"i3"}, i4{"i4"};
    sc_core::sc_signal<coef_t> px_b{"px_b"}, px_f{"px_f"};
    interp_line_unit<M, SET, DIV> blk{"blk"};
    interp_line_unit_fast<M, SET, DIV> fst{"fst"};
    line_stimulus<M> stim;
    tb::pin_compare cmp{"cmp"};

    line_pair_bench(const sc_core::sc_module_name& name, item_source<interp::interval_samples> ivs, unsigned gap)
        : sc_module(name), stim("stim", std::move(ivs), gap) {
        blk.clk(clk); blk.start(start); blk.len(len); blk.i1(i1); blk.i2(i2); blk.i3(i3); blk.i4(i4);
        blk.i_px(px_b); blk.valid(valid_b); blk.last(last_b); blk.ready(ready_b);
        fst.clk(clk); fst.start(start); fst.len(len); fst.i1(i1); fst.i2(i2); fst.i3(i3); fst.i4(i4);
        fst.i_px(px_f); fst.valid(valid_f); fst.last(last_f); fst.ready(ready_f);
        stim.clk(clk); stim.ready(ready_b); stim.valid(valid_b); stim.last(last_b);
        stim.start(start); stim.len(len); stim.i1(i1); stim.i2(i2); stim.i3(i3); stim.i4(i4);
        cmp.clk(clk);
        cmp.pair("valid", valid_b, valid_f);
        cmp.pair("last", last_b, last_f);
        cmp.pair("ready", ready_b, ready_f);
        cmp.pair("i_px", px_b, px_f, &valid_b);
        cmp.count(valid_b);
    }
    bool finished() const { return stim.finished(); }
};

template <unsigned M, sample_set SET, div3_mode DIV>
void run_pair(std::size_t pixels, uint64_t seed, unsigned gap) {
    line_pair_bench<M, SET, DIV> bench("tb", random_line_intervals<M>(pixels, seed), gap);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.cmp.differences(), 0u);
    EXPECT_EQ(bench.cmp.counted(), pixels);
}

}  // namespace

TEST(InterpLineFast, BackToBackCase1ShiftAdd) { run_alone<5, sample_set::case1, div3_mode::shift_add>(20000, 71, 0); }
TEST(InterpLineFast, WithGapsCase2Exact) { run_alone<3, sample_set::case2, div3_mode::exact>(5000, 72, 2); }
TEST(InterpLineFastPins, SameAsBlockLevelBackToBack) { run_pair<4, sample_set::case1, div3_mode::exact>(3000, 73, 0); }
TEST(InterpLineFastPins, SameAsBlockLevelWithGaps) { run_pair<2, sample_set::case2, div3_mode::shift_add>(2000, 74, 3); }

}  // namespace test_interp_line_fast
