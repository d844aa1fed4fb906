// The squared-quadratic device's RTL against its SystemC model on what the model's documented bad
// input does (modules/squared/README.md), in both overflow modes, each sample also against
// golden_squared:
//   - dropped and restarted samples: strobe 17 again before output 29 at every distance
//     (squared_restart_tb.h: before the taking edge, the load's clock, mid-squaring, one clock
//     before done; just after done, for contrast; three drops in a row), for every n 0..1023: the two
//     devices' output-29 rises paired (instant and colour), the model's drop reports counted
//     against the plan's, the clocks per sample measured on the model (never assumed) equal for
//     every pixel of a surface and k plus one constant over all n;
//   - n = 0, n = 1001..1023 and cos > 1.0 with k_s*I reloaded between the pixels
//     (squared_cover.h), the model's input reports counted against the stream's.
// A negative test shows that the pairing catches a monitor that misses a restart.
#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "arith/squared_arith.h"
#include "core/report_ids.h"
#include "rtl_cosim_tb.h"
#include "rtl_squared_tb.h"
#include "squared/squared_device.h"
#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/squared/squared_cover.h"
#include "testbenches/squared/squared_restart_tb.h"
#include "verilated.h"

// The Verilated devices (testbenches/rtl/CMakeLists.txt).
#include "Vrtl_squared_saturate.h"
#include "Vrtl_squared_wrap.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_rtl_squared_cover {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_MS;
using sc_core::sc_time;

// The co-simulation bench driven by the restart stimulus, which reads the model's output 29.
template <typename Rtl, typename ModelMonitor = specular_monitor>
class restart_bench : public rtl_cosim_bench<squared_device, Rtl, restart_stimulus, ModelMonitor> {
    using base = rtl_cosim_bench<squared_device, Rtl, restart_stimulus, ModelMonitor>;

public:
    restart_bench(const sc_core::sc_module_name& name, std::vector<restart_episode> plan, overflow_mode mode,
                  specular_checker::golden_fn model_golden)
        : base(name, std::move(plan), squared_timing(), std::move(model_golden), squared_golden(mode), mode) {
        this->stim.out29_valid(this->out29_valid);
    }
};

std::string trace_stem() {
    const char* dir = std::getenv("SHADING_TRACE");
    return dir && *dir ? std::string(dir) + "/" + current_test_name() : std::string();
}

template <typename T>
class RtlSquaredCover : public ::testing::Test {
protected:
    void SetUp() override { Verilated::traceEverOn(true); }

    // Both devices' samples against golden and each other, every pixel the plan lets out paired;
    // the model's drops and reports counted against the plan's; the clocks per sample (measured on
    // the model) the same for every pixel of a surface, and k (golden) plus one constant for all n.
    void restarts(unsigned first, unsigned last) {
        report_log::get().expect(msg::timing);
        report_log::get().expect(msg::input);
        const auto plan = restart_plans(first, last);
        const restart_counts want = planned(plan);
        restart_bench<typename T::rtl> bench("tb", plan, T::mode, squared_golden(T::mode));
        ASSERT_TRUE(run_cosim(bench, sc_time(1000, SC_MS), trace_stem()));
        EXPECT_EQ(bench.stim.timeouts(), 0u);
        EXPECT_EQ(bench.checker.samples(), want.pixels);
        EXPECT_EQ(bench.rtl_checker.samples(), want.pixels);
        EXPECT_EQ(bench.pairs(), want.pixels);
        EXPECT_EQ(bench.unpaired(), 0u);
        EXPECT_EQ(bench.checker.mismatches(), 0u) << "SystemC model against golden";
        EXPECT_EQ(bench.rtl_checker.mismatches(), 0u) << "RTL against golden";
        EXPECT_EQ(bench.cross_mismatches(), 0u) << "RTL against the SystemC model";
        EXPECT_EQ(bench.dut.stage().ctl_sq.dropped(), want.drops);
        EXPECT_EQ(report_log::get().count(msg::timing), want.drops) << "one report per dropped result";
        EXPECT_EQ(report_log::get().count(msg::input), want.input_reports);
        EXPECT_EQ(bench.stim.latency_changes(), 0u) << "a restarted pixel takes the clocks of its n";
        const auto& edges = bench.stim.edges();
        ASSERT_EQ(edges.size(), plan.size());
        const int base = static_cast<int>(edges[0]) - static_cast<int>(golden_squared_a(plan[0].n).k);
        for (std::size_t i = 0; i < plan.size(); ++i)
            EXPECT_EQ(static_cast<int>(edges[i]) - static_cast<int>(golden_squared_a(plan[i].n).k), base)
                << "n = " << plan[i].n << ": " << edges[i] << " rising edges";
        // Counted by hand from rtl/squared/sq_ctrl.v: the taking edge and the done edge beside the k
        // squares, so the stimulus's taking edge is the device's and every restart lands where its
        // name says (in the load's clock, not in the synchroniser's).
        EXPECT_EQ(base, 2) << "rising edges from the taking edge to done, minus k";
    }
};

using variants = ::testing::Types<squared_variant<Vrtl_squared_saturate, overflow_mode::saturate>,
                                  squared_variant<Vrtl_squared_wrap, overflow_mode::wrap>>;

// A faulty model-side monitor: it misses restarts (keeps the cos of the first strobe 17 after an
// output 29), so it names an abandoned pixel for the result that comes out.
class restart_blind_monitor : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_in<n_t> in16_n{"in16_n"};
    sc_core::sc_in<cos_t> in18_cos{"in18_cos"};
    sc_core::sc_in<ksi_t> in19_ksi_r{"in19_ksi_r"}, in21_ksi_g{"in21_ksi_g"}, in23_ksi_b{"in23_ksi_b"};
    sc_core::sc_in<out_t> out25_r{"out25_r"}, out26_g{"out26_g"}, out27_b{"out27_b"};
    sc_core::sc_in<bool> out29_valid{"out29_valid"};

    SC_HAS_PROCESS(restart_blind_monitor);
    restart_blind_monitor(const sc_core::sc_module_name& name, std::function<void(const pixel_sample&)> sink)
        : sc_module(name), sink_(std::move(sink)) {
        SC_METHOD(on_load);
        sensitive << ctl15.neg() << ctl20.neg() << ctl22.neg() << ctl24.neg();
        dont_initialize();
        SC_METHOD(on_latch);
        sensitive << ctl17.neg();
        dont_initialize();
        SC_METHOD(on_valid);
        sensitive << out29_valid.pos();
        dont_initialize();
    }

private:
    void on_load() {
        if (ctl15.negedge()) cur_.n = in16_n.read().to_uint64();
        if (ctl20.negedge()) cur_.ksi[0] = in19_ksi_r.read().to_uint64();
        if (ctl22.negedge()) cur_.ksi[1] = in21_ksi_g.read().to_uint64();
        if (ctl24.negedge()) cur_.ksi[2] = in23_ksi_b.read().to_uint64();
    }
    void on_latch() {
        if (!pending_) cur_.cos = in18_cos.read().to_uint64();  // the fault: a restart goes unseen
        pending_ = true;
    }
    void on_valid() {
        if (!pending_) return;
        pending_ = false;
        pixel_sample s = cur_;
        s.out = {out25_r.read().to_uint64(), out26_g.read().to_uint64(), out27_b.read().to_uint64()};
        s.at = sc_core::sc_time_stamp();
        sink_(s);
    }

    std::function<void(const pixel_sample&)> sink_;
    pixel_sample cur_;
    bool pending_ = false;
};

TYPED_TEST_SUITE(RtlSquaredCover, variants, squared_variant_names);

// Every n 0..1023, the restart plan of squared_restart_tb.h: per n 15 strobes, 7 of them dropping
// the result before them, 8 pixels out.
TYPED_TEST(RtlSquaredCover, RestartsEveryN) { this->restarts(0, (1u << squared::n_fmt.width) - 1); }

TYPED_TEST(RtlSquaredCover, BadInputsWithKsiReloadsBetweenPixels) {
    // n = 0 and 1001..1023 (and 1, 512, 1000), each with cos above 1.0 and near the levels, k_s*I
    // reloaded in another subset of RG3..RG5 before every pixel; Fig. 3's timing for the device.
    report_log::get().expect(msg::input);
    const auto s = bad_input_surfaces();
    const std::size_t pixels = pixel_ns(s).size();
    const auto golden = squared_golden(TypeParam::mode);
    rtl_cosim_bench<squared_device, typename TypeParam::rtl> bench("tb", s, squared_timing(), golden, golden,
                                                                   TypeParam::mode);
    ASSERT_TRUE(run_cosim(bench, sc_time(100, SC_MS), trace_stem()));
    EXPECT_EQ(bench.checker.samples(), pixels);
    EXPECT_EQ(bench.rtl_checker.samples(), pixels);
    EXPECT_EQ(bench.pairs(), pixels);
    EXPECT_EQ(bench.unpaired(), 0u);
    EXPECT_EQ(bench.checker.mismatches(), 0u) << "SystemC model against golden";
    EXPECT_EQ(bench.rtl_checker.mismatches(), 0u) << "RTL against golden";
    EXPECT_EQ(bench.cross_mismatches(), 0u) << "RTL against the SystemC model";
    EXPECT_EQ(report_log::get().count(msg::input), input_reports(s));
    EXPECT_EQ(bench.dut.stage().ctl_sq.dropped(), 0u);
}

TEST(RtlSquaredCoverCheck, AMonitorThatMissesARestartIsCaught) {
    // Negative test: the model's samples taken by a monitor that misses restarts. At n = 20, a
    // reference pixel, a restart mid-squaring (dropped) and a strobe after done (not dropped):
    // 4 pixels; only the restarted one is misnamed, so the model's sample fails golden and the
    // pairing, once each, and the RTL's passes.
    Verilated::traceEverOn(true);
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::input);
    report_log::get().expect(msg::mismatch);
    restart_episode e = restart_plan(20);
    e.chains = {e.chains[2], e.chains[4]};
    ASSERT_EQ(e.chains[0].at[0], restart_at::mid_squaring);
    ASSERT_EQ(e.chains[1].at[0], restart_at::after_done);
    const std::vector<restart_episode> plan{e};
    ASSERT_EQ(planned(plan).pixels, 4u);
    ASSERT_EQ(planned(plan).drops, 1u);
    const auto golden = squared_golden(overflow_mode::saturate);
    restart_bench<Vrtl_squared_saturate, restart_blind_monitor> bench("tb", plan, overflow_mode::saturate, golden);
    ASSERT_TRUE(run_cosim(bench, sc_time(1, SC_MS)));
    EXPECT_EQ(bench.pairs(), 4u);
    EXPECT_EQ(bench.dut.stage().ctl_sq.dropped(), 1u);
    EXPECT_EQ(bench.checker.mismatches(), 1u);
    EXPECT_EQ(bench.rtl_checker.mismatches(), 0u);
    EXPECT_EQ(bench.cross_mismatches(), 1u);
    EXPECT_EQ(report_log::get().count(msg::mismatch), 2u);
}

}  // namespace test_rtl_squared_cover
