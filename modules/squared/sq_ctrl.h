// Controller of the squared-quadratic device's squaring stage (ours): sq_count.h stepped at the
// rising edges of clk and at the falling edges of strobe 17, in one process, so an edge of both in
// the same instant is ordered: the clock first. Strobe 17's edge drives `req` (strobe 17's
// domain) into the synchroniser sync17; each rising edge reads only sync17's output `req_s`.
// Drives MX_SQ's select (at rising edges; RG_SQ latches at the falling edge half a clock later) and
// `done`, output 29's gate (cleared by the strobe itself, set at a rising edge).
// Bad input (shading/timing): a strobe before the previous result is valid is reported; that
// result is dropped, the new cos is taken once its request has crossed.
#pragma once

#include <sstream>
#include <systemc>

#include "core/report_ids.h"
#include "core/timed_block.h"
#include "formats/squared_formats.h"
#include "squared/sq_count.h"

namespace shading {

// A timed_block clocked by clk: its outputs switch at the rising edge (no delay modelled), so the
// timing graph starts paths there and never runs through it.
class sq_ctrl : public sc_core::sc_module, public timed_block {
public:
    using select_t = sc_dt::sc_uint<2>;
    using z_t = sc_dt::sc_uint<squared::z_width>;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> ctl17{"ctl17"};
    sc_core::sc_in<bool> req_s{"req_s"};  // req through sync17: the only strobe input clk reads
    sc_core::sc_in<z_t> z{"z"};           // the LZC of RG1: 9 - z squarings
    sc_core::sc_out<select_t> sel{"sel"};
    sc_core::sc_out<bool> done{"done"};
    sc_core::sc_out<bool> req{"req"};     // strobe 17's request flip-flop, into sync17

    SC_HAS_PROCESS(sq_ctrl);
    explicit sq_ctrl(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_edge);
        sensitive << clk.pos() << ctl17.neg();
        dont_initialize();
        done.initialize(true);  // idle: output 29 follows strobe 17, as UA 60553's
    }

    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }
    const sc_core::sc_port_base* clock_port() const override { return &clk; }
    bool switches_on_rising_edge() const override { return true; }

    unsigned dropped() const { return dropped_; }  // strobes that abandoned a result
    const squared::sq_count& state() const { return st_; }

private:
    void on_edge() {
        if (clk.posedge()) {
            const auto s = st_.rising(req_s.read(), z.read().to_uint());
            sel.write(select_t(s));
            done.write(st_.done());
        }
        if (ctl17.negedge()) {
            const bool was_busy = st_.busy();
            if (st_.strobe()) report(was_busy);
            req.write(st_.req());
            done.write(false);
        }
    }

    void report(bool was_busy) {
        ++dropped_;
        std::ostringstream os;
        os << name() << ": ctl17 fell at " << sc_core::sc_time_stamp() << " before the previous result was valid ("
           << (was_busy ? "still being squared" : "not yet taken by clk")
           << "); that result is dropped, output 29 stays low until the new cos has been squared";
        SC_REPORT_WARNING(msg::timing, os.str().c_str());
    }

    squared::sq_count st_;
    unsigned dropped_ = 0;
};

}  // namespace shading
