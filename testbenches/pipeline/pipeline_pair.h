// Two shading pipelines side by side on the same pins (test_pipeline_fast: the block-level model and the
// fast pin-level one; test_rtl_pipeline: the block-level model and the Verilog twin), in three parts:
//   stimulus  - random_plan, random_constants: random jobs (every m, lengths, degrees, exact pixels,
//               invalid ones) and frame constants, presented by pipeline_bench.h's geometry_source;
//   monitor   - pin_comparator: every pin of the two compared at every edge of the clock (ready at
//               every edge, px_valid / px_x / px_y at rising edges, px_r/g/b where px_valid = 1),
//               and one frame buffer per pipeline;
//   checker   - one pipeline_checker per frame buffer: every pixel against golden_interval.
// pair_bench holds the clock, the pins, both pipelines and the three parts.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <systemc>
#include <type_traits>
#include <utility>

#include "testbenches/common/bench_source.h"
#include "pipeline_bench.h"

namespace shading::pipeline {

// A random plan on a frame `w` wide: jobs placed left to right, line after line, never overlapping;
// about one in `bad_every` invalid (len 0, len > 2^m, m 1 or 7, an exact quadratic; refused and
// reported by the SystemC pipelines), the rest valid for the evaluator (fd_m != 0: that m or
// exact pixels). chain: about half the jobs start at the codes of the job before's last sample, as a
// planned line's do (the carry's case). nh_above_one: about one N.H code in four above 1.0 (the
// device's input checker reports them; its overflow mode decides what it makes of them).
inline plan random_plan(uint64_t seed, std::size_t jobs, unsigned w, unsigned fd_m, unsigned bad_every,
                        bool chain = false, bool nh_above_one = false) {
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
            // Q1.15 codes in [0, 1].
            const uint64_t one = uint64_t{1} << spec::cos_fmt.frac;
            s.cos_nl = static_cast<uint32_t>(r.range(0, one));
            s.cos_nh = s.cos_nl == 0 ? 0 : static_cast<uint32_t>(r.range(0, one));
            if (nh_above_one && r.range(0, 3) == 0)
                s.cos_nh = static_cast<uint32_t>(r.range(one + 1, spec::cos_fmt.mask()));
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

inline frame_constants random_constants(uint64_t seed) {
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

// Clocks a pair run is given before it counts as hung: far beyond the plan (pipeline_sim_run.h's
// bound, doubled; 14 clocks a sample covers the square-and-multiply device's longest walk).
inline uint64_t pair_watchdog_clocks(const plan& p) {
    uint64_t clocks = 100;
    for (const auto& j : p.jobs) clocks += 2 * (14 + 14 * 4 + 6ull * std::min(j.len, 64u));
    return clocks;
}

// Compares the two pipelines' pins at every edge (samples taken after the edge's writes settle:
// at the next opposite edge, which reads the values both held through the phase). _b: the block-level
// pipeline's, _o: the other's.
class pin_comparator : public sc_core::sc_module {
public:
    using coord_t = sc_dt::sc_uint<16>;
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> ready_b{"ready_b"}, ready_o{"ready_o"}, valid_b{"valid_b"}, valid_o{"valid_o"};
    sc_core::sc_in<coord_t> x_b{"x_b"}, x_o{"x_o"}, y_b{"y_b"}, y_o{"y_o"};
    sc_core::sc_vector<sc_core::sc_in<pipeline::sample_t>> px_b{"px_b", 3}, px_o{"px_o", 3};

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
        bool same = ready_b.read() == ready_o.read();
        if (clk.read()) {
            same = same && valid_b.read() == valid_o.read() && x_b.read() == x_o.read() && y_b.read() == y_o.read();
            if (valid_b.read()) {
                ++valid_edges_;
                for (int c = 0; c < 3; ++c) same = same && px_b[c].read() == px_o[c].read();
            }
        }
        if (!same && diffs_++ < 5) {
            std::printf("pins differ at %s (%s edge): ready %d/%d valid %d/%d x %u/%u y %u/%u r %x/%x g %x/%x b %x/%x\n",
                        sc_core::sc_time_stamp().to_string().c_str(), clk.read() ? "rising" : "falling",
                        int(ready_b.read()), int(ready_o.read()), int(valid_b.read()), int(valid_o.read()),
                        x_b.read().to_uint(), x_o.read().to_uint(), y_b.read().to_uint(), y_o.read().to_uint(),
                        px_b[0].read().to_uint(), px_o[0].read().to_uint(), px_b[1].read().to_uint(),
                        px_o[1].read().to_uint(), px_b[2].read().to_uint(), px_o[2].read().to_uint());
        }
    }
    std::size_t diffs_ = 0, edges_ = 0, valid_edges_ = 0;
};

// One wire from a 1-bit bus to a bool pin: `verilator --pins-sc-uint` (5.006 has no option for
// it) makes a Verilated model's 1-wire pins bool, where our in_deg2 is sc_uint<1>.
class bit_to_bool : public sc_core::sc_module {
public:
    sc_core::sc_in<sc_dt::sc_uint<1>> x{"x"};
    sc_core::sc_out<bool> y{"y"};

    SC_HAS_PROCESS(bit_to_bool);
    explicit bit_to_bool(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(follow);
        sensitive << x;
    }

private:
    void follow() { y.write(x.read() == 1); }
};

// The block-level shading_pipeline<AGen, EVAL> (`blk`) and `other`, any module with the pipeline's
// pins (pipeline_pins.h; in_deg2 sc_uint<1> or bool), built from `other_args`, on the same input
// signals and clock; each with its frame buffer and checker; one source, which stops the simulation
// when both pipelines are idle (`other_idle`: the other's own account, or none) and the last pixels
// have been sampled.
template <class AGen, evaluator EVAL, class Other>
class pair_bench : public sc_core::sc_module {
public:
    using coord_t = sc_dt::sc_uint<16>;
    using block_t = shading_pipeline<AGen, EVAL>;
    // One pipeline's outputs, named <pin>_<side> in a trace (side b: the block level, o: the other).
    struct outs {
        explicit outs(const std::string& side)
            : ready(("ready_" + side).c_str()), valid(("px_valid_" + side).c_str()), x(("px_x_" + side).c_str()),
              y(("px_y_" + side).c_str()), r(("px_r_" + side).c_str()), g(("px_g_" + side).c_str()),
              b(("px_b_" + side).c_str()) {}
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
    sc_core::sc_signal<bool> deg2_bit{"deg2_bit"};  // deg2 for a bool pin (bit_to_bool)
    sc_core::sc_vector<sc_core::sc_signal<pipeline::cos_t>> nh{"nh", 4}, nl{"nl", 4};
    sc_core::sc_signal<sc_dt::sc_uint<ua60553::n_fmt.width>> n{"n"};
    sc_core::sc_vector<sc_core::sc_signal<sc_dt::sc_uint<spec::ksi_fmt.width>>> ksi{"ksi", 3};
    sc_core::sc_vector<sc_core::sc_signal<pipeline::kdi_t>> kdi{"kdi", 3};
    sc_core::sc_vector<sc_core::sc_signal<pipeline::sample_t>> amb{"amb", 3};
    outs ob{"b"}, oo{"o"};

    block_t blk;
    Other other;
    frame_buffer fb_b, fb_o;
    geometry_source src;
    pipeline_checker chk_b, chk_o;
    pin_comparator cmp{"cmp"};
    std::unique_ptr<bit_to_bool> deg2_wire;  // only when the other's in_deg2 is bool

    template <class... OtherArgs>
    pair_bench(const sc_core::sc_module_name& name, const plan& p, const frame_constants& k,
               const scene::device_config& dev, const plan_config& c, const typename AGen::config& gen,
               std::function<bool(const Other&)> other_idle, OtherArgs&&... other_args)
        : sc_module(name), blk("blk", dev.mode, gen, c.set, c.div, fd_m(c), {}, {}, c.carry_samples),
          other(std::forward<OtherArgs>(other_args)...),
          fb_b("fb_b", p.width, p.height), fb_o("fb_o", p.width, p.height),
          src("src", p, k, [this, other_idle] { return blk.idle() && (!other_idle || other_idle(other)); }),
          chk_b(p, k, dev, c, EVAL == evaluator::fd ? fd_m(c) : 0), chk_o(p, k, dev, c, EVAL == evaluator::fd ? fd_m(c) : 0) {
        // (A Verilated model's ports are references: decltype gives sc_in<bool>&.)
        if constexpr (std::is_same_v<std::remove_reference_t<decltype(other.in_deg2)>, sc_core::sc_in<bool>>) {
            deg2_wire = std::make_unique<bit_to_bool>("deg2_wire");
            deg2_wire->x(deg2);
            deg2_wire->y(deg2_bit);
        }
        bind(blk, ob);
        bind(other, oo);
        fb_b.clk(clk); fb_b.valid(ob.valid); fb_b.x(ob.x); fb_b.y(ob.y); fb_b.r(ob.r); fb_b.g(ob.g); fb_b.b(ob.b);
        fb_o.clk(clk); fb_o.valid(oo.valid); fb_o.x(oo.x); fb_o.y(oo.y); fb_o.r(oo.r); fb_o.g(oo.g); fb_o.b(oo.b);
        fb_b.on_write([this](unsigned px, unsigned py, const frame_buffer::rgb& v) { chk_b.check(px, py, v); });
        fb_o.on_write([this](unsigned px, unsigned py, const frame_buffer::rgb& v) { chk_o.check(px, py, v); });
        bind_geometry_source(src, *this, ob.ready);
        cmp.clk(clk);
        cmp.ready_b(ob.ready); cmp.ready_o(oo.ready); cmp.valid_b(ob.valid); cmp.valid_o(oo.valid);
        cmp.x_b(ob.x); cmp.x_o(oo.x); cmp.y_b(ob.y); cmp.y_o(oo.y);
        cmp.px_b[0](ob.r); cmp.px_b[1](ob.g); cmp.px_b[2](ob.b);
        cmp.px_o[0](oo.r); cmp.px_o[1](oo.g); cmp.px_o[2](oo.b);
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

}  // namespace shading::pipeline
