// The state the geometry side keeps for the cells (ours; src/golden_pipeline/cells.h's scheme), as
// the block library's RAM with the capacities of formats/cell_store_formats.h. What is modelled: the
// size, the addressing and the overflow check (a write beyond the capacity dropped, `overflow` set
// and reported by the RAM); not the geometry side's datapath that fills and reads them.
//   walker_store  the edge walker's live triangles: a slot per triangle, its stepped words at
//                 {slot, k} (walker_word_bits wires of k); a slot beyond the capacity is an address
//                 beyond the RAM's words
//   band_buffer   a band's lines of colour samples {r, g, b}: the sample at line offset l (from the
//                 band's top) and x at {l, x}, x on the frame pitch's wires; l beyond the lines is
//                 an address beyond the RAM's words
// Each takes its capacity at construction (default: the format header's; a test gives a smaller one)
// and wires its two address fields into the RAM's write and read addresses. rtl/pipeline/
// walker_store.v and band_buffer.v are the twins.
#pragma once

#include <cstdint>
#include <systemc>

#include "blocks/ram.h"
#include "formats/cell_store_formats.h"
#include "formats/interp_formats.h"

namespace shading {

// Two address fields {hi, lo} wired into one RAM: lo on lo_bits wires (fixed at construction), hi
// above it. A base of the two stores below; it computes nothing but the concatenation.
template <unsigned W, unsigned HI, unsigned LO_MAX>
class split_ram : public sc_core::sc_module {
public:
    using store = ram<W, HI + LO_MAX>;
    using hi_t = sc_dt::sc_uint<HI>;
    using lo_t = sc_dt::sc_uint<LO_MAX>;
    sc_core::sc_in<bool> clk{"clk"}, we{"we"};
    sc_core::sc_in<hi_t> wa_hi{"wa_hi"}, ra_hi{"ra_hi"};
    sc_core::sc_in<lo_t> wa_lo{"wa_lo"}, ra_lo{"ra_lo"};
    sc_core::sc_in<typename store::word> wd{"wd"};
    sc_core::sc_out<typename store::word> rd{"rd"};
    sc_core::sc_out<bool> overflow{"overflow"};

    sc_core::sc_signal<typename store::addr_t> mem_wa{"mem_wa"}, mem_ra{"mem_ra"};
    store ram_words;

    SC_HAS_PROCESS(split_ram);
    // hi_words values of hi, each of 2^lo_bits words.
    split_ram(const sc_core::sc_module_name& name, uint64_t hi_words, unsigned lo_bits)
        : sc_module(name), ram_words("ram_words", hi_words << lo_bits), lo_bits_(lo_bits) {
        ram_words.clk(clk); ram_words.we(we); ram_words.wa(mem_wa); ram_words.ra(mem_ra); ram_words.wd(wd);
        ram_words.rd(rd); ram_words.overflow(overflow);
        SC_METHOD(address);  // wiring: {hi, lo}
        sensitive << wa_hi << wa_lo << ra_hi << ra_lo;
    }
    uint64_t words() const { return ram_words.depth(); }
    uint64_t bits() const { return ram_words.depth() * W; }

private:
    void address() {
        const uint64_t lo_mask = (uint64_t(1) << lo_bits_) - 1;
        mem_wa.write((wa_hi.read().to_uint64() << lo_bits_) | (wa_lo.read().to_uint64() & lo_mask));
        mem_ra.write((ra_hi.read().to_uint64() << lo_bits_) | (ra_lo.read().to_uint64() & lo_mask));
    }
    unsigned lo_bits_;
};

// The walker's live triangles: `slots` slots (the format's 2^11 by default) of 2^walker_word_bits
// words; wa_hi / ra_hi the slot (16 wires, so that a slot beyond the capacity can be asked for and
// flagged), wa_lo / ra_lo the word in it.
class walker_store : public split_ram<pipeline::walker_word_width, 16, pipeline::walker_word_bits> {
public:
    explicit walker_store(const sc_core::sc_module_name& name, unsigned slots = pipeline::walker_slots)
        : split_ram(name, slots, pipeline::walker_word_bits) {}
};

// The band buffer of a frame `width` pixels wide: `lines` lines (the format's 33 by default) of
// frame_pitch(width) words; wa_hi / ra_hi the line offset, wa_lo / ra_lo the x.
class band_buffer : public split_ram<pipeline::band_word_width, pipeline::band_line_bits, 16> {
public:
    band_buffer(const sc_core::sc_module_name& name, unsigned width, unsigned lines = pipeline::band_lines)
        : split_ram(name, lines, x_bits(width)) {}
    static unsigned x_bits(unsigned width) {
        const unsigned p = pipeline::frame_pitch(width);
        return p == 1 ? 0 : interp::code_width(p);
    }
};

}  // namespace shading
