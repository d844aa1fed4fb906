// Controller of the cell unit (ours, cell_unit.h): a clocked FSM on the rising edge of clk.
//   idle     ready = 1; where start = 1 it takes the cell's x0, y0 and m (s = 2^m pixels a side),
//            raises ld_lat and drops ready (the geometry side then holds the lattice pins until
//            ready rises again, and lowers start);
//   latch    ld_lat falls: the lattice registers latch; col_start = 1;
//   columns  the column channels take the cell where col_start = 1 and they are idle (fd_ctrl's rule,
//            as fd_pixel_ctrl reads it) and stream the column values of rows 0 .. s - 1; the column
//            buffers write each where the edge sees col_valid, at wa, counted up from 0 here;
//   rows     with the last column value written, ra = 0 and row_start = 1; the row channel takes
//            row y at an edge where it is idle or on its last pixel, and one clock later ra moves to
//            row y + 1 (the coefficient unit latches it at the falling edge after, when the row
//            channel has loaded row y's coefficients); px_x / px_y are set at the taking edge and
//            stepped, one clock ahead of each pixel, as fd_pixel_ctrl does;
//   back to idle at the edge that sees the last row's last pixel.
// A cell takes s^2 + s + 3 clocks from the taking edge to the edge that stores its last pixel. Bad
// input (shading/input, a defined result): m outside interp::m_min .. interp::m_max is taken as the
// nearest of them.
#pragma once

#include <sstream>
#include <systemc>

#include "core/report_ids.h"
#include "core/timed_block.h"
#include "formats/interp_formats.h"
#include "pipeline/cell_channel.h"

namespace shading {

class cell_ctrl : public sc_core::sc_module, public timed_block {
public:
    using coord_t = sc_dt::sc_uint<16>;
    using addr_t = cell_channel::addr_t;
    using len_t = cell_channel::len_t;
    using m_t = cell_channel::m_t;

    sc_core::sc_in<bool> clk{"clk"}, start{"start"};
    sc_core::sc_in<coord_t> in_x0{"in_x0"}, in_y0{"in_y0"};
    sc_core::sc_in<m_t> in_m{"in_m"};
    sc_core::sc_in<bool> col_valid{"col_valid"}, col_last{"col_last"};  // channel R's (the three run in step)
    sc_core::sc_in<bool> row_valid{"row_valid"}, row_last{"row_last"};
    sc_core::sc_out<bool> ready{"ready"}, ld_lat{"ld_lat"}, col_start{"col_start"}, row_start{"row_start"};
    sc_core::sc_out<len_t> len{"len"};
    sc_core::sc_out<m_t> m{"m"};
    sc_core::sc_out<addr_t> wa{"wa"}, ra{"ra"};
    sc_core::sc_out<coord_t> px_x{"px_x"}, px_y{"px_y"};

    SC_HAS_PROCESS(cell_ctrl);
    explicit cell_ctrl(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_clock);
        sensitive << clk.pos();
        dont_initialize();
        ready.initialize(true);  // ready from the start, before the first edge
    }

    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }
    const sc_core::sc_port_base* clock_port() const override { return &clk; }
    bool switches_on_rising_edge() const override { return true; }

    std::size_t cells() const { return cells_; }
    bool idle() const { return phase_ == phase::idle; }

private:
    enum class phase { idle, latch, columns, rows };

    void on_clock() {
        switch (phase_) {
            case phase::idle:
                if (start.read()) take();
                break;
            case phase::latch:
                ld_lat.write(false);  // the lattice registers latch at this edge
                col_start.write(true);
                col_start_ = true;
                phase_ = phase::columns;
                break;
            case phase::columns: columns(); break;
            case phase::rows: rows(); break;
        }
    }

    void take() {
        unsigned mm = in_m.read().to_uint();
        if (mm < interp::m_min || mm > interp::m_max) {
            const unsigned to = mm < interp::m_min ? interp::m_min : interp::m_max;
            std::ostringstream msg;
            msg << name() << ": a cell of 2^" << mm << " pixels at (" << in_x0.read().to_uint() << ", "
                << in_y0.read().to_uint() << "); sizes are 2^" << interp::m_min << " .. 2^" << interp::m_max
                << ": taken as 2^" << to;
            SC_REPORT_WARNING(msg::input, msg.str().c_str());
            mm = to;
        }
        x0_ = in_x0.read().to_uint();
        y0_ = in_y0.read().to_uint();
        s_ = 1u << mm;
        m.write(m_t(mm));
        len.write(len_t(s_));
        ld_lat.write(true);
        ready.write(false);
        phase_ = phase::latch;
        ++cells_;
    }

    void columns() {
        const bool v = col_valid.read(), l = col_last.read();
        if (col_start_ && !v) {  // the column channels take the cell at this edge
            col_start.write(false);
            col_start_ = false;
            wa_ = 0;
            wa.write(addr_t(0));
            return;
        }
        if (!v) return;
        if (!l) {  // this edge writes row wa_'s column values
            wa.write(addr_t(++wa_));
            return;
        }
        // The last column value is written at this edge: the rows start.
        row_ = 0;
        ra.write(addr_t(0));
        row_start.write(true);
        row_start_ = true;
        phase_ = phase::rows;
    }

    void rows() {
        const bool v = row_valid.read(), l = row_last.read();
        if (move_ra_) {  // one clock after a row was taken: the next row's column values
            ra.write(addr_t(row_));
            move_ra_ = false;
        }
        if (row_start_ && (!v || l)) {  // the row channel takes row row_ at this edge
            px_x.write(coord_t(x0_));
            px_y.write(coord_t(y0_ + row_));
            next_x_ = 1;
            left_ = s_ - 1;
            if (++row_ < s_) {
                move_ra_ = true;
            } else {
                row_start.write(false);
                row_start_ = false;
            }
            return;
        }
        if (left_ > 0) {  // px_x one clock ahead of the pixel
            px_x.write(coord_t(x0_ + next_x_++));
            --left_;
            return;
        }
        if (!row_start_ && v && l) {  // this edge stores the cell's last pixel
            ready.write(true);
            phase_ = phase::idle;
        }
    }

    phase phase_ = phase::idle;
    bool col_start_ = false, row_start_ = false, move_ra_ = false;
    unsigned x0_ = 0, y0_ = 0, s_ = 4, wa_ = 0, row_ = 0, next_x_ = 0, left_ = 0;
    std::size_t cells_ = 0;
};

}  // namespace shading
