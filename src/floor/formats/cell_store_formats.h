// Capacities of the state the geometry side keeps for the cells (ours): one table, read by the
// SystemC stores (modules/pipeline/cell_stores.h) and, through the generated shading_formats.vh, by
// their RTL twins (rtl/pipeline/walker_store.v, band_buffer.v).
#pragma once

#include "formats/pipeline_formats.h"

namespace shading::pipeline {

// Sized from the worst case the cell planner produces
// with the race's frozen configuration on our scenes (the head, the sphere, make_test_obj's blob and
// cluster of 64 segments, at 512 and 1024: testbenches/pipeline/test_cell_stores.cpp).
// The walker's live triangles: at most 1492 at once (the cluster at 1024; the head at 1024: 1098),
// each in a slot of its own, the lowest free one, taken at its first point and freed after its last:
// 2^11 slots. A slot holds a triangle's stepped words (scene::span_stepper: 4 x (3 + 3 + 1) = 28 at
// most, of scene::state_word_bits), the word of (slot, k) at {slot, k}: 2^5 words a slot, 4 unused.
inline constexpr unsigned walker_slot_bits = 11;
inline constexpr unsigned walker_slots = 1u << walker_slot_bits;
inline constexpr unsigned walker_word_bits = 5;
inline constexpr unsigned walker_word_width = 32;
// The band buffer: a band's s_max + 1 = 33 lines of colour samples (cell_config's s_max = 32, the
// tiles' side, and the line below its last cells), one colour_fmt code per channel; the sample at
// line offset l (from the band's top) and x at {l, x}, x on frame_pitch(width) wires.
inline constexpr unsigned band_lines = 33;
inline constexpr unsigned band_line_bits = 6;  // 33 lines and an offset beyond them, to be flagged
inline constexpr unsigned band_word_width = 3 * colour_fmt.width;

}  // namespace shading::pipeline
