// Testbench of the SystemC shading pipeline, in three parts around the device under test:
//   geometry_source - the geometry side: loads the frame constants, then presents every job of a
//                     plan on the pins through the start/ready handshake (sample_ctrl.h);
//   monitor         - the frame buffer's write port: every pixel stored at a valid edge;
//   checker         - golden_interval per job (pipeline.h): every written pixel against its job's
//                     golden codes; missing and unexpected pixels count as mismatches too.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <systemc>
#include <vector>

#include "core/report_ids.h"
#include "pipeline/frame_buffer.h"
#include "golden_pipeline/pipeline.h"
#include "pipeline/shading_pipeline.h"

namespace shading {
// The fast abstraction (pipeline/shading_pipeline_fast.h), included only where a fast bench is built
// (pipeline_sim_fast.cpp), so the block-level runs do not recompile when it changes.
template <pipeline::evaluator EVAL>
class shading_pipeline_fast;
}  // namespace shading

namespace shading::pipeline {

inline sc_core::sc_time pipeline_period() { return sc_core::sc_time(20, sc_core::SC_NS); }

// The m the forward-difference evaluator is built for: c.m with a fixed length, 0 (fd_eval_var, any
// m per interval) with an adaptive one.
inline unsigned fd_m(const plan_config& c) { return c.length == length_policy::fixed ? c.m : 0; }

// Which jobs the hardware takes (sample_ctrl.h's rule, written here independently): m 0 or
// m_min..m_max, len 1..2^m, an exact pixel cubic, and with forward differences built for fd_m only
// that m (or an exact pixel).
inline bool job_ok(const interval_job& j, unsigned fd_m) {
    const bool exact = j.m == 0;
    if (!exact && (j.m < interp::m_min || j.m > interp::m_max)) return false;
    if (j.len < 1 || j.len > (1u << j.m) || (exact && j.deg2)) return false;
    return fd_m == 0 || exact || j.m == fd_m;
}

// Expected pixels and the verdict (the checker).
class pipeline_checker {
public:
    pipeline_checker(const plan& p, const frame_constants& k, const scene::device_config& dev, const plan_config& c,
                     unsigned fd_m)
        : w_(p.width), h_(p.height), expected_(std::size_t(p.width) * p.height), wanted_(expected_.size(), 0) {
        for (const auto& j : p.jobs) {
            if (!job_ok(j, fd_m)) {
                ++dropped_;
                continue;
            }
            const auto px = golden_interval(j, k, dev, c.eval, c.set, c.div);
            for (unsigned i = 0; i < j.len; ++i) {
                const unsigned x = j.x0 + i;
                if (x >= w_ || j.y >= h_) continue;  // the frame buffer drops it (reported)
                const std::size_t at = std::size_t(j.y) * w_ + x;
                expected_[at] = px[i];
                ++wanted_[at];
                ++pixels_;
            }
        }
    }

    void check(unsigned x, unsigned y, const frame_buffer::rgb& got) {
        const std::size_t at = std::size_t(y) * w_ + x;
        if (keep_order_) order_.push_back(at);
        rgb_codes g{got[0], got[1], got[2]};
        if (written_++ == inject_) g[0] ^= 1;  // as if the golden codes differed
        if (wanted_[at] == 0) {
            mismatch(x, y, g, "no job covers this pixel (or it was written already)");
            return;
        }
        --wanted_[at];
        if (g != expected_[at]) mismatch(x, y, g, "differs from golden_interval");
    }

    // After the run: pixels never written.
    void finish() {
        for (std::size_t i = 0; i < wanted_.size(); ++i)
            if (wanted_[i] != 0) {
                mismatches_ += wanted_[i];
                if (reported_++ < 10) {
                    std::ostringstream os;
                    os << "pixel (" << i % w_ << ", " << i / w_ << ") was never written";
                    SC_REPORT_WARNING(msg::mismatch, os.str().c_str());
                }
            }
    }

    void inject_mismatch(std::size_t k) { inject_ = k; }
    // Off: the writes are counted but their order is not kept (8 bytes per write: a long soak
    // would otherwise see the log's growth, not the model's).
    void keep_order(bool on) { keep_order_ = on; }
    std::size_t pixels() const { return pixels_; }
    std::size_t written() const { return written_; }
    std::size_t mismatches() const { return mismatches_; }
    std::size_t dropped() const { return dropped_; }
    const std::vector<std::size_t>& order() const { return order_; }  // empty unless keep_order

private:
    void mismatch(unsigned x, unsigned y, const rgb_codes& got, const char* why) {
        ++mismatches_;
        if (reported_++ >= 10) return;
        const std::size_t at = std::size_t(y) * w_ + x;
        std::ostringstream os;
        os << "pixel (" << x << ", " << y << ") at " << sc_core::sc_time_stamp() << ": " << why << ": sim " << std::hex
           << got[0] << " " << got[1] << " " << got[2] << ", golden " << expected_[at][0] << " " << expected_[at][1]
           << " " << expected_[at][2] << " [Q8.8 codes]";
        SC_REPORT_WARNING(msg::mismatch, os.str().c_str());
    }

    unsigned w_, h_;
    std::vector<rgb_codes> expected_;
    // Writes each pixel is still owed: 32 bits, as a plan may repeat a frame (soak_pipeline renders the
    // head 1000 times in one simulation; 8 bits wrapped at 256 and called every later write unexpected).
    std::vector<uint32_t> wanted_;
    std::vector<std::size_t> order_;
    bool keep_order_ = true;
    std::size_t written_ = 0, pixels_ = 0, mismatches_ = 0, dropped_ = 0, reported_ = 0, inject_ = SIZE_MAX;
};

// The geometry side: drives the pins at rising edges of clk (sample_ctrl.h's handshake: a request
// present at a rising edge where ready = 1 is taken at the falling edge after it, so the pins are
// held until the next rising edge).
class geometry_source : public sc_core::sc_module {
public:
    using coord_t = sc_dt::sc_uint<16>;
    using cos_t = pipeline::cos_t;

    sc_core::sc_in<bool> clk{"clk"}, ready{"ready"};
    sc_core::sc_out<bool> start{"start"}, load_frame{"load_frame"};
    sc_core::sc_out<coord_t> y{"y"}, x0{"x0"};
    sc_core::sc_out<sc_dt::sc_uint<sample_ctrl::len_bits>> len{"len"};
    sc_core::sc_out<sc_dt::sc_uint<sample_ctrl::m_bits>> m{"m"};
    sc_core::sc_out<sc_dt::sc_uint<1>> deg2{"deg2"};
    sc_core::sc_vector<sc_core::sc_out<cos_t>> nh{"nh", 4}, nl{"nl", 4};
    sc_core::sc_out<sc_dt::sc_uint<ua60553::n_fmt.width>> n{"n"};
    sc_core::sc_vector<sc_core::sc_out<sc_dt::sc_uint<spec::ksi_fmt.width>>> ksi{"ksi", 3};
    sc_core::sc_vector<sc_core::sc_out<pipeline::kdi_t>> kdi{"kdi", 3};
    sc_core::sc_vector<sc_core::sc_out<pipeline::sample_t>> amb{"amb", 3};

    SC_HAS_PROCESS(geometry_source);
    geometry_source(const sc_core::sc_module_name& name, const plan& p, const frame_constants& k,
                    std::function<bool()> drained)
        : sc_module(name), p_(p), k_(k), drained_(std::move(drained)) {
        SC_THREAD(run);
        sensitive << clk.pos();
    }

    bool finished() const { return finished_; }
    uint64_t frame_loaded_at_edge() const { return frame_edge_; }

private:
    // Hold the request until it is taken, then return at the next rising edge. Ready at this rising
    // edge: taken at the falling edge after it. Else ready rises at some falling edge F and the
    // request is taken at F + 1 clock; the next rising edge after that is F + 1.5 clocks. (Waiting on
    // ready's event, not polling every clock: the source sleeps through a long interval.)
    void take() {
        if (!ready.read()) {
            wait(ready.posedge_event());
            wait();
        }
        wait();
    }

    void run() {
        wait();
        n.write(k_.n);
        for (int c = 0; c < 3; ++c) {
            ksi[c].write(k_.ksi[c]);
            kdi[c].write(k_.kdi[c]);
            amb[c].write(k_.ambient[c]);
        }
        load_frame.write(true);
        take();
        load_frame.write(false);
        frame_edge_ = static_cast<uint64_t>(sc_core::sc_time_stamp() / pipeline_period());
        for (const auto& j : p_.jobs) {
            y.write(j.y);
            x0.write(j.x0);
            len.write(j.len);
            m.write(j.m);
            deg2.write(j.deg2 ? 1 : 0);
            for (int i = 0; i < 4; ++i) {
                nh[i].write(j.s[i].cos_nh);
                nl[i].write(j.s[i].cos_nl);
            }
            start.write(true);
            take();
        }
        start.write(false);
        do wait();
        while (!drained_());
        wait();
        wait();
        finished_ = true;
        sc_core::sc_stop();
    }

    const plan& p_;
    frame_constants k_;
    std::function<bool()> drained_;
    bool finished_ = false;
    uint64_t frame_edge_ = 0;
};

// in_deg2: our sc_uint<1> pin on the bench's deg2, or a Verilated model's bool pin (verilator
// --pins-sc-uint makes 1-wire pins bool) on its deg2_bit (pipeline_pair.h's bit_to_bool).
template <class B>
void bind_deg2(sc_core::sc_in<sc_dt::sc_uint<1>>& pin, B& b) {
    pin(b.deg2);
}
template <class B>
void bind_deg2(sc_core::sc_in<bool>& pin, B& b) {
    pin(b.deg2_bit);
}

// A pipeline's input pins (D: shading_pipeline, shading_pipeline_fast or the Verilog twin) and the
// geometry source's outputs bound to a bench's signals of the same names (pipeline_bench; the
// pairs of pipeline_pair.h).
template <class D, class B>
void bind_pipeline_inputs(D& d, B& b) {
    d.clk(b.clk); d.start(b.start); d.load_frame(b.load_frame);
    d.in_y(b.y); d.in_x0(b.x0); d.in_len(b.len); d.in_m(b.m);
    bind_deg2(d.in_deg2, b);
    d.in_nh1(b.nh[0]); d.in_nh2(b.nh[1]); d.in_nh3(b.nh[2]); d.in_nh4(b.nh[3]);
    d.in_nl1(b.nl[0]); d.in_nl2(b.nl[1]); d.in_nl3(b.nl[2]); d.in_nl4(b.nl[3]);
    d.in_n(b.n);
    d.in_ksi_r(b.ksi[0]); d.in_ksi_g(b.ksi[1]); d.in_ksi_b(b.ksi[2]);
    d.in_kdi_r(b.kdi[0]); d.in_kdi_g(b.kdi[1]); d.in_kdi_b(b.kdi[2]);
    d.in_amb_r(b.amb[0]); d.in_amb_g(b.amb[1]); d.in_amb_b(b.amb[2]);
}
template <class B>
void bind_geometry_source(geometry_source& src, B& b, sc_core::sc_signal<bool>& ready) {
    src.clk(b.clk); src.ready(ready); src.start(b.start); src.load_frame(b.load_frame);
    src.y(b.y); src.x0(b.x0); src.len(b.len); src.m(b.m); src.deg2(b.deg2);
    for (int i = 0; i < 4; ++i) {
        src.nh[i](b.nh[i]);
        src.nl[i](b.nl[i]);
    }
    src.n(b.n);
    for (int c = 0; c < 3; ++c) {
        src.ksi[c](b.ksi[c]);
        src.kdi[c](b.kdi[c]);
        src.amb[c](b.amb[c]);
    }
}

// The bench: clock, pins, the pipeline, the frame buffer, the geometry source and the checker. FAST:
// the fast pin-level abstraction (shading_pipeline_fast.h, which names the device by `dev` and
// ignores `gen`) instead of the block-level pipeline.
template <class AGen, evaluator EVAL, bool FAST = false>
class pipeline_bench : public sc_core::sc_module {
public:
    using dut_t = std::conditional_t<FAST, shading_pipeline_fast<EVAL>, shading_pipeline<AGen, EVAL>>;
    using coord_t = sc_dt::sc_uint<16>;

    sc_core::sc_clock clk{"clk", pipeline_period()};
    sc_core::sc_signal<bool> start{"start"}, load_frame{"load_frame"}, ready{"ready"};
    sc_core::sc_signal<coord_t> y{"y"}, x0{"x0"};
    sc_core::sc_signal<sc_dt::sc_uint<sample_ctrl::len_bits>> len{"len"};
    sc_core::sc_signal<sc_dt::sc_uint<sample_ctrl::m_bits>> m{"m"};
    sc_core::sc_signal<sc_dt::sc_uint<1>> deg2{"deg2"};
    sc_core::sc_vector<sc_core::sc_signal<pipeline::cos_t>> nh{"nh", 4}, nl{"nl", 4};
    sc_core::sc_signal<sc_dt::sc_uint<ua60553::n_fmt.width>> n{"n"};
    sc_core::sc_vector<sc_core::sc_signal<sc_dt::sc_uint<spec::ksi_fmt.width>>> ksi{"ksi", 3};
    sc_core::sc_vector<sc_core::sc_signal<pipeline::kdi_t>> kdi{"kdi", 3};
    sc_core::sc_vector<sc_core::sc_signal<pipeline::sample_t>> amb{"amb", 3};
    sc_core::sc_signal<bool> px_valid{"px_valid"};
    sc_core::sc_signal<coord_t> px_x{"px_x"}, px_y{"px_y"};
    sc_core::sc_signal<pipeline::sample_t> px_r{"px_r"}, px_g{"px_g"}, px_b{"px_b"};

    dut_t dut;
    frame_buffer fb;
    geometry_source src;
    pipeline_checker checker;

    // others_done (empty: none): a unit run beside the pipeline in the same simulation, which the
    // source waits for too before it stops the simulation.
    pipeline_bench(const sc_core::sc_module_name& name, const plan& p, const frame_constants& k,
                   const scene::device_config& dev, const plan_config& c, const typename AGen::config& gen,
                   std::function<void(std::size_t, std::size_t)> progress, std::function<bool()> others_done = {})
        : sc_module(name), dut(make_dut("dut", dev, gen, c)), fb("fb", p.width, p.height),
          src("src", p, k, [this, others_done] { return dut.idle() && (!others_done || others_done()); }),
          checker(p, k, dev, c, EVAL == evaluator::fd ? fd_m(c) : 0), progress_(std::move(progress)) {
        bind_pipeline_inputs(dut, *this);
        dut.ready(ready);
        dut.px_valid(px_valid); dut.px_x(px_x); dut.px_y(px_y);
        dut.px_r(px_r); dut.px_g(px_g); dut.px_b(px_b);

        fb.clk(clk); fb.valid(px_valid); fb.x(px_x); fb.y(px_y); fb.r(px_r); fb.g(px_g); fb.b(px_b);
        fb.on_write([this](unsigned px, unsigned py, const frame_buffer::rgb& v) {
            checker.check(px, py, v);
            last_write_ = sc_core::sc_time_stamp();
            const std::size_t done = checker.written();
            if (progress_ && (done % 4096 == 0 || done == checker.pixels())) progress_(done, checker.pixels());
        });

        bind_geometry_source(src, *this, ready);
    }

    bool finished() const { return src.finished(); }
    const sc_core::sc_time& last_write() const { return last_write_; }

private:
    // The DUT's constructor by abstraction (guaranteed copy elision: a module is built in place).
    static dut_t make_dut(const char* name, const scene::device_config& dev, const typename AGen::config& gen,
                          const plan_config& c) {
        if constexpr (FAST) return dut_t(name, dev, c.set, c.div, fd_m(c), c.carry_samples);
        else return dut_t(name, dev.mode, gen, c.set, c.div, fd_m(c), {}, {}, c.carry_samples);
    }

    std::function<void(std::size_t, std::size_t)> progress_;
    sc_core::sc_time last_write_;
};

}  // namespace shading::pipeline
