// The fast pin-level abstraction of the forward-difference evaluator (interp/fd_eval_fast.h): alone in
// the FD bench against the golden model (every pixel, one per clock, random intervals of every
// length), and side by side with the block-level fd_eval<M> on the same pins, valid / last / i_px
// compared at every rising edge. One elaboration per test (its own process).
#include <gtest/gtest.h>

#include <cstdio>

#include "testbenches/common/pin_compare.h"
#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/interp/interp_fd_bench.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_interp_fd_fast {

using namespace shading;
using namespace shading::tb;

namespace {

const sc_core::sc_time limit(1, sc_core::SC_SEC);

template <unsigned M>
void run_alone(std::size_t pixels, uint64_t seed) {
    fd_bench<M, fd_eval_fast<M>> bench("tb", random_fd_intervals<M>(pixels, seed));
    bench.checker.keep_samples(false);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.checked(), pixels);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_TRUE(bench.checker.within_horner_bound());
    // Pixel k of an interval is on the output k + 1 clocks after its acceptance.
    for (const auto& [k, lat] : bench.checker.latencies()) {
        ASSERT_EQ(lat.size(), 1u);
        EXPECT_EQ(*lat.begin(), (k + 1) * interp_period());
    }
}

// Both units on one stimulus (driven by the block unit's valid / last), outputs compared.
template <unsigned M>
class fd_pair_bench : public sc_core::sc_module {
public:
    using len_t = typename fd_ctrl<M>::len_t;
    sc_core::sc_clock clk{"clk", interp_period()};
    sc_core::sc_signal<bool> start{"start"}, valid_b{"valid_b"}, last_b{"last_b"}, valid_f{"valid_f"}, last_f{"last_f"};
    sc_core::sc_signal<len_t> len{"len"};
    sc_core::sc_signal<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"}, i_b{"i_b"}, i_f{"i_f"};
    fd_eval<M> blk{"blk"};
    fd_eval_fast<M> fst{"fst"};
    fd_stimulus<M> stim;
    tb::pin_compare cmp{"cmp"};

    fd_pair_bench(const sc_core::sc_module_name& name, item_source<fd_interval> ivs)
        : sc_module(name), stim("stim", std::move(ivs)) {
        blk.clk(clk); blk.start(start); blk.len(len); blk.a(a); blk.b(b); blk.c(c); blk.d(d);
        blk.i_px(i_b); blk.valid(valid_b); blk.last(last_b);
        fst.clk(clk); fst.start(start); fst.len(len); fst.a(a); fst.b(b); fst.c(c); fst.d(d);
        fst.i_px(i_f); fst.valid(valid_f); fst.last(last_f);
        stim.clk(clk); stim.valid(valid_b); stim.last(last_b); stim.start(start); stim.len(len);
        stim.a(a); stim.b(b); stim.c(c); stim.d(d);
        cmp.clk(clk);
        cmp.pair("valid", valid_b, valid_f);
        cmp.pair("last", last_b, last_f);
        cmp.pair("i_px", i_b, i_f, &valid_b);
        cmp.count(valid_b);
    }
    bool finished() const { return stim.finished(); }
};

template <unsigned M>
void run_pair(std::size_t pixels, uint64_t seed) {
    fd_pair_bench<M> bench("tb", random_fd_intervals<M>(pixels, seed));
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.cmp.differences(), 0u);
    EXPECT_EQ(bench.cmp.counted(), pixels);
}

}  // namespace

TEST(InterpFdFast, RandomIntervalsM2) { run_alone<2>(20000, 41); }
TEST(InterpFdFast, RandomIntervalsM4) { run_alone<4>(20000, 42); }
TEST(InterpFdFast, RandomIntervalsM6) { run_alone<6>(20000, 43); }
TEST(InterpFdFastPins, SameAsBlockLevelM3) { run_pair<3>(3000, 51); }
TEST(InterpFdFastPins, SameAsBlockLevelM6) { run_pair<6>(3000, 52); }

// A len of 0 or above 2^M is reported as fd_ctrl does and evaluated as a full interval.
TEST(InterpFdFast, BadLengthReportedAndFullIntervalEvaluated) {
    tb::report_log::get().expect(msg::input);
    const interp::cubic_coefs k{3 << 16, -(5 << 16), 2 << 16, 100 << 16};
    std::vector<fd_interval> ivs{{k, 3}, {k, 0}, {k, 4}};
    fd_bench<2, fd_eval_fast<2>> bench("tb", ivs);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(tb::report_log::get().count(msg::input), 1u);
    EXPECT_EQ(bench.checker.checked(), 3u + 4u + 4u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
}

// The checker can fail on the fast unit too.
TEST(InterpFdFast, CheckerCatchesOneWrongPixel) {
    tb::report_log::get().expect(msg::mismatch);
    fd_bench<4, fd_eval_fast<4>> bench("tb", random_fd_intervals<4>(200, 9));
    bench.checker.inject_mismatch(77);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.mismatches(), 1u);
}

// The side-by-side comparison can fail: two pins that differ at 3 rising edges (data compared only
// where its valid reads 1, so a difference under valid = 0 is not one).
TEST(InterpFdFastPins, ComparatorCatchesDifferences) {
    struct pair_of_pins : sc_core::sc_module {
        sc_core::sc_clock clk{"clk", interp_period()};
        sc_core::sc_signal<bool> valid{"valid"};
        sc_core::sc_signal<coef_t> x{"x"}, y{"y"};
        tb::pin_compare cmp{"cmp"};
        SC_HAS_PROCESS(pair_of_pins);
        explicit pair_of_pins(const sc_core::sc_module_name& name) : sc_module(name) {
            cmp.clk(clk);
            cmp.pair("x", x, y, &valid);
            cmp.count(valid);
            SC_THREAD(drive);
        }
        void drive() {
            // Written between edges (the clock rises every period): y differs from x in words 2, 3
            // and 5 under valid, and in word 4 with valid low.
            const coef_t v[8] = {1, 2, 3, 4, 5, 6, 7, 8}, w[8] = {1, 2, 9, 9, 9, 9, 7, 8};
            const bool ok[8] = {1, 1, 1, 1, 0, 1, 1, 1};
            wait(interp_period() / 2);
            for (int i = 0; i < 8; ++i) {
                x.write(v[i]);
                y.write(w[i]);
                valid.write(ok[i]);
                wait(interp_period());
            }
            sc_core::sc_stop();
        }
    } bench("tb");
    sc_core::sc_start();
    EXPECT_EQ(bench.cmp.differences(), 3u);
    EXPECT_EQ(bench.cmp.counted(), 7u);
}

}  // namespace test_interp_fd_fast
