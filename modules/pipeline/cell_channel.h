// One colour channel of the cell unit (ours, cell_unit.h): the biquadratic through a 3 x 3 lattice of
// colour samples, from the pipeline's own blocks, bit-exact against src/golden_pipeline/cells.h's
// cell_pixels (forward differences):
//   rg_lat_0..8     the lattice registers (strobe ld_lat), lattice[3 i + j] at (j s/2, i s/2)
//   cq_col0..2      quadratic coefficient units down lattice columns 0, 1, 2 (lattice j, 3 + j, 6 + j)
//   fd_col0..2      forward-difference channels (quadratic, any m): the column's value at every row
//   buf_col0..2     column buffers of 64 words, written while the column channels stream (we, wa);
//                   their overflow flags on nets of their own (6 address wires name only words)
//   cq_row, fd_row  the quadratic through the three column values of row ra, along the row: px
// The cubic inputs of the forward-difference channels are tied to zero and their degree select to
// the quadratic (k_zero, k_quad). Only instantiates and wires.
#pragma once

#include <systemc>

#include "blocks/constant.h"
#include "blocks/ram.h"
#include "blocks/reg.h"
#include "interp/coef_unit_quad.h"
#include "interp/interp_delays.h"
#include "pipeline/fd_channel.h"
#include "pipeline/sample_channel.h"

namespace shading {

class cell_channel : public sc_core::sc_module {
public:
    static constexpr unsigned WI = interp::sample_fmt.width;
    static constexpr unsigned depth = 1u << interp::m_max;  // rows of the largest cell
    using buffer = ram<WI, interp::code_width(depth)>;
    using addr_t = buffer::addr_t;
    using len_t = fd_channel::len_t;
    using m_t = fd_channel::m_t;
    using sample_t = pipeline::sample_t;

    sc_core::sc_in<bool> clk{"clk"}, ld_lat{"ld_lat"};
    sc_core::sc_vector<sc_core::sc_in<sample_t>> in_lat{"in_lat", 9};
    sc_core::sc_in<bool> col_start{"col_start"}, row_start{"row_start"};
    sc_core::sc_in<len_t> len{"len"};
    sc_core::sc_in<m_t> m{"m"};
    sc_core::sc_in<addr_t> wa{"wa"}, ra{"ra"};
    sc_core::sc_out<sample_t> px{"px"};
    sc_core::sc_out<bool> col_valid{"col_valid"}, col_last{"col_last"}, valid{"valid"}, last{"last"};

    // Nets.
    sc_core::sc_vector<sc_core::sc_signal<sample_t>> lat{"lat", 9};
    sc_core::sc_vector<sc_core::sc_signal<pipeline::coef_t>> col_a{"col_a", 3}, col_b{"col_b", 3}, col_c{"col_c", 3};
    sc_core::sc_vector<sc_core::sc_signal<sample_t>> col_px{"col_px", 3}, col_rd{"col_rd", 3};
    sc_core::sc_vector<sc_core::sc_signal<bool>> col_valid_n{"col_valid_n", 2}, col_last_n{"col_last_n", 2};
    sc_core::sc_vector<sc_core::sc_signal<bool>> buf_overflow{"buf_overflow", 3};
    sc_core::sc_signal<pipeline::coef_t> row_a{"row_a"}, row_b{"row_b"}, row_c{"row_c"}, zero_word{"zero_word"};
    sc_core::sc_signal<fd_channel::sel_t> quad_sel{"quad_sel"};

    sc_core::sc_vector<reg<WI>> rg_lat;
    constant<pipeline::coef_t> k_zero{"k_zero", pipeline::coef_t(0)};
    constant<fd_channel::sel_t> k_quad{"k_quad", fd_channel::sel_t(1)};  // fd_channel: 1 selects the quadratic
    sc_core::sc_vector<coef_unit_quad> cq_col;
    sc_core::sc_vector<fd_channel> fd_col;
    sc_core::sc_vector<buffer> buf_col;
    coef_unit_quad cq_row;
    fd_channel fd_row;

    explicit cell_channel(const sc_core::sc_module_name& name, const interp_delays& dl = {})
        : sc_module(name),
          rg_lat("rg_lat", 9, [&](const char* n, std::size_t) { return new reg<WI>(n, dl.reg); }),
          cq_col("cq_col", 3, [&](const char* n, std::size_t) { return new coef_unit_quad(n, dl); }),
          fd_col("fd_col", 3, [&](const char* n, std::size_t) { return new fd_channel(n, 0, dl); }),
          buf_col("buf_col", 3, [](const char* n, std::size_t) { return new buffer(n, depth); }),
          cq_row("cq_row", dl), fd_row("fd_row", 0, dl) {
        k_zero.y(zero_word);
        k_quad.y(quad_sel);
        for (std::size_t i = 0; i < 9; ++i) {
            rg_lat[i].ctl(ld_lat); rg_lat[i].d(in_lat[i]); rg_lat[i].q(lat[i]);
        }
        for (std::size_t j = 0; j < 3; ++j) {
            coef_unit_quad& q = cq_col[j];
            q.clk(clk); q.i1(lat[j]); q.i2(lat[3 + j]); q.i3(lat[6 + j]);
            q.a(col_a[j]); q.b(col_b[j]); q.c(col_c[j]);
            wire_fd(fd_col[j], col_start, col_a[j], col_b[j], col_c[j], col_px[j]);
            buffer& b = buf_col[j];
            b.clk(clk); b.we(col_valid); b.wa(wa); b.wd(col_px[j]); b.ra(ra); b.rd(col_rd[j]);
            b.overflow(buf_overflow[j]);
        }
        // Channel's column 0 reports its stream (the three run in step); 1 and 2 drive nets of their own.
        fd_col[0].valid(col_valid); fd_col[0].last(col_last);
        for (std::size_t j = 1; j < 3; ++j) {
            fd_col[j].valid(col_valid_n[j - 1]); fd_col[j].last(col_last_n[j - 1]);
        }
        cq_row.clk(clk); cq_row.i1(col_rd[0]); cq_row.i2(col_rd[1]); cq_row.i3(col_rd[2]);
        cq_row.a(row_a); cq_row.b(row_b); cq_row.c(row_c);
        wire_fd(fd_row, row_start, row_a, row_b, row_c, px);
        fd_row.valid(valid); fd_row.last(last);
    }

private:
    template <class A, class P>
    void wire_fd(fd_channel& f, sc_core::sc_in<bool>& start, A& a, A& b, A& c, P& out) {
        f.clk(clk); f.start(start); f.deg_sel(quad_sel); f.len(len); f.m(m);
        f.ca(zero_word); f.cb(zero_word); f.cc(zero_word); f.cd(zero_word);
        f.qa(a); f.qb(b); f.qc(c);
        f.px(out);
    }
};

}  // namespace shading
