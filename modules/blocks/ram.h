// A small memory of DEPTH words of W bits (ours: the cells' column buffers): one synchronous write
// port, at a rising edge of clk where `we` is 1 it stores `wd` at `wa` (the values the edge sees, as
// the frame buffer samples its stream); one asynchronous read port, `rd` the word at `ra` (a
// register file; no delay modelled, outside the timing graph like the frame buffer). A write or
// read address beyond DEPTH is bad input: reported (shading/input), the write dropped, the read 0.
#pragma once

#include <sstream>
#include <systemc>
#include <vector>

#include "core/report_ids.h"
#include "formats/interp_formats.h"

namespace shading {

template <unsigned W, unsigned DEPTH>
class ram : public sc_core::sc_module {
public:
    static constexpr unsigned addr_width = interp::code_width(DEPTH);
    using word = sc_dt::sc_uint<W>;
    using addr_t = sc_dt::sc_uint<addr_width>;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> we{"we"};
    sc_core::sc_in<addr_t> wa{"wa"}, ra{"ra"};
    sc_core::sc_in<word> wd{"wd"};
    sc_core::sc_out<word> rd{"rd"};

    SC_HAS_PROCESS(ram);
    explicit ram(const sc_core::sc_module_name& name) : sc_module(name), mem_(DEPTH, 0) {
        SC_METHOD(on_clock);
        sensitive << clk.pos();
        dont_initialize();
        SC_METHOD(read);  // rd's only writer
        sensitive << ra << written_;
    }

    std::size_t writes() const { return writes_; }

private:
    void on_clock() {
        if (!we.read()) return;
        const unsigned a = wa.read().to_uint();
        if (a >= DEPTH) return bad("write", a);
        mem_[a] = wd.read();
        ++writes_;
        if (a == ra.read().to_uint()) written_.notify(sc_core::SC_ZERO_TIME);  // the read port shows the new word
    }
    void read() {
        const unsigned a = ra.read().to_uint();
        if (a >= DEPTH) {
            bad("read", a);
            rd.write(0);
            return;
        }
        rd.write(mem_[a]);
    }
    void bad(const char* what, unsigned a) {
        std::ostringstream m;
        m << name() << ": " << what << " address " << a << " beyond the " << DEPTH << " words";
        SC_REPORT_WARNING(msg::input, m.str().c_str());
    }

    sc_core::sc_event written_;
    std::vector<word> mem_;
    std::size_t writes_ = 0;
};

}  // namespace shading
