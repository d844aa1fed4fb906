// Forward-difference evaluator for intervals of any length 2^m, m in MMIN..MMAX, chosen per interval
// (ours, like fd_eval.h, whose registers, adders, pins and timing it keeps): the adaptive length
// policy's intervals without a multiplier. The recurrence is fd_eval's,
//   P <- P + D1,  D1 <- D1 + D2,  D2 <- D2 + D3,
// one pixel per clock. Only the set-up depends on m: per m one set of fd_eval<m>'s shift-and-add
// networks (fd_setup.h), and per difference a multiplexer on setup_sel = m - MMIN (fd_ctrl_var,
// which latches m with len at acceptance) feeding the register's load input.
// Pins: fd_eval's plus `m` (m_t: codes 0..MMAX; 0 is an exact pixel, len 1). The same formats:
// A..D Q16.16 in, Q22.34 inside (fd_fmt: every m's set-up exact), i_px Q16.16 (floor).
// This class only instantiates and wires.
#pragma once

#include <string>
#include <systemc>

#include "blocks/adder.h"
#include "blocks/constant.h"
#include "blocks/mux.h"
#include "blocks/reg.h"
#include "blocks/shift_add_network.h"
#include "blocks/shifter.h"
#include "core/timing_graph.h"
#include "formats/interp_formats.h"
#include "interp/fd_ctrl_var.h"
#include "interp/fd_eval.h"
#include "interp/fd_setup.h"
#include "interp/interp_delays.h"
#include "monitors/phase_checker.h"

namespace shading {

template <unsigned MMIN, unsigned MMAX>
class fd_eval_var : public sc_core::sc_module {
    static_assert(MMIN >= interp::m_min && MMAX <= interp::m_max && MMIN < MMAX,
                  "intervals of 2^m pixels, MMIN < MMAX in 2..6 (one length: fd_eval<M>)");
    static constexpr unsigned WC = interp::coef_fmt.width;  // 32
    static constexpr unsigned WF = interp::fd_fmt.width;    // 56
    static constexpr int S = fd_setup::align;               // 18: Q.16 -> Q.34
    using coef_t = sc_dt::sc_uint<WC>;
    using fd_t = sc_dt::sc_uint<WF>;
    using network = shift_add_network<WC, WF, true>;

public:
    using ctrl_t = fd_ctrl_var<MMIN, MMAX>;
    using len_t = typename ctrl_t::len_t;
    using m_t = typename ctrl_t::m_t;
    static constexpr unsigned lengths = ctrl_t::lengths;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> start{"start"};
    sc_core::sc_in<len_t> len{"len"};
    sc_core::sc_in<m_t> m{"m"};
    sc_core::sc_in<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"};
    sc_core::sc_out<coef_t> i_px{"i_px"};
    sc_core::sc_out<bool> valid{"valid"}, last{"last"};

    // Nets. init_dK_m<m>: the set-up of difference K for intervals of 2^m; init_dK: the one selected.
    sc_core::sc_vector<sc_core::sc_signal<fd_t>> init_d1_m{"init_d1_m"}, init_d2_m{"init_d2_m"}, init_d3_m{"init_d3_m"};
    sc_core::sc_signal<fd_t> init_p{"init_p"}, init_d1{"init_d1"}, init_d2{"init_d2"}, init_d3{"init_d3"};
    sc_core::sc_signal<fd_t> p_value{"p_value"}, d1_value{"d1_value"}, d2_value{"d2_value"}, d3_value{"d3_value"};
    sc_core::sc_signal<fd_t> p_next{"p_next"}, d1_next{"d1_next"}, d2_next{"d2_next"};
    sc_core::sc_signal<fd_t> p_sum{"p_sum"}, d1_sum{"d1_sum"}, d2_sum{"d2_sum"}, d3_keep{"d3_keep"};
    sc_core::sc_signal<typename ctrl_t::select> fd_sel{"fd_sel"};
    sc_core::sc_signal<typename ctrl_t::setup_select> setup_sel{"setup_sel"};
    sc_core::sc_signal<len_t> pixel{"pixel"};
    sc_core::sc_signal<bool> carry0{"carry0"};

    // Set-up: D is m-independent; D1..D3 per m (setup_dK_m<m>, fd_eval<m>'s networks) and a mux each.
    shifter<WC, WF, true> setup_p{"setup_p", S};  // D: Q16.16 -> Q22.34
    sc_core::sc_vector<network> setup_d1{"setup_d1"}, setup_d2{"setup_d2"}, setup_d3{"setup_d3"};
    mux<WF, lengths> mx_setup_d1, mx_setup_d2, mx_setup_d3;  // select by setup_sel = m - MMIN

    mux<WF, interp::fd_mx_inputs> mx_p, mx_d1, mx_d2, mx_d3;
    reg<WF> rg_p, rg_d1, rg_d2, rg_d3;
    adder<WF, WF, WF, true, true> add_p, add_d1, add_d2;  // Q22.34 + Q22.34 -> Q22.34
    shifter<WF, WC, true> out_align{"out_align", -S};  // Q22.34 -> Q16.16, 18 low wires dropped (floor)
    constant<bool> k_carry0{"k_carry0", false};
    ctrl_t ctrl{"ctrl"};
    // Assertion monitor (not hardware), as in fd_eval. High: from the accepting rising edge A..D ->
    // set-up network -> set-up mux -> MX (and fd_sel, setup_sel from the controller) must reach the
    // registers before the falling edge. Low: RG_P onto i_px before the rising edge. Derived from
    // the elaborated blocks at end_of_elaboration.
    phase_checker chk_clock{"chk_clock"};

    explicit fd_eval_var(const sc_core::sc_module_name& name, const interp_delays& t = {})
        : sc_module(name), mx_setup_d1("mx_setup_d1", t.mux), mx_setup_d2("mx_setup_d2", t.mux),
          mx_setup_d3("mx_setup_d3", t.mux), mx_p("mx_p", t.mux), mx_d1("mx_d1", t.mux), mx_d2("mx_d2", t.mux),
          mx_d3("mx_d3", t.mux), rg_p("rg_p", t.reg), rg_d1("rg_d1", t.reg), rg_d2("rg_d2", t.reg),
          rg_d3("rg_d3", t.reg), add_p("add_p", overflow_mode::wrap, 0, 0, t.adder),
          add_d1("add_d1", overflow_mode::wrap, 0, 0, t.adder), add_d2("add_d2", overflow_mode::wrap, 0, 0, t.adder) {
        init_d1_m.init(lengths, named_net("init_d1_m"));
        init_d2_m.init(lengths, named_net("init_d2_m"));
        init_d3_m.init(lengths, named_net("init_d3_m"));
        setup_d1.init(lengths, [](const char*, std::size_t i) {
            return new network(by_m("setup_d1_m", i).c_str(), 3, fd_setup::d1_terms(MMIN + i));  // A, B, C
        });
        setup_d2.init(lengths, [](const char*, std::size_t i) {
            return new network(by_m("setup_d2_m", i).c_str(), 2, fd_setup::d2_terms(MMIN + i));  // A, B
        });
        setup_d3.init(lengths, [](const char*, std::size_t i) {
            return new network(by_m("setup_d3_m", i).c_str(), 1, fd_setup::d3_terms(MMIN + i));  // A
        });

        setup_p.x(d); setup_p.y(init_p);
        for (unsigned i = 0; i < lengths; ++i) {
            setup_d1[i].in[0](a); setup_d1[i].in[1](b); setup_d1[i].in[2](c); setup_d1[i].y(init_d1_m[i]);
            setup_d2[i].in[0](a); setup_d2[i].in[1](b); setup_d2[i].y(init_d2_m[i]);
            setup_d3[i].in[0](a); setup_d3[i].y(init_d3_m[i]);
            mx_setup_d1.in[i](init_d1_m[i]);
            mx_setup_d2.in[i](init_d2_m[i]);
            mx_setup_d3.in[i](init_d3_m[i]);
        }
        mx_setup_d1.sel(setup_sel); mx_setup_d1.y(init_d1);
        mx_setup_d2.sel(setup_sel); mx_setup_d2.y(init_d2);
        mx_setup_d3.sel(setup_sel); mx_setup_d3.y(init_d3);

        wire_fd_recurrence(*this);  // fd_eval.h's
        ctrl.clk(clk); ctrl.start(start); ctrl.len(len); ctrl.m(m);
        ctrl.fd_sel(fd_sel); ctrl.setup_sel(setup_sel); ctrl.pixel(pixel); ctrl.valid(valid); ctrl.last(last);
        chk_clock.clk(clk);
    }

    void end_of_elaboration() override { chk_clock.derive(timing_graph(*this)); }
    // Shortest clock phases this unit works with (checked by chk_clock; after elaboration).
    const sc_core::sc_time& min_high() const { return chk_clock.min_high(); }
    const sc_core::sc_time& min_low() const { return chk_clock.min_low(); }

private:
    // "<base><m>" for the i-th interval length (m = MMIN + i): nets and networks named by their m.
    static std::string by_m(const char* base, std::size_t i) { return base + std::to_string(MMIN + i); }
    static auto named_net(const char* base) {
        return [base](const char*, std::size_t i) { return new sc_core::sc_signal<fd_t>(by_m(base, i).c_str()); };
    }
};

}  // namespace shading
