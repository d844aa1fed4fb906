// A memory of `depth` words of W bits (ours: the cells' column buffers, the frame buffer, the geometry
// side's stores), addressed by AW wires; depth <= 2^AW is given at construction, as a frame's size
// is known only at run time. One synchronous write port: at a rising edge of clk where `we` is 1 it
// stores `wd` at `wa` (the values the edge sees, as the frame buffer samples its stream); one
// asynchronous read port, `rd` the word at `ra` (a register file; no delay modelled). To the timing
// graph it is a block on the rising edge: it takes we, wa, wd and ra there and rd starts paths there
// (its read address settles by that edge). A write address beyond depth is dropped and sets `overflow`, a sticky flag (a
// flip-flop that only a new elaboration clears), and is reported (shading/input); a read address
// beyond depth reads 0 and is reported. rtl/blocks/ram.v is the twin, pin for pin.
#pragma once

#include <cstdint>
#include <functional>
#include <sstream>
#include <systemc>
#include <vector>

#include "core/report_ids.h"
#include "core/strobe_gate.h"
#include "core/timed_block.h"

namespace shading {

template <unsigned W, unsigned AW>
class ram : public sc_core::sc_module, public timed_block {
    static_assert(W >= 1 && W <= 64, "a word of 1..64 bits");
    static_assert(AW >= 1 && AW <= 32, "1..32 address wires");

public:
    static constexpr unsigned addr_width = AW;
    using word = sc_dt::sc_uint<W>;
    using addr_t = sc_dt::sc_uint<AW>;

    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<bool> we{"we"};
    sc_core::sc_in<addr_t> wa{"wa"}, ra{"ra"};
    sc_core::sc_in<word> wd{"wd"};
    sc_core::sc_out<word> rd{"rd"};
    sc_core::sc_out<bool> overflow{"overflow"};

    SC_HAS_PROCESS(ram);
    ram(const sc_core::sc_module_name& name, uint64_t depth) : sc_module(name), mem_(depth, 0) {
        if (depth == 0 || depth > (uint64_t(1) << AW)) {
            std::ostringstream m;
            m << this->name() << ": " << depth << " words do not fit " << AW << " address wires; one word kept";
            SC_REPORT_ERROR(msg::config, m.str().c_str());
            mem_.assign(1, 0);
        }
        SC_METHOD(on_clock);
        sensitive << clk.pos();
        dont_initialize();
        SC_METHOD(read);  // rd's only writer
        sensitive << ra << written_;
    }

    // timed_block: clocked by clk, switching at its rising edge.
    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }
    const sc_core::sc_port_base* clock_port() const override { return &clk; }
    bool switches_on_rising_edge() const override { return true; }

    uint64_t depth() const { return mem_.size(); }
    std::size_t writes() const { return writes_; }
    // The word at address a as the read port would show it (a testbench's back door: no pin, no time).
    uint64_t word_at(uint64_t a) const { return a < mem_.size() ? mem_[a] : 0; }
    // Called after every stored word with its address and value (a testbench's monitor, not hardware).
    void on_write(std::function<void(uint64_t, uint64_t)> f) { sink_ = std::move(f); }

private:
    // Woken at rising edges only while `we` may be 1 (core/strobe_gate.h): an idle memory costs no
    // wake-up per clock.
    void on_clock() {
        if (!we_gate_.sample(clk, we)) return;
        const uint64_t a = wa.read().to_uint64();
        if (a >= mem_.size()) {
            overflow.write(true);
            return bad("write", a);
        }
        mem_[a] = wd.read().to_uint64();
        ++writes_;
        if (a == ra.read().to_uint64()) written_.notify(sc_core::SC_ZERO_TIME);  // the read port shows the new word
        if (sink_) sink_(a, mem_[a]);
    }
    void read() {
        const uint64_t a = ra.read().to_uint64();
        if (a >= mem_.size()) {
            bad("read", a);
            rd.write(0);
            return;
        }
        rd.write(mem_[a]);
    }
    void bad(const char* what, uint64_t a) {
        std::ostringstream m;
        m << name() << ": " << what << " address " << a << " beyond the " << mem_.size() << " words";
        if (std::string(what) == "write") m << "; dropped, overflow set";
        SC_REPORT_WARNING(msg::input, m.str().c_str());
    }

    sc_core::sc_event written_;
    std::vector<uint64_t> mem_;
    std::size_t writes_ = 0;
    strobe_gate we_gate_;
    std::function<void(uint64_t, uint64_t)> sink_;
};

}  // namespace shading
