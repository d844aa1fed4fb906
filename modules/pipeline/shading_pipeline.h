// The interpolation paper's shading system in hardware: a raster-line shading unit that takes one interval at a
// time from the geometry side and writes its pixels as an R, G, B stream. A device top: it only
// instantiates and wires.
//   job registers  rg_y, rg_x0, rg_len, rg_m, rg_deg2 and the samples' N.H / N.L codes
//                  rg_nh1..4, rg_nl1..4, latched where ld_job falls (the edge that takes a job)
//   rg_dy, rg_dx0, rg_dlen, rg_dm, rg_ddeg2  the descriptor of the interval in the sample
//                  registers (ld_d, at its last sample's latch), read by the pixel controller
//   mx_nh, mx_nl   the sample being formed (smp_sel)
//   rg_lnh, rg_lnl the last sample's N.H / N.L (strobe ld_last, at every sample's latch), and
//   eq_nh, eq_nl, and_carry  whether the job's first codes are those (carry_hit): with `carry` (ours)
//                  that sample's colour is taken from the channels' rg_last instead of the device
//   dev            the specular device (pipe_device.h): UA 60553, Fig. 1, with the generator of
//                  `a` AGen (a_gen_linear: the patent's constants; a_gen_tuned: minimax /
//                  rom_matched; a_gen_rom: UA 22802), or the squared-quadratic device (AGen =
//                  squared_device, on clk), driven through its Fig. 3 strobes: ctl15, ctl20, ctl22,
//                  ctl24 once per frame, ctl17 once per sample (out29_valid is its output 29)
//   rg_kd_r/g/b, rg_amb_r/g/b  the frame's k_d*I and ambient codes (strobe ld_k)
//   smp_r/g/b      per channel: diffuse multiplier, adders, sample registers I1..I4, interval
//                  registers, cubic and quadratic coefficient units (sample_channel.h)
//   horner_r/g/b   per channel: degree-select multiplexers, the Fig. 4 Horner unit and the output
//     or fd_r/g/b  clamp (horner_channel.h), or our forward differences (fd_channel.h: fd_eval<M>
//                  for one interval length, or fd_eval_var for any m per interval)
//   ctl_sample     sample controller (falling edges; the geometry side's handshake, sample_ctrl.h)
//   ctl_pixel      pixel controller (rising edges; horner_pixel_ctrl.h or fd_pixel_ctrl.h)
// Pixel stream: at a rising edge of clk where px_valid = 1, px_r/g/b (Q8.8 codes) belong at
// (px_x, px_y); a frame_buffer samples it there.
#pragma once

#include <string>
#include <systemc>
#include <type_traits>

#include "arith/pipeline_arith.h"
#include "blocks/and_gate.h"
#include "blocks/eq_cmp.h"
#include "blocks/mux.h"
#include "blocks/reg.h"
#include "blocks/wire.h"
#include "formats/interp_formats.h"
#include "formats/specular_formats.h"
#include "formats/ua60553_formats.h"
#include "interp/interp_delays.h"
#include "monitors/phase_checker.h"
#include "pipeline/fd_channel.h"
#include "pipeline/fd_pixel_ctrl.h"
#include "pipeline/horner_channel.h"
#include "pipeline/horner_pixel_ctrl.h"
#include "pipeline/pipe_device.h"
#include "pipeline/pipeline_pins.h"
#include "pipeline/sample_channel.h"
#include "pipeline/sample_ctrl.h"
#include "specular/block_delays.h"

namespace shading {

// Pins: pipeline_pins.h.
template <class AGen, pipeline::evaluator EVAL>
class shading_pipeline : public sc_core::sc_module, public pipeline_pins {
    static constexpr bool horner = EVAL == pipeline::evaluator::horner;
    static constexpr unsigned WCOS = spec::cos_fmt.width;
    static constexpr unsigned WI = interp::sample_fmt.width;
    static_assert(AGen::n_fmt.width == ua60553::n_fmt.width, "in_n: every device takes n on in16's width");
    static_assert(std::is_same_v<len_t, sc_dt::sc_uint<sample_ctrl::len_bits>> &&
                      std::is_same_v<m_t, sc_dt::sc_uint<sample_ctrl::m_bits>>,
                  "the job registers' widths are the sample controller's");

public:
    using eval_channel = std::conditional_t<horner, horner_channel, fd_channel>;
    using pixel_ctrl = std::conditional_t<horner, horner_pixel_ctrl, fd_pixel_ctrl>;

    // Nets.
    sc_core::sc_signal<bool> ld_job{"ld_job"}, ld_d{"ld_d"}, ld_k{"ld_k"}, samples_ready{"samples_ready"}, ld_e{"ld_e"};
    sc_core::sc_signal<bool> ctl15{"ctl15"}, ctl17{"ctl17"}, ctl20{"ctl20"}, ctl22{"ctl22"}, ctl24{"ctl24"};
    sc_core::sc_signal<bool> out29_valid{"out29_valid"};
    sc_core::sc_signal<bool> ld_i1{"ld_i1"}, ld_i2{"ld_i2"}, ld_i3{"ld_i3"}, ld_i4{"ld_i4"};
    sc_core::sc_signal<coord_t> y{"y"}, x0{"x0"};
    sc_core::sc_signal<len_t> len{"len"};
    sc_core::sc_signal<m_t> m{"m"};
    sc_core::sc_signal<bit_t> deg2_job{"deg2_job"};
    sc_core::sc_signal<coord_t> d_y{"d_y"}, d_x0{"d_x0"};  // the descriptor of the interval in I1..I4
    sc_core::sc_signal<len_t> d_len{"d_len"};
    sc_core::sc_signal<m_t> d_m{"d_m"};
    sc_core::sc_signal<bit_t> d_deg2{"d_deg2"};
    sc_core::sc_signal<cos_t> nh1{"nh1"}, nh2{"nh2"}, nh3{"nh3"}, nh4{"nh4"}, nl1{"nl1"}, nl2{"nl2"}, nl3{"nl3"},
        nl4{"nl4"};
    sc_core::sc_signal<sample_ctrl::sel_t> smp_sel{"smp_sel"};
    sc_core::sc_signal<cos_t> in18_cos{"in18_cos"}, cos_nl{"cos_nl"};
    sc_core::sc_signal<cos_t> last_nh{"last_nh"}, last_nl{"last_nl"};  // the last sample's codes
    sc_core::sc_signal<bool> ld_last{"ld_last"}, nh_hit{"nh_hit"}, nl_hit{"nl_hit"}, carry_hit{"carry_hit"};
    sc_core::sc_signal<sample_ctrl::bit_t> carry_sel{"carry_sel"};
    sc_core::sc_signal<sc_dt::sc_uint<spec::out_fmt.width>> out25_r{"out25_r"}, out26_g{"out26_g"}, out27_b{"out27_b"};
    sc_core::sc_signal<pipeline::kdi_t> kdi_r{"kdi_r"}, kdi_g{"kdi_g"}, kdi_b{"kdi_b"};
    sc_core::sc_signal<sample_t> amb_r{"amb_r"}, amb_g{"amb_g"}, amb_b{"amb_b"};
    template <class T>
    using rgb_nets = sc_core::sc_vector<sc_core::sc_signal<T>>;
    rgb_nets<pipeline::coef_t> ca{"ca", 3, rgb_net<pipeline::coef_t>}, cb{"cb", 3, rgb_net<pipeline::coef_t>},
        cc{"cc", 3, rgb_net<pipeline::coef_t>}, cd{"cd", 3, rgb_net<pipeline::coef_t>}, qa{"qa", 3, rgb_net<pipeline::coef_t>},
        qb{"qb", 3, rgb_net<pipeline::coef_t>}, qc{"qc", 3, rgb_net<pipeline::coef_t>};
    sc_core::sc_signal<bool> ev_start{"ev_start"}, deg2{"deg2"};
    sc_core::sc_signal<sc_dt::sc_uint<1>> deg_sel{"deg_sel"};
    sc_core::sc_signal<horner_channel::t_t> t{"t"};
    sc_core::sc_signal<fd_channel::len_t> ev_len{"ev_len"};
    sc_core::sc_signal<fd_channel::m_t> ev_m{"ev_m"};
    // Horner: done, busy; forward differences: valid, last.
    rgb_nets<bool> ev_done{"ev_done", 3, rgb_net<bool>}, ev_busy{"ev_busy", 3, rgb_net<bool>};

    // Blocks.
    reg<16> rg_y, rg_x0, rg_len;
    reg<sample_ctrl::m_bits> rg_m;
    reg<1> rg_deg2;
    reg<16> rg_dy, rg_dx0, rg_dlen;
    reg<sample_ctrl::m_bits> rg_dm;
    reg<1> rg_ddeg2;
    reg<WCOS> rg_nh1, rg_nh2, rg_nh3, rg_nh4, rg_nl1, rg_nl2, rg_nl3, rg_nl4;
    mux<WCOS, 4> mx_nh, mx_nl;
    reg<WCOS> rg_lnh, rg_lnl;
    eq_cmp<WCOS> eq_nh, eq_nl;
    and_gate and_carry;
    typename pipe_device<AGen>::type dev;
    reg<pipeline::kdi_fmt.width> rg_kd_r, rg_kd_g, rg_kd_b;
    reg<WI> rg_amb_r, rg_amb_g, rg_amb_b;
    sample_channel smp_r, smp_g, smp_b;
    eval_channel ev_r, ev_g, ev_b;
    wire<bool> out_valid{"out_valid"};
    sample_ctrl ctl_sample;
    pixel_ctrl ctl_pixel;
    // Assertion monitor (not hardware): the clock's phases along every path of the top, also those
    // between its units (each unit's own chk_clock sees only its own).
    phase_checker chk_clock{"chk_clock"};

    // fd_m: the interval length 2^fd_m the forward-difference evaluator is built for, 0 for any m per
    // interval (fd_eval_var); ignored for Horner. carry: a job whose first sample point is the last
    // sample's takes its colour from rg_last (sample_ctrl.h); off, the controller never selects it.
    shading_pipeline(const sc_core::sc_module_name& name, overflow_mode mode, const typename AGen::config& gen,
                     interp::sample_set set, interp::div3_mode div, unsigned fd_m = 4, const block_delays& bd = {},
                     const interp_delays& dl = {}, bool carry = false);

    void end_of_elaboration() override { chk_clock.derive(timing_graph(*this)); }
    // Shortest clock phases the whole top works with (after elaboration).
    const sc_core::sc_time& min_high() const { return chk_clock.min_high(); }
    const sc_core::sc_time& min_low() const { return chk_clock.min_low(); }

    // Nothing taken and not yet written out.
    bool idle() const { return ctl_sample.idle() && ctl_pixel.idle(); }
    // Colours the device formed, and colours carried from rg_last (the sample controller's counts).
    std::size_t samples() const { return ctl_sample.samples(); }
    std::size_t carried() const { return ctl_sample.carried(); }

private:
    // Per-channel nets named <base>_r, _g, _b.
    template <class T>
    static sc_core::sc_signal<T>* rgb_net(const char* generated, std::size_t i) {
        std::string n(generated);
        n = n.substr(0, n.rfind('_') + 1) + "rgb"[i];
        return new sc_core::sc_signal<T>(n.c_str());
    }
};

// Defined outside the class so that it is not inline: a program that declares an instance
// `extern template` (testbenches/pipeline/pipeline_tops.h) then takes it from the one unit that
// instantiates it instead of compiling the whole top again.
template <class AGen, pipeline::evaluator EVAL>
shading_pipeline<AGen, EVAL>::shading_pipeline(const sc_core::sc_module_name& name, overflow_mode mode,
                                               const typename AGen::config& gen, interp::sample_set set,
                                               interp::div3_mode div, unsigned fd_m, const block_delays& bd,
                                               const interp_delays& dl, bool carry)
    : sc_module(name), rg_y("rg_y", dl.reg), rg_x0("rg_x0", dl.reg), rg_len("rg_len", dl.reg),
      rg_m("rg_m", dl.reg), rg_deg2("rg_deg2", dl.reg), rg_dy("rg_dy", dl.reg), rg_dx0("rg_dx0", dl.reg),
      rg_dlen("rg_dlen", dl.reg), rg_dm("rg_dm", dl.reg), rg_ddeg2("rg_ddeg2", dl.reg), rg_nh1("rg_nh1", dl.reg), rg_nh2("rg_nh2", dl.reg),
      rg_nh3("rg_nh3", dl.reg), rg_nh4("rg_nh4", dl.reg), rg_nl1("rg_nl1", dl.reg), rg_nl2("rg_nl2", dl.reg),
      rg_nl3("rg_nl3", dl.reg), rg_nl4("rg_nl4", dl.reg), mx_nh("mx_nh", dl.mux), mx_nl("mx_nl", dl.mux),
      rg_lnh("rg_lnh", dl.reg), rg_lnl("rg_lnl", dl.reg), eq_nh("eq_nh", dl.mux), eq_nl("eq_nl", dl.mux),
      and_carry("and_carry", dl.mux),
      dev("dev", mode, gen, bd), rg_kd_r("rg_kd_r", dl.reg), rg_kd_g("rg_kd_g", dl.reg), rg_kd_b("rg_kd_b", dl.reg),
      rg_amb_r("rg_amb_r", dl.reg), rg_amb_g("rg_amb_g", dl.reg), rg_amb_b("rg_amb_b", dl.reg),
      smp_r("smp_r", set, div, dl), smp_g("smp_g", set, div, dl), smp_b("smp_b", set, div, dl),
      ev_r(horner ? "horner_r" : "fd_r", fd_m, dl), ev_g(horner ? "horner_g" : "fd_g", fd_m, dl),
      ev_b(horner ? "horner_b" : "fd_b", fd_m, dl),
      ctl_sample("ctl_sample", horner ? 0 : fd_m, pipe_device<AGen>::clocked, carry), ctl_pixel("ctl_pixel") {
    // Job registers: latched where ld_job falls.
    rg_y.ctl(ld_job); rg_y.d(in_y); rg_y.q(y);
    rg_x0.ctl(ld_job); rg_x0.d(in_x0); rg_x0.q(x0);
    rg_len.ctl(ld_job); rg_len.d(in_len); rg_len.q(len);
    rg_m.ctl(ld_job); rg_m.d(in_m); rg_m.q(m);
    rg_deg2.ctl(ld_job); rg_deg2.d(in_deg2); rg_deg2.q(deg2_job);
    // Descriptor registers: the job's y, x0, len, m, deg2 travel with its samples (ld_d falls at
    // the last sample's latch), so the job registers are free for the next job.
    rg_dy.ctl(ld_d); rg_dy.d(y); rg_dy.q(d_y);
    rg_dx0.ctl(ld_d); rg_dx0.d(x0); rg_dx0.q(d_x0);
    rg_dlen.ctl(ld_d); rg_dlen.d(len); rg_dlen.q(d_len);
    rg_dm.ctl(ld_d); rg_dm.d(m); rg_dm.q(d_m);
    rg_ddeg2.ctl(ld_d); rg_ddeg2.d(deg2_job); rg_ddeg2.q(d_deg2);
    reg<WCOS>* rnh[] = {&rg_nh1, &rg_nh2, &rg_nh3, &rg_nh4};
    reg<WCOS>* rnl[] = {&rg_nl1, &rg_nl2, &rg_nl3, &rg_nl4};
    sc_core::sc_in<cos_t>* pnh[] = {&in_nh1, &in_nh2, &in_nh3, &in_nh4};
    sc_core::sc_in<cos_t>* pnl[] = {&in_nl1, &in_nl2, &in_nl3, &in_nl4};
    sc_core::sc_signal<cos_t>* snh[] = {&nh1, &nh2, &nh3, &nh4};
    sc_core::sc_signal<cos_t>* snl[] = {&nl1, &nl2, &nl3, &nl4};
    for (int k = 0; k < 4; ++k) {
        rnh[k]->ctl(ld_job); rnh[k]->d(*pnh[k]); rnh[k]->q(*snh[k]);
        rnl[k]->ctl(ld_job); rnl[k]->d(*pnl[k]); rnl[k]->q(*snl[k]);
        mx_nh.in[k](*snh[k]);
        mx_nl.in[k](*snl[k]);
    }
    mx_nh.sel(smp_sel); mx_nh.y(in18_cos);
    mx_nl.sel(smp_sel); mx_nl.y(cos_nl);
    // The last sample's codes, and whether the job's first sample is that point again.
    rg_lnh.ctl(ld_last); rg_lnh.d(in18_cos); rg_lnh.q(last_nh);
    rg_lnl.ctl(ld_last); rg_lnl.d(cos_nl); rg_lnl.q(last_nl);
    eq_nh.a(nh1); eq_nh.b(last_nh); eq_nh.y(nh_hit);
    eq_nl.a(nl1); eq_nl.b(last_nl); eq_nl.y(nl_hit);
    and_carry.a(nh_hit); and_carry.b(nl_hit); and_carry.y(carry_hit);

    // The specular device: frame constants straight from the pins through its own registers.
    dev.ctl15(ctl15); dev.ctl17(ctl17); dev.ctl20(ctl20); dev.ctl22(ctl22); dev.ctl24(ctl24);
    dev.in16_n(in_n); dev.in18_cos(in18_cos);
    dev.in19_ksi_r(in_ksi_r); dev.in21_ksi_g(in_ksi_g); dev.in23_ksi_b(in_ksi_b);
    dev.out25_r(out25_r); dev.out26_g(out26_g); dev.out27_b(out27_b); dev.out29_valid(out29_valid);
    if constexpr (pipe_device<AGen>::clocked) dev.clk(clk);
    rg_kd_r.ctl(ld_k); rg_kd_r.d(in_kdi_r); rg_kd_r.q(kdi_r);
    rg_kd_g.ctl(ld_k); rg_kd_g.d(in_kdi_g); rg_kd_g.q(kdi_g);
    rg_kd_b.ctl(ld_k); rg_kd_b.d(in_kdi_b); rg_kd_b.q(kdi_b);
    rg_amb_r.ctl(ld_k); rg_amb_r.d(in_amb_r); rg_amb_r.q(amb_r);
    rg_amb_g.ctl(ld_k); rg_amb_g.d(in_amb_g); rg_amb_g.q(amb_g);
    rg_amb_b.ctl(ld_k); rg_amb_b.d(in_amb_b); rg_amb_b.q(amb_b);

    sample_channel* smp[] = {&smp_r, &smp_g, &smp_b};
    eval_channel* ev[] = {&ev_r, &ev_g, &ev_b};
    sc_core::sc_signal<pipeline::kdi_t>* kd[] = {&kdi_r, &kdi_g, &kdi_b};
    sc_core::sc_signal<sample_t>* amb[] = {&amb_r, &amb_g, &amb_b};
    sc_core::sc_signal<sc_dt::sc_uint<spec::out_fmt.width>>* spec[] = {&out25_r, &out26_g, &out27_b};
    sc_core::sc_out<sample_t>* px[] = {&px_r, &px_g, &px_b};
    for (int ch = 0; ch < 3; ++ch) {
        sample_channel& s = *smp[ch];
        s.clk(clk);
        s.ld_i1(ld_i1); s.ld_i2(ld_i2); s.ld_i3(ld_i3); s.ld_i4(ld_i4); s.ld_e(ld_e);
        s.kdi(*kd[ch]); s.ambient(*amb[ch]); s.cos_nl(cos_nl); s.specular(*spec[ch]);
        s.carry_sel(carry_sel); s.ld_last(ld_last);
        s.ca(ca[ch]); s.cb(cb[ch]); s.cc(cc[ch]); s.cd(cd[ch]); s.qa(qa[ch]); s.qb(qb[ch]); s.qc(qc[ch]);
        eval_channel& e = *ev[ch];
        e.clk(clk); e.start(ev_start); e.deg_sel(deg_sel);
        e.ca(ca[ch]); e.cb(cb[ch]); e.cc(cc[ch]); e.cd(cd[ch]); e.qa(qa[ch]); e.qb(qb[ch]); e.qc(qc[ch]);
        e.px(*px[ch]);
        if constexpr (horner) {
            e.deg2(deg2); e.t(t);
            e.done(ev_done[ch]); e.busy(ev_busy[ch]);
        } else {
            e.len(ev_len); e.m(ev_m);
            e.valid(ev_done[ch]); e.last(ev_busy[ch]);
        }
    }
    out_valid.x(ev_done[0]); out_valid.y(px_valid);

    ctl_sample.clk(clk); ctl_sample.start(start); ctl_sample.load_frame(load_frame);
    ctl_sample.len(len); ctl_sample.m(m); ctl_sample.deg2(deg2_job); ctl_sample.ld_e(ld_e);
    ctl_sample.dev_valid(out29_valid);
    ctl_sample.ready(ready); ctl_sample.ld_job(ld_job); ctl_sample.ld_d(ld_d);
    ctl_sample.ctl15(ctl15); ctl_sample.ctl17(ctl17); ctl_sample.ctl20(ctl20); ctl_sample.ctl22(ctl22);
    ctl_sample.ctl24(ctl24); ctl_sample.ld_k(ld_k);
    ctl_sample.smp_sel(smp_sel);
    ctl_sample.ld_i1(ld_i1); ctl_sample.ld_i2(ld_i2); ctl_sample.ld_i3(ld_i3); ctl_sample.ld_i4(ld_i4);
    ctl_sample.samples_ready(samples_ready);
    ctl_sample.carry_hit(carry_hit); ctl_sample.carry_sel(carry_sel); ctl_sample.ld_last(ld_last);

    ctl_pixel.clk(clk); ctl_pixel.samples_ready(samples_ready);
    ctl_pixel.y(d_y); ctl_pixel.x0(d_x0); ctl_pixel.deg2_in(d_deg2);
    ctl_pixel.ld_e(ld_e); ctl_pixel.start(ev_start); ctl_pixel.deg_sel(deg_sel);
    ctl_pixel.px_x(px_x); ctl_pixel.px_y(px_y);
    if constexpr (horner) {
        ctl_pixel.len(d_len); ctl_pixel.m(d_m);
        ctl_pixel.busy(ev_busy[0]); ctl_pixel.done(ev_done[0]);
        ctl_pixel.deg2(deg2); ctl_pixel.t(t);
    } else {
        ctl_pixel.len_in(d_len); ctl_pixel.m_in(d_m); ctl_pixel.m(ev_m);
        ctl_pixel.valid(ev_done[0]); ctl_pixel.last(ev_busy[0]);
        ctl_pixel.len(ev_len);
    }
    chk_clock.clk(clk);
}

}  // namespace shading
