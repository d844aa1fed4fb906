// The memories' Verilog twins (rtl/blocks/ram.v, rtl/pipeline/frame_buffer.v, walker_store.v,
// band_buffer.v, verilated with --sc) co-simulated with the SystemC blocks (modules/blocks/ram.h,
// modules/pipeline/frame_buffer.h, cell_stores.h) on the same pins and clock, both held to the bench's
// own record of what was written (the independent reference): the RAM at every edge (random writes,
// some beyond its words, random reads), the frame buffer on a pixel stream (a whole frame, then
// random rewrites and writes outside the frame) read back word by word through the RTL's read port
// and the model's back door, the cells' stores on the replay of the head at 512's cell plan
// (testbenches/pipeline/cell_store_replay.h). The negative test corrupts one word of the frame's
// record: both sides must be seen to differ from it, once each.
// SHADING_TRACE=<dir>: <dir>/<Suite.Test>.vcd and <dir>/<Suite.Test>_rtl.vcd.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "blocks/ram.h"
#include "core/report_ids.h"
#include "pipeline/frame_buffer.h"
#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/rtl/rtl_cosim_tb.h"
#include "verilated.h"

// The verilated memories (testbenches/rtl/memories.cmake): ram.v at W = 16, DEPTH = 48, AW = 6;
// frame_buffer.v at 48 x 40 (pitch 64: 6 + 6 address wires, 2560 words).
#include "Vrtl_band_buffer.h"
#include "Vrtl_frame_buffer.h"
#include "Vrtl_ram.h"
#include "Vrtl_walker_store.h"
#include "golden_pipeline/frame_setup.h"
#include "golden_pipeline/race.h"
#include "scene/scanline.h"
#include "testbenches/pipeline/cell_store_replay.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_rtl_memories {

using namespace shading;

namespace {

const sc_core::sc_time period(10, sc_core::SC_NS), settle(1, sc_core::SC_NS);

// ram<16, 6> of 48 words and ram.v the same, on one set of signals: a random write and read at
// every clock (wa over all 64 addresses: 16 name no word), each side's rd and overflow checked
// after every edge against the record.
class ram_pair_bench : public sc_core::sc_module {
public:
    static constexpr unsigned words = 48;
    using mem_t = ram<16, 6>;
    sc_core::sc_clock clk{"clk", period};
    sc_core::sc_signal<bool> we{"we"}, overflow_b{"overflow_b"}, overflow_o{"overflow_o"};
    sc_core::sc_signal<mem_t::addr_t> wa{"wa"}, ra{"ra"};
    sc_core::sc_signal<mem_t::word> wd{"wd"}, rd_b{"rd_b"}, rd_o{"rd_o"};
    mem_t dut{"dut", words};
    Vrtl_ram rtl{"rtl"};
    std::size_t checks = 0, mismatches = 0, dropped = 0;

    SC_HAS_PROCESS(ram_pair_bench);
    ram_pair_bench(const sc_core::sc_module_name& name, std::size_t clocks, uint32_t seed)
        : sc_module(name), clocks_(clocks), rng_(seed), record_(words, 0) {
        dut.clk(clk); dut.we(we); dut.wa(wa); dut.ra(ra); dut.wd(wd); dut.rd(rd_b); dut.overflow(overflow_b);
        rtl.clk(clk); rtl.we(we); rtl.wa(wa); rtl.ra(ra); rtl.wd(wd); rtl.rd(rd_o); rtl.overflow(overflow_o);
        SC_THREAD(run);
    }
    bool finished() const { return done_; }

private:
    void run() {
        bool was_we = false, flag = false;
        unsigned was_wa = 0, was_wd = 0;
        std::uniform_int_distribution<unsigned> addr(0, 63), data(0, 0xFFFF), coin(0, 3);
        for (std::size_t i = 0; i < clocks_; ++i) {
            wait(clk.posedge_event());
            wait(settle);
            if (was_we && was_wa < words) record_[was_wa] = was_wd;
            if (was_we && was_wa >= words) {
                flag = true;
                ++dropped;
            }
            const unsigned a = ra.read().to_uint(), want = a < words ? record_[a] : 0;
            for (unsigned got : {rd_b.read().to_uint(), rd_o.read().to_uint()}) mismatches += got != want;
            mismatches += (overflow_b.read() != flag) + (overflow_o.read() != flag);
            ++checks;
            was_we = coin(rng_) != 0;
            was_wa = addr(rng_) % (coin(rng_) == 0 ? 64 : words);  // a quarter over all 64 addresses
            was_wd = data(rng_);
            we.write(was_we); wa.write(was_wa); wd.write(was_wd); ra.write(addr(rng_) % words);
        }
        done_ = true;
    }

    std::size_t clocks_;
    std::mt19937 rng_;
    std::vector<unsigned> record_;
    bool done_ = false;
};

// One write of the pixel stream: at the edge after it is presented, valid = 0 or a pixel at (x, y).
struct pixel_write {
    bool valid;
    unsigned x, y;
    uint16_t r, g, b;
};

// frame_buffer (the model) and frame_buffer.v at width x height on the same stream; afterwards every
// word of the RTL's RAM read through its read port, and the model's through pixel(), against the
// record (a word of a pixel never written: 0).
class frame_pair_bench : public sc_core::sc_module {
public:
    static constexpr unsigned width = 48, height = 40, pitch = 64, aw = 12;
    using coord_t = frame_buffer::coord_t;
    using px_t = frame_buffer::px_t;
    sc_core::sc_clock clk{"clk", period};
    sc_core::sc_signal<bool> valid{"valid"}, overflow_o{"overflow_o"};
    sc_core::sc_signal<coord_t> x{"x"}, y{"y"};
    sc_core::sc_signal<px_t> r{"r"}, g{"g"}, b{"b"};
    sc_core::sc_signal<sc_dt::sc_uint<aw>> ra{"ra"};
    sc_core::sc_signal<sc_dt::sc_uint<48>> rd_o{"rd_o"};
    frame_buffer dut{"dut", width, height};
    Vrtl_frame_buffer rtl{"rtl"};
    std::size_t words_read = 0, mismatches_b = 0, mismatches_o = 0;

    SC_HAS_PROCESS(frame_pair_bench);
    frame_pair_bench(const sc_core::sc_module_name& name, std::vector<pixel_write> stream,
                     std::vector<uint64_t> record)
        : sc_module(name), stream_(std::move(stream)), record_(std::move(record)) {
        dut.clk(clk); dut.valid(valid); dut.x(x); dut.y(y); dut.r(r); dut.g(g); dut.b(b);
        rtl.clk(clk); rtl.valid(valid); rtl.x(x); rtl.y(y); rtl.r(r); rtl.g(g); rtl.b(b);
        rtl.ra(ra); rtl.rd(rd_o); rtl.overflow(overflow_o);
        SC_THREAD(run);
    }
    bool finished() const { return done_; }

private:
    void run() {
        for (const pixel_write& w : stream_) {
            wait(clk.posedge_event());
            wait(settle);
            valid.write(w.valid); x.write(w.x); y.write(w.y); r.write(w.r); g.write(w.g); b.write(w.b);
        }
        wait(clk.posedge_event());
        wait(settle);
        valid.write(false);
        for (unsigned a = 0; a < pitch * height; ++a) {
            ra.write(a);
            wait(settle);
            ++words_read;
            mismatches_o += rd_o.read().to_uint64() != record_[a];
            const unsigned px = a % pitch, py = a / pitch;
            if (px >= width) continue;  // no pixel: the model's back door names pixels only
            const frame_buffer::rgb v = dut.pixel(px, py);
            const uint64_t word = uint64_t(v[0]) << 32 | uint64_t(v[1]) << 16 | v[2];
            mismatches_b += word != record_[a];
        }
        done_ = true;
    }

    std::vector<pixel_write> stream_;
    std::vector<uint64_t> record_;
    bool done_ = false;
};

// The bench made in a statement of its own before (its sc_module_name gone: elaboration complete).
template <class Bench>
Bench& run(Bench* bench, const sc_core::sc_time& limit) {
    Verilated::traceEverOn(true);
    const char* dir = std::getenv("SHADING_TRACE");
    const std::string stem = dir && *dir ? std::string(dir) + "/" + tb::current_test_name() : std::string();
    EXPECT_TRUE(tb::run_cosim(*bench, limit, stem));
    return *bench;
}

// The stream: every pixel of the frame once (raster order, a gap of valid = 0 every seventh
// clock), then `extra` random writes: rewrites in the frame and, one in eight, outside it (x up to
// the pitch and beyond, y beyond the height). The record: the word each address holds after it.
struct frame_stream {
    std::vector<pixel_write> writes;
    std::vector<uint64_t> record;
    std::size_t stored = 0, outside = 0;
};
frame_stream make_stream(uint32_t seed, std::size_t extra) {
    using B = frame_pair_bench;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<unsigned> code(0, 0xFFFF), coin(0, 7);
    frame_stream s;
    s.record.assign(B::pitch * B::height, 0);
    auto put = [&](unsigned px, unsigned py) {
        const pixel_write w{true, px, py, uint16_t(code(rng)), uint16_t(code(rng)), uint16_t(code(rng))};
        s.writes.push_back(w);
        if (px >= B::width || py >= B::height) return void(++s.outside);
        s.record[py * B::pitch + px] = uint64_t(w.r) << 32 | uint64_t(w.g) << 16 | w.b;
        ++s.stored;
    };
    for (unsigned py = 0; py < B::height; ++py)
        for (unsigned px = 0; px < B::width; ++px) {
            if ((py * B::width + px) % 7 == 3) s.writes.push_back({false, px, py, 1, 2, 3});
            put(px, py);
        }
    std::uniform_int_distribution<unsigned> fx(0, B::width - 1), fy(0, B::height - 1), far(0, 0xFFFF);
    for (std::size_t i = 0; i < extra; ++i) {
        if (coin(rng) != 0) put(fx(rng), fy(rng));
        else if (coin(rng) < 4) put(B::width + fx(rng) % (B::pitch - B::width), fy(rng));  // in the pitch's padding
        else put(far(rng), B::height + far(rng) % 100);  // beyond the height
    }
    return s;
}

}  // namespace

TEST(RtlRam, RandomWritesReadsAndDropsEveryEdge) {
    tb::report_log::get().expect(msg::input);  // the model's report of each dropped write
    auto* bench = new ram_pair_bench("tb", 5000, 20261206);
    auto& b = run(bench, period * 5100.0);
    EXPECT_EQ(b.checks, 5000u);
    EXPECT_EQ(b.mismatches, 0u) << "rd and overflow of both sides against the record";
    EXPECT_GT(b.dropped, 100u);
    EXPECT_EQ(tb::report_log::get().count(msg::input), b.dropped) << "each dropped write reported";
    std::printf("%zu edges, %zu writes stored, %zu dropped\n", b.checks, b.dut.writes(), b.dropped);
}

TEST(RtlFrameBuffer, StreamWithWritesOutsideTheFrameReadsBackEveryWord) {
    tb::report_log::get().expect(msg::input);
    const frame_stream s = make_stream(77, 3000);
    auto* bench = new frame_pair_bench("tb", s.writes, s.record);
    auto& b = run(bench, period * double(s.writes.size() + 100) + settle * 3000.0);
    EXPECT_EQ(b.words_read, 64u * 40u);
    EXPECT_EQ(b.mismatches_o, 0u) << "the RTL's words against the record";
    EXPECT_EQ(b.mismatches_b, 0u) << "the model's pixels against the record";
    EXPECT_EQ(b.dut.writes(), s.stored);
    EXPECT_EQ(tb::report_log::get().count(msg::input), s.outside) << "each write outside the frame reported";
    EXPECT_GT(s.outside, 100u);
    EXPECT_TRUE(b.overflow_o.read());
    EXPECT_TRUE(b.dut.overflow());
    EXPECT_EQ(b.dut.words(), 64u * 40u);
    EXPECT_EQ(b.dut.bits(), 64u * 40u * 48u);
}

// No write outside the frame: neither flag is set.
TEST(RtlFrameBuffer, AWholeFrameInsideLeavesTheFlagsClear) {
    const frame_stream s = make_stream(78, 0);
    auto* bench = new frame_pair_bench("tb", s.writes, s.record);
    auto& b = run(bench, period * double(s.writes.size() + 100) + settle * 3000.0);
    EXPECT_EQ(s.outside, 0u);
    EXPECT_EQ(b.mismatches_o + b.mismatches_b, 0u);
    EXPECT_EQ(b.dut.writes(), 48u * 40u);
    EXPECT_FALSE(b.overflow_o.read());
    EXPECT_FALSE(b.dut.overflow());
}

// The read-back can fail: one word of the record corrupted is one mismatch on each side.
TEST(RtlFrameBufferVerdict, ACorruptedRecordWordIsSeenOnBothSides) {
    frame_stream s = make_stream(79, 0);
    s.record[5 * 64 + 17] ^= uint64_t(1) << 40;
    auto* bench = new frame_pair_bench("tb", s.writes, s.record);
    auto& b = run(bench, period * double(s.writes.size() + 100) + settle * 3000.0);
    EXPECT_EQ(b.mismatches_o, 1u);
    EXPECT_EQ(b.mismatches_b, 1u);
}

// The head at 512's cell plan replayed into both stores and their RTL twins on the same pins: every
// word back on both sides, no overflow flag on either.
TEST(RtlCellStores, HeadAt512ReplayEveryWordBack) {
    const pipeline::frame_setup f("head", SHADING_SOURCE_DIR, 512, "sqmul", true);
    const pipeline::race_config c = pipeline::frozen_race_config();
    const pipeline::cell_plan p = pipeline::make_cell_plan(f.r, f.k, f.dev, c.cell_lines, c.cells);
    auto* b = new tb::cell_store_replay(
        "tb", tb::make_store_schedule(f.r, p, scene::span_stepper(f.r).words_per_triangle(), c.cells.s_max), 512);
    auto& rtl_walker = *new Vrtl_walker_store("rtl_walker");  // kept: SystemC cannot tear a design down
    auto& rtl_band = *new Vrtl_band_buffer("rtl_band");
    rtl_walker.clk(b->clk); rtl_walker.we(b->wp.we); rtl_walker.wa_hi(b->wp.wa_hi); rtl_walker.wa_lo(b->wp.wa_lo);
    rtl_walker.ra_hi(b->wp.ra_hi); rtl_walker.ra_lo(b->wp.ra_lo); rtl_walker.wd(b->wp.wd); rtl_walker.rd(b->wp.rd_o);
    rtl_walker.overflow(b->wp.overflow_o);
    rtl_band.clk(b->clk); rtl_band.we(b->bp.we); rtl_band.wa_hi(b->bp.wa_hi); rtl_band.wa_lo(b->bp.wa_lo);
    rtl_band.ra_hi(b->bp.ra_hi); rtl_band.ra_lo(b->bp.ra_lo); rtl_band.wd(b->bp.wd); rtl_band.rd(b->bp.rd_o);
    rtl_band.overflow(b->bp.overflow_o);
    b->second = true;
    const std::size_t ops = b->schedule().walker.size() + b->schedule().band.size();
    EXPECT_TRUE(tb::run_to_completion(*b, period * 2.0 * double(ops + 100)));
    EXPECT_GT(b->walker_counts.reads, 10000u);
    EXPECT_EQ(b->band_counts.reads, 9 * p.cells.size());
    EXPECT_EQ(b->walker_counts.mismatches + b->walker_counts.mismatches_o, 0u);
    EXPECT_EQ(b->band_counts.mismatches + b->band_counts.mismatches_o, 0u);
    for (const auto* of : {&b->wp.overflow, &b->wp.overflow_o, &b->bp.overflow, &b->bp.overflow_o}) EXPECT_FALSE(of->read());
}

}  // namespace test_rtl_memories
