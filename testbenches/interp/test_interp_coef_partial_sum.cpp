// The coefficient unit with the interpolation paper's grouping of the /3 (coef_unit_cubic_partial_sum.h) against its
// golden model, bit for bit, per sample set and divider (value-parameterised), plus hand-worked
// values and its clock-phase requirement. A small bench of its own: a driver writes one sample
// set just after each rising edge; at the next rising edge the coefficients are compared.
// Each TEST elaborates its own bench (one process per test).
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <random>
#include <systemc>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "formats/fixed_point.h"
#include "golden/interp_golden.h"
#include "interp/coef_unit_cubic_partial_sum.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_interp_coef_partial_sum {

using namespace shading;
using interp::div3_grouping;
using interp::div3_mode;
using interp::sample_set;
using sc_core::sc_time;

using samples = std::array<uint64_t, 4>;
using golden_fn = std::function<interp::cubic_coefs(const samples&)>;

template <sample_set SET, div3_mode DIV, div3_grouping G>
class coef_partial_sum_bench : public sc_core::sc_module {
    using sample_t = sc_dt::sc_uint<interp::sample_fmt.width>;
    using coef_t = sc_dt::sc_uint<interp::coef_fmt.width>;

public:
    sc_core::sc_clock clk{"clk", sc_time(20, sc_core::SC_NS)};
    sc_core::sc_vector<sc_core::sc_signal<sample_t>> in{"in", 4};
    sc_core::sc_vector<sc_core::sc_signal<coef_t>> out{"out", 4};
    coef_unit_cubic_t<SET, DIV, G> dut{"dut"};

    SC_HAS_PROCESS(coef_partial_sum_bench);
    coef_partial_sum_bench(const sc_core::sc_module_name& name, std::vector<samples> sets, golden_fn golden)
        : sc_module(name), sets_(std::move(sets)), golden_(std::move(golden)) {
        dut.clk(clk);
        dut.i1(in[0]); dut.i2(in[1]); dut.i3(in[2]); dut.i4(in[3]);
        dut.a(out[0]); dut.b(out[1]); dut.c(out[2]); dut.d(out[3]);
        SC_THREAD(run);
    }
    bool finished() const { return finished_; }
    std::size_t checked() const { return checked_; }
    std::size_t mismatches() const { return mismatches_; }
    const std::vector<interp::cubic_coefs>& results() const { return results_; }

private:
    void run() {
        const samples* pending = nullptr;
        for (std::size_t k = 0; k <= sets_.size(); ++k) {
            wait(clk.posedge_event());
            if (pending != nullptr) check(*pending);
            if (k == sets_.size()) break;
            for (std::size_t i = 0; i < 4; ++i) in[i].write(sets_[k][i]);
            pending = &sets_[k];
        }
        finished_ = true;
        sc_core::sc_stop();
    }
    void check(const samples& s) {
        auto code = [this](std::size_t i) { return code_value(out[i].read().to_uint64(), interp::coef_fmt); };
        const interp::cubic_coefs got{code(0), code(1), code(2), code(3)};
        results_.push_back(got);
        ++checked_;
        if (!(got == golden_(s))) ++mismatches_;
    }

    std::vector<samples> sets_;
    golden_fn golden_;
    std::vector<interp::cubic_coefs> results_;
    std::size_t checked_ = 0, mismatches_ = 0;
    bool finished_ = false;
};

// Corners (all zero, full scale, the sign patterns that maximise the partial sums) then random.
std::vector<samples> sample_sets(std::size_t n, unsigned seed) {
    const uint64_t hi = interp::sample_fmt.mask();
    std::vector<samples> v{{0, 0, 0, 0}, {hi, hi, hi, hi}, {hi, 0, hi, 0}, {0, hi, 0, hi}, {hi, 0, 0, hi}, {0, hi, hi, 0}};
    std::mt19937 rng(seed);
    std::uniform_int_distribution<uint64_t> u(0, hi);
    while (v.size() < n) v.push_back({u(rng), u(rng), u(rng), u(rng)});
    return v;
}

golden_fn golden_of(sample_set set, div3_mode div, div3_grouping g) {
    return [=](const samples& s) { return interp::golden_cubic_coefs(s, set, div, g); };
}

struct unit_param {
    sample_set set;
    div3_mode div;
};
void PrintTo(const unit_param& p, std::ostream* os) {
    *os << (p.set == sample_set::case1 ? "case 1, " : "case 2, ") << (p.div == div3_mode::shift_add ? "shift-and-add" : "exact");
}

// Runs `body` with a bench of the partial-sum unit for the parameter's set and divider.
template <typename Body>
void with_unit_bench(const unit_param& p, std::vector<samples> sets, golden_fn golden, Body body) {
    auto go = [&](auto* tag) {
        using bench_t = std::remove_pointer_t<decltype(tag)>;
        bench_t bench("tb", std::move(sets), std::move(golden));
        EXPECT_TRUE(tb::run_to_completion(bench, sc_time(1, sc_core::SC_MS)));
        body(bench);
    };
    constexpr auto G = div3_grouping::partial_sum;
    if (p.set == sample_set::case1 && p.div == div3_mode::shift_add)
        go(static_cast<coef_partial_sum_bench<sample_set::case1, div3_mode::shift_add, G>*>(nullptr));
    else if (p.set == sample_set::case1)
        go(static_cast<coef_partial_sum_bench<sample_set::case1, div3_mode::exact, G>*>(nullptr));
    else if (p.div == div3_mode::shift_add)
        go(static_cast<coef_partial_sum_bench<sample_set::case2, div3_mode::shift_add, G>*>(nullptr));
    else
        go(static_cast<coef_partial_sum_bench<sample_set::case2, div3_mode::exact, G>*>(nullptr));
}

class InterpCoefPartialSumUnit : public ::testing::TestWithParam<unit_param> {};

std::string param_name(const ::testing::TestParamInfo<unit_param>& info) {
    return std::string(info.param.set == sample_set::case1 ? "Case1" : "Case2") +
           (info.param.div == div3_mode::shift_add ? "ShiftAdd" : "Exact");
}

TEST_P(InterpCoefPartialSumUnit, BitExactAgainstItsGoldenModel) {
    const auto p = GetParam();
    with_unit_bench(p, sample_sets(400, 41), golden_of(p.set, p.div, div3_grouping::partial_sum), [](auto& bench) {
        EXPECT_EQ(bench.checked(), 400u);
        EXPECT_EQ(bench.mismatches(), 0u);
        EXPECT_EQ(tb::report_log::get().count(msg::timing), 0u) << "the 20 ns clock meets the unit's phases";
    });
}

INSTANTIATE_TEST_SUITE_P(SetsAndDividers, InterpCoefPartialSumUnit,
                         ::testing::Values(unit_param{sample_set::case1, div3_mode::shift_add},
                                           unit_param{sample_set::case1, div3_mode::exact},
                                           unit_param{sample_set::case2, div3_mode::shift_add},
                                           unit_param{sample_set::case2, div3_mode::exact}),
                         param_name);

// The bench tells the groupings apart: with the shift-and-add, partial - whole = 43X/128 - Y -
// 43(X - 3Y)/128 = Y/128 per coefficient (Y the integer part: case 1 8I1 + 16I3 and 7I1 + 4I3),
// so the whole-sum golden model fails on every set but those with I1 = I3 = 0.
TEST(InterpCoefPartialSumChecks, WholeSumGoldenDoesNotMatchThePartialSumGrouping) {
    const unit_param p{sample_set::case1, div3_mode::shift_add};
    const auto sets = sample_sets(50, 42);
    std::size_t differ = 0;
    for (const auto& s : sets) differ += (s[0] | s[2]) != 0 ? 1 : 0;
    EXPECT_EQ(differ, 48u);  // the corners {0, 0, 0, 0} and {0, hi, 0, hi}
    with_unit_bench(p, sets, golden_of(p.set, p.div, div3_grouping::whole_sum), [&](auto& bench) {
        EXPECT_EQ(bench.checked(), 50u);
        EXPECT_EQ(bench.mismatches(), differ);
    });
}

// A flat line, every sample 1.0 (hand-worked in test_interp_golden): the real A = C = 0; the
// partial-sum grouping with the shift-and-add gives case 1 A = 0.1875, C = 0.0859375 (12288 and 5632
// LSB), case 2 A = -0.1875, C = -0.1171875 (-12288, -7680); with the exact divider 0 (72, 33 and
// 45 are multiples of 3). B = 0, D = 1.0 (65536).
TEST_P(InterpCoefPartialSumUnit, HandWorkedFlatLine) {
    const auto p = GetParam();
    const bool sa = p.div == div3_mode::shift_add, c1 = p.set == sample_set::case1;
    const interp::cubic_coefs want{sa ? (c1 ? 12288 : -12288) : 0, 0, sa ? (c1 ? 5632 : -7680) : 0, 65536};
    auto unused = [](const samples&) { return interp::cubic_coefs{}; };
    with_unit_bench(p, {{256, 256, 256, 256}}, unused, [&](auto& bench) {
        ASSERT_EQ(bench.results().size(), 1u);
        EXPECT_EQ(bench.results()[0], want);
    });
}

}  // namespace test_interp_coef_partial_sum
