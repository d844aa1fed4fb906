// Controller of the square-and-multiply device's stage (ours; RTL twin rtl/sqmul/sqmul_ctrl.v):
// sqmul_count.h stepped at the rising edges of clk and at the falling edges of strobe 17, in one
// process, so an edge of both in the same instant is ordered: the clock first. Strobe 17's edge
// drives `req` (strobe 17's domain) into the synchroniser sync17; each rising edge reads only
// sync17's output `req_s`. Drives MX_P's and MX_B's selects (at rising edges; RG_P latches at the
// falling edge half a clock later) and `done`, output 29's gate (cleared by the strobe itself, set
// at a rising edge).
// Bad input (shading/timing): a strobe before the previous result is valid is reported; that result
// is dropped, the new cos is taken once its request has crossed.
#pragma once

#include <sstream>
#include <systemc>

#include "blocks/mux.h"
#include "core/report_ids.h"
#include "core/timed_block.h"
#include "formats/sqmul_formats.h"
#include "sqmul/sqmul_count.h"

namespace shading {

// A timed_block clocked by clk: its outputs switch at the rising edge (no delay modelled), so the
// timing graph starts paths there and never runs through it. Its last latch is its last rising
// edge: the load checker reads when it took a strobe (RG1's bits, monitors/load_checker.h).
class sqmul_ctrl : public sc_core::sc_module, public timed_block {
public:
    using p_select_t = sc_dt::sc_uint<select_width(sqmul::p_inputs)>;
    using b_select_t = sc_dt::sc_uint<select_width(sqmul::b_inputs)>;
    using z_t = sc_dt::sc_uint<sqmul::z_width>;
    using f_t = sc_dt::sc_uint<sqmul::f_fmt.width>;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> ctl17{"ctl17"};
    sc_core::sc_in<bool> req_s{"req_s"};  // req through sync17: the only strobe input clk reads
    sc_core::sc_in<z_t> z{"z"};           // the LZC of RG1: 9 - z squares
    sc_core::sc_in<f_t> f{"f"};           // n's bits below its leading one, most significant first
    sc_core::sc_out<p_select_t> mx_p_sel{"mx_p_sel"};
    sc_core::sc_out<b_select_t> mx_b_sel{"mx_b_sel"};
    sc_core::sc_out<bool> done{"done"};
    sc_core::sc_out<bool> req{"req"};  // strobe 17's request flip-flop, into sync17

    SC_HAS_PROCESS(sqmul_ctrl);
    explicit sqmul_ctrl(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_edge);
        sensitive << clk.pos() << ctl17.neg();
        dont_initialize();
        done.initialize(true);  // idle: output 29 follows strobe 17, as UA 60553's
    }

    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }
    const sc_core::sc_port_base* clock_port() const override { return &clk; }
    bool switches_on_rising_edge() const override { return true; }
    bool last_latch(sc_core::sc_time& at) const override {
        at = last_rise_;
        return rose_;
    }

    unsigned dropped() const { return dropped_; }  // strobes that abandoned a result
    const sqmul::sqmul_count& state() const { return st_; }

private:
    void on_edge() {
        if (clk.posedge()) {
            last_rise_ = sc_core::sc_time_stamp();
            rose_ = true;
            const auto s = st_.rising(req_s.read(), z.read().to_uint(), f.read().to_uint());
            mx_p_sel.write(p_select_t(s.p));
            mx_b_sel.write(b_select_t(s.b));
            done.write(st_.done());
        }
        if (ctl17.negedge()) {
            const bool was_busy = st_.busy();
            if (st_.strobe()) report(was_busy);
            req.write(st_.req());
            done.write(st_.done());
        }
    }

    void report(bool was_busy) {
        ++dropped_;
        std::ostringstream os;
        os << name() << ": ctl17 fell at " << sc_core::sc_time_stamp() << " before the previous result was valid ("
           << (was_busy ? "still being walked" : "not yet taken by clk")
           << "); that result is dropped, output 29 stays low until the new cos has been raised to n";
        SC_REPORT_WARNING(msg::timing, os.str().c_str());
    }

    sqmul::sqmul_count st_;
    sc_core::sc_time last_rise_;
    bool rose_ = false;
    unsigned dropped_ = 0;
};

}  // namespace shading
