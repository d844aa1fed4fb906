// The fast pin-level abstraction (specular/specular_fast.h) against the block-level model and the
// golden model: both models of one device sit on the same input pins in one bench, each with its
// own outputs, monitor and checker (the random differential stream of the bench programs, both
// overflow modes, every variant). At every validating edge both must equal the golden model; the
// fast model's outputs change once per pixel, at the derived path delay, never before the block
// level's last transient; with zero block delays both settle in the latch's own time step; the
// input-range and strobe-timing reports come in the same numbers.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "core/report_ids.h"
#include "testbenches/specular/device_traits.h"
#include "testbenches/specular/specular_tb.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_specular_fast {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_MS;
using sc_core::SC_NS;
using sc_core::sc_time;

// Records the instants at which a model's outputs 25-27 change (one entry per time step).
class change_recorder : public sc_core::sc_module {
public:
    sc_core::sc_in<out_t> r{"r"}, g{"g"}, b{"b"};
    std::vector<sc_time> at;

    SC_HAS_PROCESS(change_recorder);
    explicit change_recorder(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_change);
        sensitive << r << g << b;
        dont_initialize();
    }

private:
    void on_change() {
        const auto now = sc_core::sc_time_stamp();
        if (at.empty() || at.back() != now) at.push_back(now);
    }
};

// One stimulus, the block-level and the fast model of AGen's device on the same inputs.
template <class Traits>
class dual_bench : public sc_core::sc_module, public fig1_inputs {
public:
    using gen = typename Traits::gen;
    sc_core::sc_signal<out_t> blk25{"blk25"}, blk26{"blk26"}, blk27{"blk27"};
    sc_core::sc_signal<out_t> fst25{"fst25"}, fst26{"fst26"}, fst27{"fst27"};
    sc_core::sc_signal<bool> blk29{"blk29"}, fst29{"fst29"};

    specular_checker blk_checker, fst_checker;
    specular_model<gen, abstraction::block> blk;
    specular_model<gen, abstraction::fast> fst;
    specular_stimulus stim;
    specular_monitor blk_mon, fst_mon;
    change_recorder blk_rec, fst_rec;

    dual_bench(const sc_core::sc_module_name& name, item_source<surface> s, strobe_timing t, overflow_mode mode,
               const block_delays& d = {})
        : sc_module(name),
          blk_checker(golden(mode)), fst_checker(golden(mode)),
          blk("blk", mode, gen::default_config(), d), fst("fst", mode, gen::default_config(), d),
          stim("stim", std::move(s), t),
          blk_mon("blk_mon", [this](const pixel_sample& p) { blk_checker.check(p); }),
          fst_mon("fst_mon", [this](const pixel_sample& p) { fst_checker.check(p); }),
          blk_rec("blk_rec"), fst_rec("fst_rec") {
        for (auto* m : {&blk_mon, &fst_mon}) bind_fig1_inputs(*m, *this);
        bind_fig1_inputs(stim, *this);
        bind_fig1_inputs(blk, *this);
        bind_fig1_inputs(fst, *this);
        blk.out25_r(blk25); blk.out26_g(blk26); blk.out27_b(blk27); blk.out29_valid(blk29);
        fst.out25_r(fst25); fst.out26_g(fst26); fst.out27_b(fst27); fst.out29_valid(fst29);
        blk_mon.out25_r(blk25); blk_mon.out26_g(blk26); blk_mon.out27_b(blk27); blk_mon.out29_valid(blk29);
        fst_mon.out25_r(fst25); fst_mon.out26_g(fst26); fst_mon.out27_b(fst27); fst_mon.out29_valid(fst29);
        blk_rec.r(blk25); blk_rec.g(blk26); blk_rec.b(blk27);
        fst_rec.r(fst25); fst_rec.g(fst26); fst_rec.b(fst27);
        SC_METHOD(on_edge);
        sensitive << ctl15.negedge_event() << ctl17 << ctl20.negedge_event() << ctl22.negedge_event()
                  << ctl24.negedge_event();
        dont_initialize();
    }
    SC_HAS_PROCESS(dual_bench);

    bool finished() const { return stim.finished(); }

    // Per pixel window (one ctl17 rise to the next): the outputs agree at the rise; the fast
    // model changed at most once when no load came in the window, at ctl17's fall + RG2's path;
    // whenever it changed, the block level changed too, and not later.
    std::size_t windows = 0, compared = 0, disagreements = 0, timing_errors = 0;
    std::vector<sc_time> latches;  // every strobe's falling edges

private:
    static specular_checker::golden_fn golden(overflow_mode mode) {
        return [mode](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) { return Traits::golden(n, c, k, mode); };
    }

    void on_edge() {
        const auto now = sc_core::sc_time_stamp();
        if (!ctl17.event() || !ctl17.read()) {  // a latching edge
            if (ctl17.event()) fall17_ = now;
            else load_in_window_ = true;
            latches.push_back(now);
            return;
        }
        // ctl17 rose: close the window [last rise, now).
        ++compared;
        if (blk25.read() != fst25.read() || blk26.read() != fst26.read() || blk27.read() != fst27.read())
            ++disagreements;
        const auto in_window = [&](const std::vector<sc_time>& v, std::size_t& from) {
            std::vector<sc_time> w;
            for (; from < v.size() && v[from] < now; ++from) w.push_back(v[from]);
            return w;
        };
        const auto b = in_window(blk_rec.at, blk_from_), f = in_window(fst_rec.at, fst_from_);
        if (!f.empty() && (b.empty() || b.back() > f.back())) ++timing_errors;
        if (!load_in_window_ && seen_rise_ && !f.empty() && (f.size() > 1 || f[0] != fall17_ + fst.rg2_to_outputs()))
            ++timing_errors;
        ++windows;
        load_in_window_ = false;
        seen_rise_ = true;
    }

    sc_time fall17_;
    std::size_t blk_from_ = 0, fst_from_ = 0;
    bool load_in_window_ = false, seen_rise_ = false;
};

template <typename T>
class SpecularFast : public ::testing::Test {};

using devices = ::testing::Types<ua60553_device, ua22802_device, tuned_device>;

// The bench programs' random stream (2000 pixels, random reloads), then small n where cos^n is
// rarely 0 (random n mostly gives 0 outputs), with cos codes up to 0xffff in wrap mode.
template <class Traits>
void random_differential(overflow_mode mode) {
    std::vector<surface> s;
    auto random = random_surfaces(2000, 11);
    for (std::size_t i = 0; i < random.size(); ++i) s.push_back(random[i]);
    split_rng rng(11, 0);
    for (unsigned n : {1u, 2u, 5u, 20u}) {
        surface f{n, {255, static_cast<unsigned>(rng.range(0, 255)), 7}, {}};
        for (int p = 0; p < 250; ++p)
            f.cos_codes.push_back(static_cast<uint32_t>(rng.range(0, mode == overflow_mode::wrap ? 0xffff : spec::cos_one)));
        s.push_back(f);
    }
    if (mode == overflow_mode::wrap) report_log::get().expect(msg::input);  // cos > 1.0
    dual_bench<Traits> tb("tb", s, strobe_timing{}, mode);
    ASSERT_TRUE(run_to_completion(tb, sc_time(10, SC_MS)));
    EXPECT_EQ(tb.blk_checker.samples(), 3000u);
    EXPECT_EQ(tb.fst_checker.samples(), 3000u);
    EXPECT_EQ(tb.fst.cos_violations(), tb.blk.chk_in18_cos.violations());
    EXPECT_EQ(tb.blk_checker.mismatches(), 0u);
    EXPECT_EQ(tb.fst_checker.mismatches(), 0u);
    EXPECT_EQ(tb.disagreements, 0u);
    EXPECT_EQ(tb.timing_errors, 0u);
    // The derived paths: the fast model's formula against the block level's timing graph.
    EXPECT_EQ(tb.fst.rg1_to_outputs(), tb.blk.rg1_to_outputs());
    EXPECT_EQ(tb.fst.rg2_to_outputs(), tb.blk.rg2_to_outputs());
    EXPECT_EQ(tb.fst.rg2_to_outputs(), sc_time(11.2, SC_NS)) << "Fig. 3's critical path (README)";
    for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(tb.fst.path(i), tb.blk.chk_timing.path(i)) << "strobe " << i;
    // The fast model wrote fewer output changes than the block level's transients.
    EXPECT_LT(tb.fst_rec.at.size(), tb.blk_rec.at.size());
}

TYPED_TEST_SUITE(SpecularFast, devices, device_names);

TYPED_TEST(SpecularFast, RandomSaturateMatchesBlockLevelAndGolden) { random_differential<TypeParam>(overflow_mode::saturate); }

TYPED_TEST(SpecularFast, RandomWrapMatchesBlockLevelAndGolden) { random_differential<TypeParam>(overflow_mode::wrap); }

TYPED_TEST(SpecularFast, ZeroDelaysSettleAtTheLatchInstant) {
    block_delays zero;
    zero.reg = zero.inverter = zero.adder = zero.multiplier = zero.rom = zero.gate = sc_core::SC_ZERO_TIME;
    dual_bench<TypeParam> tb("tb", random_surfaces(1000, 5), strobe_timing{}, overflow_mode::saturate, zero);
    ASSERT_TRUE(run_to_completion(tb, sc_time(10, SC_MS)));
    EXPECT_EQ(tb.fst_checker.samples(), 1000u);
    EXPECT_EQ(tb.fst_checker.mismatches(), 0u);
    EXPECT_EQ(tb.blk_checker.mismatches(), 0u);
    EXPECT_EQ(tb.disagreements, 0u);
    EXPECT_EQ(tb.fst.rg2_to_outputs(), sc_core::SC_ZERO_TIME);
    // Every output change of either model falls in a latching edge's own time step.
    const std::set<sc_time> latch(tb.latches.begin(), tb.latches.end());
    std::size_t off = 0;
    for (const auto& t : tb.fst_rec.at) off += latch.count(t) == 0;
    for (const auto& t : tb.blk_rec.at) off += latch.count(t) == 0;
    EXPECT_EQ(off, 0u);
    EXPECT_GT(tb.fst_rec.at.size(), 10u) << "most random pixels give cos^n = 0: few changes";
    EXPECT_LE(tb.fst_rec.at.size(), tb.blk_rec.at.size());
}

TYPED_TEST(SpecularFast, OutOfRangeInputsAndShortStrobesReportedAsTheBlockLevel) {
    // n = 0, 1001 and cos above 1.0 (wrap mode passes them on), then a settling phase shorter than
    // the critical path: the same reports, in the same numbers, from both models.
    report_log::get().expect(msg::input);
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::mismatch);  // the unsettled samples
    std::vector<surface> s{{0, {255, 10, 20}, {0x8000, 0x9000, 0x100}},
                           {1001, {255, 10, 20}, {0x4000, 0xffff}},
                           {7, {3, 200, 100}, {0x7000, 0x8001, 0x10}}};
    strobe_timing t;
    t.t_low = sc_time(8, SC_NS);  // shorter than the 11.2 ns of RG2's path
    dual_bench<TypeParam> tb("tb", s, t, overflow_mode::wrap);
    ASSERT_TRUE(run_to_completion(tb, sc_time(1, SC_MS)));
    EXPECT_EQ(tb.fst.n_violations(), 2u);
    EXPECT_EQ(tb.fst.n_violations(), tb.blk.chk_in16_n.violations());
    EXPECT_EQ(tb.fst.cos_violations(), 3u) << "0x9000, 0xffff, 0x8001";
    EXPECT_EQ(tb.fst.cos_violations(), tb.blk.chk_in18_cos.violations());
    EXPECT_GE(tb.fst.timing_violations(), 7u);
    EXPECT_EQ(tb.fst.timing_violations(), tb.blk.chk_timing.violations());
}

}  // namespace test_specular_fast
