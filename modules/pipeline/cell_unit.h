// The cell unit (ours; a departure from the interpolation paper's raster lines, see
// src/golden_pipeline/cells.h): the biquadratic through a 3 x 3 lattice of colour samples over a
// cell of s x s pixels, s = 2^m (4 .. 64), streamed row by row as R, G, B pixels, bit-exact against
// cell_pixels with forward differences. A device top: it only instantiates and wires.
//   ctl          the controller (cell_ctrl.h): handshake, lattice strobe, column and row phases,
//                buffer addresses, pixel coordinates
//   ch_r/g/b     per channel: lattice registers, three column coefficient units and forward-
//                difference channels, three column buffers, the row's coefficient unit and
//                forward-difference channel (cell_channel.h)
// Pins from the geometry side (the cell's lattice, formed by the sample stage): start, ready, in_x0,
// in_y0, in_m and in_lat_r/g/b_0..8 (colour_fmt codes, lattice[3 i + j] at (x0 + j s/2, y0 + i s/2)).
// The pixel stream is the shading pipeline's: at a rising edge of clk where px_valid = 1, px_r/g/b
// belong at (px_x, px_y); a frame_buffer samples it there.
#pragma once

#include <systemc>

#include "interp/interp_delays.h"
#include "monitors/phase_checker.h"
#include "pipeline/cell_channel.h"
#include "pipeline/cell_ctrl.h"

namespace shading {

class cell_unit : public sc_core::sc_module {
public:
    using coord_t = cell_ctrl::coord_t;
    using m_t = cell_ctrl::m_t;
    using sample_t = pipeline::sample_t;
    using lattice_pins = sc_core::sc_vector<sc_core::sc_in<sample_t>>;

    sc_core::sc_in<bool> clk{"clk"}, start{"start"};
    sc_core::sc_out<bool> ready{"ready"};
    sc_core::sc_in<coord_t> in_x0{"in_x0"}, in_y0{"in_y0"};
    sc_core::sc_in<m_t> in_m{"in_m"};
    lattice_pins in_lat_r{"in_lat_r", 9}, in_lat_g{"in_lat_g", 9}, in_lat_b{"in_lat_b", 9};
    sc_core::sc_out<bool> px_valid{"px_valid"};
    sc_core::sc_out<coord_t> px_x{"px_x"}, px_y{"px_y"};
    sc_core::sc_out<sample_t> px_r{"px_r"}, px_g{"px_g"}, px_b{"px_b"};

    // Nets.
    sc_core::sc_signal<bool> ld_lat{"ld_lat"}, col_start{"col_start"}, row_start{"row_start"};
    sc_core::sc_signal<bool> col_valid{"col_valid"}, col_last{"col_last"}, row_last{"row_last"};
    sc_core::sc_signal<cell_channel::len_t> len{"len"};
    sc_core::sc_signal<m_t> m{"m"};
    sc_core::sc_signal<cell_channel::addr_t> wa{"wa"}, ra{"ra"};
    // Channels G and B report their streams on nets of their own (the three run in step).
    sc_core::sc_signal<bool> col_valid_g{"col_valid_g"}, col_last_g{"col_last_g"}, valid_g{"valid_g"},
        last_g{"last_g"}, col_valid_b{"col_valid_b"}, col_last_b{"col_last_b"}, valid_b{"valid_b"}, last_b{"last_b"};

    cell_ctrl ctl{"ctl"};
    cell_channel ch_r, ch_g, ch_b;
    // Assertion monitor (not hardware): the clock's phases along every path of the unit, also those
    // between its channels' units (each unit's own chk_clock sees only its own).
    phase_checker chk_clock{"chk_clock"};

    explicit cell_unit(const sc_core::sc_module_name& name, const interp_delays& dl = {})
        : sc_module(name), ch_r("ch_r", dl), ch_g("ch_g", dl), ch_b("ch_b", dl) {
        ctl.clk(clk); ctl.start(start); ctl.in_x0(in_x0); ctl.in_y0(in_y0); ctl.in_m(in_m);
        ctl.col_valid(col_valid); ctl.col_last(col_last); ctl.row_valid(px_valid); ctl.row_last(row_last);
        ctl.ready(ready); ctl.ld_lat(ld_lat); ctl.col_start(col_start); ctl.row_start(row_start);
        ctl.len(len); ctl.m(m); ctl.wa(wa); ctl.ra(ra); ctl.px_x(px_x); ctl.px_y(px_y);
        wire(ch_r, in_lat_r, px_r, col_valid, col_last, px_valid, row_last);
        wire(ch_g, in_lat_g, px_g, col_valid_g, col_last_g, valid_g, last_g);
        wire(ch_b, in_lat_b, px_b, col_valid_b, col_last_b, valid_b, last_b);
        chk_clock.clk(clk);
    }

    void end_of_elaboration() override { chk_clock.derive(timing_graph(*this)); }
    // Shortest clock phases the whole unit works with (after elaboration).
    const sc_core::sc_time& min_high() const { return chk_clock.min_high(); }
    const sc_core::sc_time& min_low() const { return chk_clock.min_low(); }

private:
    template <class VALID, class LAST>
    void wire(cell_channel& ch, lattice_pins& lat, sc_core::sc_out<sample_t>& px, sc_core::sc_signal<bool>& cv,
              sc_core::sc_signal<bool>& cl, VALID& v, LAST& l) {
        ch.clk(clk); ch.ld_lat(ld_lat);
        for (std::size_t i = 0; i < 9; ++i) ch.in_lat[i](lat[i]);
        ch.col_start(col_start); ch.row_start(row_start); ch.len(len); ch.m(m); ch.wa(wa); ch.ra(ra);
        ch.px(px); ch.col_valid(cv); ch.col_last(cl); ch.valid(v); ch.last(l);
    }
};

}  // namespace shading
