// A replay of the geometry side's writes into the cells' stores (modules/pipeline/cell_stores.h) from
// the golden cell planner's plan (src/golden_pipeline/cells.h), in three parts:
//  - stimulus (store_schedule): from the plan's points in the order the scheme reads them, each
//    triangle takes the lowest free walker slot at its first point and writes its stepped words
//    there; after its last point they are read back and the slot freed. Band by band, every cell's
//    nine lattice samples are written at (line - band top, x), then every cell's lattice read back.
//    The words written are tags of what they stand for (triangle and word; x and y), not the
//    geometry side's values, which are not modelled;
//  - the bench drives the stores' pins, one write a clock, a read between edges;
//  - checker: every word read back is the tag the schedule wrote there (the schedule's own record,
//    independent of the stores), on the model and on any second store bound to the same pins
//    (rd_o: an RTL twin).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <systemc>
#include <vector>

#include "golden_pipeline/cells.h"
#include "pipeline/cell_stores.h"
#include "scene/raster.h"

namespace shading::tb {

// One access: a write of `value` at {hi, lo}, or a read there that must give `value`.
struct store_op {
    bool write;
    uint32_t hi, lo;
    uint64_t value;
};

struct store_schedule {
    std::vector<store_op> walker, band;
    uint32_t slots_used = 0;  // the highest slot taken, plus one
    uint32_t lines_used = 0;  // the highest line offset written, plus one
};

inline uint32_t walker_tag(std::size_t tri, unsigned k) { return uint32_t(tri * 2654435761u + k * 40503u + 1); }
inline uint64_t band_tag(unsigned x, unsigned y) { return ((uint64_t(y) << 24 | x) * 0x9E3779B1ull + 1) & 0xFFFFFFFFFFFFull; }

// words: a triangle's stepped words (scene::span_stepper::words_per_triangle).
inline store_schedule make_store_schedule(const scene::rasterised& r, const pipeline::cell_plan& p, unsigned words,
                                          unsigned s_max) {
    store_schedule s;
    const auto& pts = p.points;
    std::vector<std::size_t> last(r.setups.size(), 0);
    for (std::size_t i = 0; i < pts.size(); ++i) last[std::size_t(r.tri[r.index(pts[i][0], pts[i][1])])] = i;
    std::vector<int64_t> slot_of(r.setups.size(), -1);
    std::set<uint32_t> freed;
    uint32_t fresh = 0;  // slots never taken: fresh, fresh + 1, ...
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const std::size_t t = std::size_t(r.tri[r.index(pts[i][0], pts[i][1])]);
        if (slot_of[t] < 0) {  // its first point: the lowest free slot
            uint32_t slot = fresh;
            if (!freed.empty() && *freed.begin() < fresh) slot = *freed.begin(), freed.erase(freed.begin());
            else ++fresh;
            slot_of[t] = slot;
            s.slots_used = std::max(s.slots_used, slot + 1);
            for (unsigned k = 0; k < words; ++k) s.walker.push_back({true, slot, k, walker_tag(t, k)});
        }
        if (last[t] == i) {  // its last point: its words back, the slot freed
            const uint32_t slot = uint32_t(slot_of[t]);
            for (unsigned k = 0; k < words; ++k) s.walker.push_back({false, slot, k, walker_tag(t, k)});
            freed.insert(slot);
        }
    }
    // The cells band by band (stable: the plan's order within a band).
    std::vector<const pipeline::cell_job*> cells;
    for (const auto& c : p.cells) cells.push_back(&c);
    std::stable_sort(cells.begin(), cells.end(), [s_max](auto* a, auto* b) { return a->y0 / s_max < b->y0 / s_max; });
    for (std::size_t i = 0; i < cells.size();) {
        const unsigned top = cells[i]->y0 / s_max * s_max;
        std::size_t j = i;
        while (j < cells.size() && cells[j]->y0 / s_max * s_max == top) ++j;
        for (bool write : {true, false})
            for (std::size_t c = i; c < j; ++c)
                for (unsigned a = 0; a < 9; ++a) {
                    const unsigned x = cells[c]->x0 + a % 3 * cells[c]->s / 2, y = cells[c]->y0 + a / 3 * cells[c]->s / 2;
                    s.band.push_back({write, y - top, x, band_tag(x, y)});
                    s.lines_used = std::max(s.lines_used, y - top + 1);
                }
        i = j;
    }
    return s;
}

// One store's pins: the bench drives them; rd is the model's, rd_o a second store's (if bound).
template <class Store>
struct store_pins {
    using hi_t = typename Store::hi_t;
    using lo_t = typename Store::lo_t;
    using word = typename Store::store::word;
    sc_core::sc_signal<bool> we, overflow, overflow_o;
    sc_core::sc_signal<hi_t> wa_hi, ra_hi;
    sc_core::sc_signal<lo_t> wa_lo, ra_lo;
    sc_core::sc_signal<word> wd, rd, rd_o;
    void bind(Store& m, sc_core::sc_clock& clk) {
        m.clk(clk); m.we(we); m.wa_hi(wa_hi); m.wa_lo(wa_lo); m.ra_hi(ra_hi); m.ra_lo(ra_lo);
        m.wd(wd); m.rd(rd); m.overflow(overflow);
    }
};

// The counts the checker keeps per store.
struct replay_counts {
    std::size_t writes = 0, reads = 0, mismatches = 0, mismatches_o = 0;
};

class cell_store_replay : public sc_core::sc_module {
public:
    sc_core::sc_clock clk{"clk", sc_core::sc_time(10, sc_core::SC_NS)};
    store_pins<walker_store> wp;
    store_pins<band_buffer> bp;
    walker_store walker;
    band_buffer band;
    replay_counts walker_counts, band_counts;
    bool second = false;  // a second store on the pins: check its rd_o too

    SC_HAS_PROCESS(cell_store_replay);
    cell_store_replay(const sc_core::sc_module_name& name, store_schedule s, unsigned width,
                      unsigned slots = pipeline::walker_slots, unsigned lines = pipeline::band_lines)
        : sc_module(name), walker("walker", slots), band("band", width, lines), s_(std::move(s)) {
        wp.bind(walker, clk);
        bp.bind(band, clk);
        SC_THREAD(run);
    }
    bool finished() const { return done_; }
    const store_schedule& schedule() const { return s_; }

private:
    template <class Pins>
    void drive(Pins& pins, const std::vector<store_op>& ops, replay_counts& n) {
        const sc_core::sc_time settle(1, sc_core::SC_NS);
        for (const store_op& op : ops) {
            if (op.write) {
                pins.we.write(true); pins.wa_hi.write(op.hi); pins.wa_lo.write(op.lo); pins.wd.write(op.value);
                wait(clk.posedge_event());
                wait(settle);
                pins.we.write(false);
                ++n.writes;
                continue;
            }
            pins.ra_hi.write(op.hi); pins.ra_lo.write(op.lo);
            wait(settle);
            ++n.reads;
            n.mismatches += pins.rd.read().to_uint64() != op.value;
            if (second) n.mismatches_o += pins.rd_o.read().to_uint64() != op.value;
        }
    }
    void run() {
        wait(clk.posedge_event());
        wait(sc_core::sc_time(1, sc_core::SC_NS));
        drive(wp, s_.walker, walker_counts);
        drive(bp, s_.band, band_counts);
        done_ = true;
    }

    store_schedule s_;
    bool done_ = false;
};

}  // namespace shading::tb
