// The fast pin-level abstraction of the shading pipeline (modules/pipeline/shading_pipeline_fast.h)
// against the block-level pipeline and the golden model:
//   - side by side: one bench drives the block-level pipeline and the fast one from the same pins
//     (random jobs: every m, lengths, degrees, exact pixels, some invalid ones, random frame
//     constants), and every pin is compared at every edge of the clock: ready at falling and rising
//     edges, px_valid / px_x / px_y at rising edges, px_r/g/b where px_valid = 1; both frame
//     buffers against golden_interval (pipeline_checker);
//   - alone through simulate_frame (abstraction::fast): small renders equal golden_frame bit for
//     bit, in the plan's order, with the block level's clocks per pixel bounds.
// One elaboration per test (each test is its own process, gtest_discover_tests).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "testbenches/common/bench_source.h"
#include "testbenches/common/report_log.h"
#include "core/report_ids.h"
#include "pipeline/shading_pipeline_fast.h"
#include "pipeline_bench.h"
#include "pipeline_sim.h"
#include "pipeline_test.h"
#include "tuned/a_gen_tuned.h"
#include "ua22802/a_gen_rom.h"
#include "ua60553/a_gen_linear.h"
#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "sqmul/sqmul_device.h"
#include "squared/squared_device.h"

using namespace shading;
using namespace shading::pipeline;

namespace {

// ---- Random jobs ----

// A random plan on a frame `w` wide: jobs placed left to right, line after line, never overlapping;
// about one in `bad_every` invalid (len 0, len > 2^m, m 1 or 7, an exact quadratic; refused and
// reported by both pipelines), the rest valid for the evaluator (fd_m != 0: that m or exact pixels).
// chain: about half the jobs start at the codes of the job before's last sample, as a planned line's
// do (the carry's case).
plan random_plan(uint64_t seed, std::size_t jobs, unsigned w, unsigned fd_m, unsigned bad_every, bool chain = false) {
    plan p;
    p.width = w;
    unsigned x = 0, y = 0;
    pipeline::sample_geometry last{};
    for (std::size_t i = 0; i < jobs; ++i) {
        tb::split_rng r(seed, i);
        interval_job j;
        const uint64_t kind = r.range(0, 9);
        if (kind < 2) j.m = 0;
        else if (fd_m != 0) j.m = fd_m;
        else j.m = static_cast<unsigned>(r.range(interp::m_min, interp::m_max));
        j.len = j.m == 0 ? 1 : static_cast<unsigned>(r.range(1, 1u << j.m));
        j.deg2 = j.m != 0 && r.range(0, 2) == 0;
        for (auto& s : j.s) {
            // Q1.15 codes in [0, 1] (above 1.0 the device's input checker reports them).
            const uint64_t one = uint64_t{1} << spec::cos_fmt.frac;
            s.cos_nl = static_cast<uint32_t>(r.range(0, one));
            s.cos_nh = s.cos_nl == 0 ? 0 : static_cast<uint32_t>(r.range(0, one));
        }
        if (chain && r.range(0, 1) == 0) j.s[0] = last;
        if (j.m == 0) j.s[1] = j.s[2] = j.s[3] = j.s[0];
        if (j.deg2) j.s[3] = j.s[2];
        last = j.s[j.m == 0 ? 0 : (j.deg2 ? 2 : 3)];
        if (bad_every != 0 && r.range(0, bad_every - 1) == 0) {
            switch (r.range(0, 3)) {
                case 0: j.len = 0; break;
                case 1: j.m = r.range(0, 1) ? 1 : 7; break;
                case 2: j.m = 0; j.len = 1; j.deg2 = true; break;
                default: j.len = (1u << j.m) + 1; break;
            }
        }
        const unsigned span = std::max(1u, j.len);
        if (x + span > w) {
            x = 0;
            ++y;
        }
        j.x0 = x;
        j.y = y;
        x += span;
        p.jobs.push_back(j);
        p.pixels += j.len;
    }
    p.height = y + 1;
    return p;
}

frame_constants random_constants(uint64_t seed) {
    tb::split_rng r(seed, 1u << 30);
    frame_constants k;
    k.n = static_cast<unsigned>(r.range(1, 1000));
    for (int c = 0; c < 3; ++c) {
        k.ksi[c] = r.range(0, 255);
        k.kdi[c] = r.range(0, pipeline::kdi_fmt.mask());
        k.ambient[c] = r.range(0, 255 * 256);
    }
    return k;
}

// ---- Side by side ----

// Compares the two pipelines' pins at every edge (samples taken after the edge's writes settle:
// at the next opposite edge, which reads the values both held through the phase).
class pin_comparator : public sc_core::sc_module {
public:
    using coord_t = sc_dt::sc_uint<16>;
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> ready_b{"ready_b"}, ready_f{"ready_f"}, valid_b{"valid_b"}, valid_f{"valid_f"};
    sc_core::sc_in<coord_t> x_b{"x_b"}, x_f{"x_f"}, y_b{"y_b"}, y_f{"y_f"};
    sc_core::sc_vector<sc_core::sc_in<pipeline::sample_t>> px_b{"px_b", 3}, px_f{"px_f", 3};

    SC_HAS_PROCESS(pin_comparator);
    explicit pin_comparator(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_edge);
        sensitive << clk;
        dont_initialize();
    }
    std::size_t differences() const { return diffs_; }
    std::size_t edges() const { return edges_; }
    std::size_t valid_edges() const { return valid_edges_; }

private:
    void on_edge() {
        ++edges_;
        // Values held through the phase that this edge ends.
        bool same = ready_b.read() == ready_f.read();
        if (clk.read()) {
            same = same && valid_b.read() == valid_f.read() && x_b.read() == x_f.read() && y_b.read() == y_f.read();
            if (valid_b.read()) {
                ++valid_edges_;
                for (int c = 0; c < 3; ++c) same = same && px_b[c].read() == px_f[c].read();
            }
        }
        if (!same && diffs_++ < 5) {
            std::printf("pins differ at %s (%s edge): ready %d/%d valid %d/%d x %u/%u y %u/%u r %x/%x\n",
                        sc_core::sc_time_stamp().to_string().c_str(), clk.read() ? "rising" : "falling",
                        int(ready_b.read()), int(ready_f.read()), int(valid_b.read()), int(valid_f.read()),
                        x_b.read().to_uint(), x_f.read().to_uint(), y_b.read().to_uint(), y_f.read().to_uint(),
                        px_b[0].read().to_uint(), px_f[0].read().to_uint());
        }
    }
    std::size_t diffs_ = 0, edges_ = 0, valid_edges_ = 0;
};

template <class AGen, evaluator EVAL>
class pair_bench : public sc_core::sc_module {
public:
    using coord_t = sc_dt::sc_uint<16>;
    using block_t = shading_pipeline<AGen, EVAL>;
    using fast_t = shading_pipeline_fast<EVAL>;
    struct outs {
        sc_core::sc_signal<bool> ready, valid;
        sc_core::sc_signal<coord_t> x, y;
        sc_core::sc_signal<pipeline::sample_t> r, g, b;
    };

    sc_core::sc_clock clk{"clk", pipeline_period()};
    sc_core::sc_signal<bool> start{"start"}, load_frame{"load_frame"};
    sc_core::sc_signal<coord_t> y{"y"}, x0{"x0"};
    sc_core::sc_signal<sc_dt::sc_uint<sample_ctrl::len_bits>> len{"len"};
    sc_core::sc_signal<sc_dt::sc_uint<sample_ctrl::m_bits>> m{"m"};
    sc_core::sc_signal<sc_dt::sc_uint<1>> deg2{"deg2"};
    sc_core::sc_vector<sc_core::sc_signal<pipeline::cos_t>> nh{"nh", 4}, nl{"nl", 4};
    sc_core::sc_signal<sc_dt::sc_uint<ua60553::n_fmt.width>> n{"n"};
    sc_core::sc_vector<sc_core::sc_signal<sc_dt::sc_uint<spec::ksi_fmt.width>>> ksi{"ksi", 3};
    sc_core::sc_vector<sc_core::sc_signal<pipeline::kdi_t>> kdi{"kdi", 3};
    sc_core::sc_vector<sc_core::sc_signal<pipeline::sample_t>> amb{"amb", 3};
    outs ob, of;

    block_t blk;
    fast_t fst;
    frame_buffer fb_b, fb_f;
    geometry_source src;
    pipeline_checker chk_b, chk_f;
    pin_comparator cmp{"cmp"};

    pair_bench(const sc_core::sc_module_name& name, const plan& p, const frame_constants& k,
               const scene::device_config& dev, const plan_config& c, const typename AGen::config& gen,
               interp::sample_set fast_set)
        : sc_module(name), blk("blk", dev.mode, gen, c.set, c.div, fd_m(c), {}, {}, c.carry_samples),
          fst("fst", dev, fast_set, c.div, fd_m(c), c.carry_samples),
          fb_b("fb_b", p.width, p.height), fb_f("fb_f", p.width, p.height),
          src("src", p, k, [this] { return blk.idle() && fst.idle(); }),
          chk_b(p, k, dev, c, EVAL == evaluator::fd ? fd_m(c) : 0), chk_f(p, k, dev, c, EVAL == evaluator::fd ? fd_m(c) : 0) {
        bind(blk, ob);
        bind(fst, of);
        fb_b.clk(clk); fb_b.valid(ob.valid); fb_b.x(ob.x); fb_b.y(ob.y); fb_b.r(ob.r); fb_b.g(ob.g); fb_b.b(ob.b);
        fb_f.clk(clk); fb_f.valid(of.valid); fb_f.x(of.x); fb_f.y(of.y); fb_f.r(of.r); fb_f.g(of.g); fb_f.b(of.b);
        fb_b.on_write([this](unsigned px, unsigned py, const frame_buffer::rgb& v) { chk_b.check(px, py, v); });
        fb_f.on_write([this](unsigned px, unsigned py, const frame_buffer::rgb& v) { chk_f.check(px, py, v); });
        bind_geometry_source(src, *this, ob.ready);
        cmp.clk(clk);
        cmp.ready_b(ob.ready); cmp.ready_f(of.ready); cmp.valid_b(ob.valid); cmp.valid_f(of.valid);
        cmp.x_b(ob.x); cmp.x_f(of.x); cmp.y_b(ob.y); cmp.y_f(of.y);
        cmp.px_b[0](ob.r); cmp.px_b[1](ob.g); cmp.px_b[2](ob.b);
        cmp.px_f[0](of.r); cmp.px_f[1](of.g); cmp.px_f[2](of.b);
    }
    bool finished() const { return src.finished(); }

private:
    template <class D>
    void bind(D& d, outs& o) {
        bind_pipeline_inputs(d, *this);
        d.ready(o.ready);
        d.px_valid(o.valid); d.px_x(o.x); d.px_y(o.y); d.px_r(o.r); d.px_g(o.g); d.px_b(o.b);
    }
};

struct pair_case {
    const char* name;
    scene::specular_device device;
    evaluator eval;
    unsigned fd_m;  // forward differences: 0 any m per interval, else the fixed m
    uint64_t seed;
    bool carry = false;  // both pipelines with the carry, on a plan whose jobs chain
};
void PrintTo(const pair_case& c, std::ostream* os) { *os << c.name; }

// other_set: the fast pipeline built with the other cubic sample set (the comparison must then see
// differences: it can fail).
template <class AGen, evaluator EVAL>
void run_pair(const pair_case& pc, const typename AGen::config& gen, bool other_set = false) {
    tb::report_log::get().expect(msg::input);  // the invalid jobs, reported by both
    const plan p = random_plan(pc.seed, 400, 64, EVAL == evaluator::fd ? pc.fd_m : 0, 12, pc.carry);
    const frame_constants k = random_constants(pc.seed);
    scene::device_config dev;
    dev.device = pc.device;
    dev.mode = pc.seed % 2 ? overflow_mode::wrap : overflow_mode::saturate;
    plan_config c;
    c.carry_samples = pc.carry;
    c.eval = EVAL;
    c.length = pc.fd_m == 0 ? length_policy::adaptive : length_policy::fixed;
    c.m = pc.fd_m == 0 ? 4 : pc.fd_m;
    c.set = pc.seed % 3 ? interp::sample_set::case1 : interp::sample_set::case2;
    c.div = pc.seed % 5 ? interp::div3_mode::shift_add : interp::div3_mode::exact;
    const auto fast_set = !other_set ? c.set
                          : c.set == interp::sample_set::case1 ? interp::sample_set::case2 : interp::sample_set::case1;
    auto bench = std::make_unique<pair_bench<AGen, EVAL>>("tb", p, k, dev, c, gen, fast_set);
    uint64_t clocks = 100;  // a watchdog far beyond the plan (pipeline_sim_run.h's, doubled)
    for (const auto& j : p.jobs) clocks += 2 * (14 + 14 * 4 + 6ull * std::min(j.len, 64u));
    sc_core::sc_start(pipeline_period() * static_cast<double>(clocks));
    ASSERT_TRUE(bench->finished());
    bench->chk_b.finish();
    bench->chk_f.finish();
    if (other_set) {
        EXPECT_GT(bench->cmp.differences(), 10u);
        EXPECT_EQ(bench->chk_b.mismatches(), 0u);
        bench.release();
        return;
    }
    EXPECT_EQ(bench->cmp.differences(), 0u);
    EXPECT_GT(bench->cmp.valid_edges(), 500u);
    EXPECT_EQ(bench->chk_b.mismatches(), 0u);
    EXPECT_EQ(bench->chk_f.mismatches(), 0u);
    EXPECT_EQ(bench->chk_f.order(), bench->chk_b.order());
    EXPECT_EQ(bench->fst.dropped(), bench->chk_f.dropped());
    EXPECT_GT(bench->fst.dropped(), 5u);
    EXPECT_EQ(bench->fst.samples(), bench->blk.samples());
    EXPECT_EQ(bench->fst.carried(), bench->blk.carried());
    if (pc.carry) {
        EXPECT_GT(bench->blk.carried(), 50u);
    } else {
        EXPECT_EQ(bench->blk.carried(), 0u);
    }
    // Each invalid job is reported once by each pipeline.
    EXPECT_EQ(tb::report_log::get().count(msg::input), 2 * bench->chk_f.dropped());
    std::printf("%s: %zu pins compared over %zu edges, %zu pixels, %zu jobs dropped\n", pc.name,
                bench->cmp.valid_edges(), bench->cmp.edges(), bench->chk_f.written(), bench->chk_f.dropped());
    bench.release();  // elaborated for the process's life
}

class PipelineFastPins : public ::testing::TestWithParam<pair_case> {};

TEST_P(PipelineFastPins, SameAsBlockLevelAtEveryEdge) {
    const pair_case pc = GetParam();
    const bool horner = pc.eval == evaluator::horner;
    switch (pc.device) {
        case scene::specular_device::patent:
            if (horner) run_pair<a_gen_linear, evaluator::horner>(pc, ua60553::patent);
            else run_pair<a_gen_linear, evaluator::fd>(pc, ua60553::patent);
            break;
        case scene::specular_device::minimax:
            if (horner) run_pair<a_gen_tuned, evaluator::horner>(pc, ua60553::minimax);
            else run_pair<a_gen_tuned, evaluator::fd>(pc, ua60553::minimax);
            break;
        case scene::specular_device::rom_matched:
            if (horner) run_pair<a_gen_tuned, evaluator::horner>(pc, ua60553::rom_matched);
            else run_pair<a_gen_tuned, evaluator::fd>(pc, ua60553::rom_matched);
            break;
        case scene::specular_device::ua22802:
            if (horner) run_pair<a_gen_rom, evaluator::horner>(pc, a_gen_rom::default_config());
            else run_pair<a_gen_rom, evaluator::fd>(pc, a_gen_rom::default_config());
            break;
        case scene::specular_device::squared:
            if (horner) run_pair<squared_device, evaluator::horner>(pc, squared_device::default_config());
            else run_pair<squared_device, evaluator::fd>(pc, squared_device::default_config());
            break;
        case scene::specular_device::sqmul:
            if (horner) run_pair<sqmul_device, evaluator::horner>(pc, sqmul_device::default_config());
            else run_pair<sqmul_device, evaluator::fd>(pc, sqmul_device::default_config());
            break;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Random, PipelineFastPins,
    ::testing::Values(pair_case{"horner_patent", scene::specular_device::patent, evaluator::horner, 0, 1},
                      pair_case{"horner_ua22802", scene::specular_device::ua22802, evaluator::horner, 0, 2},
                      pair_case{"horner_minimax", scene::specular_device::minimax, evaluator::horner, 0, 3},
                      pair_case{"fd_any_m_rom_matched", scene::specular_device::rom_matched, evaluator::fd, 0, 4},
                      pair_case{"fd_m4_patent", scene::specular_device::patent, evaluator::fd, 4, 5},
                      pair_case{"fd_m2_minimax", scene::specular_device::minimax, evaluator::fd, 2, 6},
                      pair_case{"horner_squared", scene::specular_device::squared, evaluator::horner, 0, 8},
                      pair_case{"fd_any_m_squared", scene::specular_device::squared, evaluator::fd, 0, 9},
                      pair_case{"horner_patent_carry", scene::specular_device::patent, evaluator::horner, 0, 10, true},
                      pair_case{"fd_any_m_squared_carry", scene::specular_device::squared, evaluator::fd, 0, 11, true},
                      pair_case{"fd_m3_ua22802_carry", scene::specular_device::ua22802, evaluator::fd, 3, 13, true},
                      pair_case{"horner_sqmul", scene::specular_device::sqmul, evaluator::horner, 0, 14},
                      pair_case{"fd_any_m_sqmul_carry", scene::specular_device::sqmul, evaluator::fd, 0, 15, true}),
    [](const ::testing::TestParamInfo<pair_case>& i) { return std::string(i.param.name); });

// The comparison can fail: the fast pipeline built with the other sample set differs at the pins.
TEST(PipelineFastPinsVerdict, AnotherSampleSetIsSeen) {
    tb::report_log::get().expect(msg::mismatch);  // the fast frame buffer's checker
    run_pair<a_gen_linear, evaluator::horner>(
        pair_case{"horner_other_set", scene::specular_device::patent, evaluator::horner, 0, 7}, ua60553::patent, true);
}

// ---- Alone: renders through simulate_frame ----

class PipelineFastRender : public ::testing::TestWithParam<render_case> {};

// The fast pipeline's frame equals golden_frame bit for bit, every planned pixel written once in the
// plan's order, within the block level's clock bounds (test_pipeline_sim: the evaluator's clocks plus
// at most 10 per job).
TEST_P(PipelineFastRender, BitExactAgainstTheGoldenFrame) {
    const auto rc = GetParam();
    render_setup rs(rc);
    auto& [w, r, k, dev, c] = rs;
    if (rc.adaptive) {
        c.length = length_policy::adaptive;
        c.degree = degree_policy::adaptive;
    } else {
        c.degree = degree_policy::zones;
    }
    const plan p = make_plan(r, k, dev, c);
    ASSERT_GT(p.pixels, 100u);
    sim_options o;
    o.level = abstraction::fast;
    const sim_result s = simulate_frame(p, k, dev, c, o);
    EXPECT_EQ(s.mismatches, 0u);
    EXPECT_EQ(s.write_order, job_order(p));
    expect_golden_frame(s, p, k, dev, c);
    const hardware_counts hw = hardware_ops(p, c);
    EXPECT_GE(s.clocks, s.frame_load_clocks + hw.clocks);
    // The squared-quadratic device adds k + 3 clocks to each of a job's samples (sample_fsm.h;
    // k + 4 rising edges from its strobe to output 29: its synchroniser's two, taking, k, done), the
    // square-and-multiply device its squares and multiplications + 3 (the same edges around its walk).
    uint64_t per_sample = 0;
    if (dev.device == scene::specular_device::squared)
        per_sample = squared::sq_count::squarings(static_cast<unsigned>(golden_squared_a(k.n).z)) + 3;
    if (dev.device == scene::specular_device::sqmul) {
        const auto g = golden_sqmul(k.n, 0, {0, 0, 0}, overflow_mode::saturate);
        per_sample = g.squares + g.multiplies + 3;
    }
    const uint64_t per_job = 10 + 4 * per_sample;
    EXPECT_LE(s.clocks, s.frame_load_clocks + 20 + hw.clocks + per_job * p.jobs.size());
    std::printf("%s%u %s %s fast: %zu pixels, %.2f clocks/pixel, %.0f pixels per CPU second\n", rc.scene, rc.size,
                scene::device_name(rc.device), evaluator_name(rc.e), p.pixels, double(s.clocks) / p.pixels,
                s.cpu_seconds > 0 ? p.pixels / s.cpu_seconds : 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, PipelineFastRender,
    ::testing::Values(render_case{"head", 64, scene::specular_device::patent, evaluator::horner, false},
                      render_case{"head", 64, scene::specular_device::ua22802, evaluator::fd, true},
                      render_case{"sphere", 48, scene::specular_device::minimax, evaluator::horner, true},
                      render_case{"head", 64, scene::specular_device::squared, evaluator::fd, true},
                      render_case{"head", 64, scene::specular_device::sqmul, evaluator::horner, true}),
    render_case_name);

}  // namespace
