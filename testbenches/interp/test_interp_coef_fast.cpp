// The fast pin-level coefficient units (interp/coef_unit_fast.h) side by side with the block-level
// ones (every sample set and /3 mode, and the quadratic unit) on the same sample pins: random samples
// over the whole bus, new ones after most rising edges (some held), A..D / a..c compared at every
// rising edge with the block units' and with the golden model of the samples latched at the falling
// edge before. One elaboration per test (its own process).
#include <gtest/gtest.h>

#include <cstdio>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "interp/coef_unit_cubic.h"
#include "interp/coef_unit_fast.h"
#include "interp/coef_unit_quad.h"
#include "testbenches/interp/interp_bench_common.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_interp_coef_fast {

using namespace shading;
using namespace shading::tb;
using interp::div3_mode;
using interp::sample_set;

namespace {

class coef_pair_bench : public sc_core::sc_module {
public:
    sc_core::sc_clock clk{"clk", interp_period()};
    sc_core::sc_vector<sc_core::sc_signal<sample_t>> i{"i", 4};
    // Outputs: [unit][coefficient], units 0..3 the cubic variants, 4 the quadratic; block and fast.
    sc_core::sc_vector<sc_core::sc_signal<coef_t>> ob{"ob", 20}, of{"of", 20};

    coef_unit_cubic<sample_set::case1, div3_mode::shift_add> b0{"b0"};
    coef_unit_cubic<sample_set::case1, div3_mode::exact> b1{"b1"};
    coef_unit_cubic<sample_set::case2, div3_mode::shift_add> b2{"b2"};
    coef_unit_cubic<sample_set::case2, div3_mode::exact> b3{"b3"};
    coef_unit_quad bq{"bq"};
    coef_unit_cubic_fast<sample_set::case1, div3_mode::shift_add> f0{"f0"};
    coef_unit_cubic_fast<sample_set::case1, div3_mode::exact> f1{"f1"};
    coef_unit_cubic_fast<sample_set::case2, div3_mode::shift_add> f2{"f2"};
    coef_unit_cubic_fast<sample_set::case2, div3_mode::exact> f3{"f3"};
    coef_unit_quad_fast fq{"fq"};

    SC_HAS_PROCESS(coef_pair_bench);
    coef_pair_bench(const sc_core::sc_module_name& name, std::size_t clocks, uint64_t seed)
        : sc_module(name), clocks_(clocks), seed_(seed) {
        bind_cubic(b0, ob, 0); bind_cubic(b1, ob, 1); bind_cubic(b2, ob, 2); bind_cubic(b3, ob, 3);
        bind_cubic(f0, of, 0); bind_cubic(f1, of, 1); bind_cubic(f2, of, 2); bind_cubic(f3, of, 3);
        bind_quad(bq, ob);
        bind_quad(fq, of);
        SC_METHOD(on_rise);
        sensitive << clk.posedge_event();
        dont_initialize();
        SC_METHOD(on_fall);
        sensitive << clk.negedge_event();
        dont_initialize();
    }
    bool finished() const { return finished_; }
    std::size_t differences = 0, golden_differences = 0, compared = 0;

private:
    template <class U>
    void bind_cubic(U& u, sc_core::sc_vector<sc_core::sc_signal<coef_t>>& o, int k) {
        u.clk(clk); u.i1(i[0]); u.i2(i[1]); u.i3(i[2]); u.i4(i[3]);
        u.a(o[4 * k]); u.b(o[4 * k + 1]); u.c(o[4 * k + 2]); u.d(o[4 * k + 3]);
    }
    template <class U>
    void bind_quad(U& u, sc_core::sc_vector<sc_core::sc_signal<coef_t>>& o) {
        u.clk(clk); u.i1(i[0]); u.i2(i[1]); u.i3(i[2]);
        u.a(o[16]); u.b(o[17]); u.c(o[18]);
    }

    void on_fall() {  // the samples the units latch now
        for (int k = 0; k < 4; ++k) latched_[k] = i[k].read().to_uint64();
        any_latched_ = true;
    }

    void on_rise() {
        if (any_latched_) {
            ++compared;
            for (int n = 0; n < 19; ++n)
                if (ob[n].read() != of[n].read() && differences++ < 5)
                    std::printf("output %d differs at %s: block %x fast %x\n", n,
                                sc_core::sc_time_stamp().to_string().c_str(), unsigned(ob[n].read().to_uint()),
                                unsigned(of[n].read().to_uint()));
            const sample_set sets[] = {sample_set::case1, sample_set::case1, sample_set::case2, sample_set::case2};
            const div3_mode divs[] = {div3_mode::shift_add, div3_mode::exact, div3_mode::shift_add, div3_mode::exact};
            for (int u = 0; u < 4; ++u) {
                const auto g = interp::golden_cubic_coefs(latched_, sets[u], divs[u]);
                const int64_t want[] = {g.a, g.b, g.c, g.d};
                for (int n = 0; n < 4; ++n) golden_differences += coef_code(of[4 * u + n].read()) != want[n];
            }
            const auto q = interp::golden_quad_coefs({latched_[0], latched_[1], latched_[2]});
            golden_differences += coef_code(of[16].read()) != q.a;
            golden_differences += coef_code(of[17].read()) != q.b;
            golden_differences += coef_code(of[18].read()) != q.c;
        }
        if (clock_ == clocks_) {
            finished_ = true;
            sc_core::sc_stop();
            return;
        }
        split_rng r(seed_, clock_++);
        if (r.range(0, 4) != 0) {  // new samples after 4 rising edges in 5; held otherwise
            const auto s = random_samples<4>(r);
            for (int k = 0; k < 4; ++k) i[k].write(sample_t(s[k]));
        }
    }

    std::size_t clocks_, clock_ = 0;
    uint64_t seed_;
    std::array<uint64_t, 4> latched_{};
    bool any_latched_ = false, finished_ = false;
};

}  // namespace

TEST(InterpCoefFast, SameAsBlockLevelAndGoldenAtEveryEdge) {
    coef_pair_bench bench("tb", 20000, 61);
    EXPECT_TRUE(tb::run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_SEC)));
    EXPECT_EQ(bench.compared, 20000u);
    EXPECT_EQ(bench.differences, 0u);
    EXPECT_EQ(bench.golden_differences, 0u);
}

}  // namespace test_interp_coef_fast
