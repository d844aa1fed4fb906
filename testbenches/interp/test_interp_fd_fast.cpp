// The fast pin-level abstraction of the forward-difference evaluator (interp/fd_eval_fast.h): alone in
// the FD bench against the golden model (every pixel, one per clock, random intervals of every
// length), and side by side with the block-level fd_eval<M> on the same pins, valid / last / i_px
// compared at every rising edge. One elaboration per test (its own process).
#include <gtest/gtest.h>

#include <cstdio>

#include "common/report_log.h"
#include "common/sim_guard.h"
#include "interp/interp_fd_bench.h"

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

    SC_HAS_PROCESS(fd_pair_bench);
    fd_pair_bench(const sc_core::sc_module_name& name, item_source<fd_interval> ivs)
        : sc_module(name), stim("stim", std::move(ivs)) {
        blk.clk(clk); blk.start(start); blk.len(len); blk.a(a); blk.b(b); blk.c(c); blk.d(d);
        blk.i_px(i_b); blk.valid(valid_b); blk.last(last_b);
        fst.clk(clk); fst.start(start); fst.len(len); fst.a(a); fst.b(b); fst.c(c); fst.d(d);
        fst.i_px(i_f); fst.valid(valid_f); fst.last(last_f);
        stim.clk(clk); stim.valid(valid_b); stim.last(last_b); stim.start(start); stim.len(len);
        stim.a(a); stim.b(b); stim.c(c); stim.d(d);
        SC_METHOD(compare);
        sensitive << clk.posedge_event();
        dont_initialize();
    }
    bool finished() const { return stim.finished(); }
    std::size_t differences = 0, valid_edges = 0;

private:
    void compare() {
        valid_edges += valid_b.read();
        const bool same = valid_b.read() == valid_f.read() && last_b.read() == last_f.read() &&
                          (!valid_b.read() || i_b.read() == i_f.read());
        if (!same && differences++ < 5)
            std::printf("outputs differ at %s: valid %d/%d last %d/%d i_px %llx/%llx\n",
                        sc_core::sc_time_stamp().to_string().c_str(), int(valid_b.read()), int(valid_f.read()),
                        int(last_b.read()), int(last_f.read()), (unsigned long long)i_b.read().to_uint64(),
                        (unsigned long long)i_f.read().to_uint64());
    }
};

template <unsigned M>
void run_pair(std::size_t pixels, uint64_t seed) {
    fd_pair_bench<M> bench("tb", random_fd_intervals<M>(pixels, seed));
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.differences, 0u);
    EXPECT_EQ(bench.valid_edges, pixels);
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
