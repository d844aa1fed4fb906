// One colour channel's evaluator with forward differences (ours, the alternative to the Horner
// unit behind the same pins): fd_eval<M> for the interval length 2^M fixed at construction, or
// (M = 0 at construction) fd_eval_var<m_min, m_max>, whose length 2^m comes with each interval. A
// quadratic a t^2 + b t + c is evaluated as the cubic A = 0, B = a, C = b, D = c: the degree-select
// pin switches mx_a..mx_d between the cubic unit's A..D and (0, a, b, c). out_clamp as in
// horner_channel.h. Only instantiates and wires.
#pragma once

#include <memory>
#include <type_traits>
#include <systemc>

#include "blocks/clamp.h"
#include "blocks/constant.h"
#include "blocks/mux.h"
#include "blocks/shifter.h"
#include "formats/interp_formats.h"
#include "interp/fd_eval.h"
#include "interp/fd_eval_var.h"
#include "interp/interp_delays.h"
#include "pipeline/sample_channel.h"

namespace shading {

class fd_channel : public sc_core::sc_module {
public:
    using sel_t = sc_dt::sc_uint<1>;
    // The pixel controller's len bus is wide enough for every M; fd_eval<M> takes its M + 1 low wires.
    static constexpr unsigned len_width = interp::len_width(interp::m_max);
    using len_t = sc_dt::sc_uint<len_width>;
    using m_t = sc_dt::sc_uint<interp::code_width(interp::m_max + 1)>;  // 0 (exact pixel), m_min..m_max

    sc_core::sc_in<bool> clk{"clk"}, start{"start"};
    sc_core::sc_in<sel_t> deg_sel{"deg_sel"};
    sc_core::sc_in<len_t> len{"len"};
    sc_core::sc_in<m_t> m{"m"};  // read by fd_eval_var only (fd_eval<M> is built for its M)
    sc_core::sc_in<pipeline::coef_t> ca{"ca"}, cb{"cb"}, cc{"cc"}, cd{"cd"}, qa{"qa"}, qb{"qb"}, qc{"qc"};
    sc_core::sc_out<pipeline::sample_t> px{"px"};
    sc_core::sc_out<bool> valid{"valid"}, last{"last"};

    sc_core::sc_signal<pipeline::coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"}, i_px{"i_px"}, zero_word{"zero_word"};

    constant<pipeline::coef_t> k_zero{"k_zero", pipeline::coef_t(0)};
    mux<interp::coef_fmt.width, 2> mx_a, mx_b, mx_c, mx_d;
    std::unique_ptr<sc_core::sc_module> fd;        // fd_eval<M> or fd_eval_var<m_min, m_max>
    std::unique_ptr<sc_core::sc_module> len_wires;  // the M + 1 low wires of len (shifter, wiring)
    std::unique_ptr<sc_core::sc_interface> fd_len;   // the signal between them
    clamp<interp::coef_fmt.width, interp::sample_fmt.width, interp::coef_fmt.frac - interp::sample_fmt.frac> out_clamp;

    // fixed_m: 2..6 builds fd_eval<fixed_m>; 0 builds fd_eval_var (any m per interval).
    fd_channel(const sc_core::sc_module_name& name, unsigned fixed_m, const interp_delays& dl = {})
        : sc_module(name), mx_a("mx_a", dl.mux), mx_b("mx_b", dl.mux), mx_c("mx_c", dl.mux), mx_d("mx_d", dl.mux),
          out_clamp("out_clamp", dl.adder) {
        k_zero.y(zero_word);
        mx_a.in[0](ca); mx_a.in[1](zero_word); mx_a.sel(deg_sel); mx_a.y(a);
        mx_b.in[0](cb); mx_b.in[1](qa); mx_b.sel(deg_sel); mx_b.y(b);
        mx_c.in[0](cc); mx_c.in[1](qb); mx_c.sel(deg_sel); mx_c.y(c);
        mx_d.in[0](cd); mx_d.in[1](qc); mx_d.sel(deg_sel); mx_d.y(d);
        switch (fixed_m) {
            case 0: make_fd_var(dl); break;
            case 2: make_fd<2>(dl); break;
            case 3: make_fd<3>(dl); break;
            case 4: make_fd<4>(dl); break;
            case 5: make_fd<5>(dl); break;
            default: make_fd<6>(dl); break;  // the caller checks m (shading_pipeline)
        }
        out_clamp.x(i_px); out_clamp.y(px);
    }

private:
    void make_fd_var(const interp_delays& dl) {
        using var_t = fd_eval_var<interp::m_min, interp::m_max>;
        static_assert(std::is_same_v<var_t::len_t, len_t> && std::is_same_v<var_t::m_t, m_t>, "pins");
        auto u = std::make_unique<var_t>("fd", dl);
        u->clk(clk); u->start(start); u->len(len); u->m(m);
        u->a(a); u->b(b); u->c(c); u->d(d);
        u->i_px(i_px); u->valid(valid); u->last(last);
        fd = std::move(u);
    }

    template <unsigned M>
    void make_fd(const interp_delays& dl) {
        using flen_t = typename fd_eval<M>::len_t;
        auto sig = std::make_unique<sc_core::sc_signal<flen_t>>("fd_len");
        auto wires = std::make_unique<shifter<len_width, interp::len_width(M)>>("len_wires", 0);
        auto u = std::make_unique<fd_eval<M>>("fd", dl);
        wires->x(len); wires->y(*sig);
        u->clk(clk); u->start(start); u->len(*sig);
        u->a(a); u->b(b); u->c(c); u->d(d);
        u->i_px(i_px); u->valid(valid); u->last(last);
        fd_len = std::move(sig);
        len_wires = std::move(wires);
        fd = std::move(u);
    }
};

}  // namespace shading
