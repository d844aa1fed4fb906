// A synchroniser: STAGES flip-flops in series on the rising edge of the receiving domain's clock,
// W wires wide, for a signal that comes from another clock domain (or from a strobe with no clock
// at all). The first flip-flop may go metastable when the input changes near a rising edge; the
// stages after it give it a whole clock period each to settle, so only q, the last stage, may be
// read by the receiving domain. A change at d is seen at q at the STAGES-th rising edge after it.
// d is read in the delta cycle of the clock's edge: a d driven by a flip-flop of the other domain
// (strobe 17's request) changes a delta cycle after that flip-flop's own edge, so a strobe at a
// rising edge's very instant is taken one edge later, as a real first stage may also do. Each
// wire is synchronised on its own, so W > 1 only carries words that change one wire at a time (a
// Gray count, a toggle); the devices use W = 1.
//   synchroniser_chain<W, STAGES>  the flip-flops as plain state (fast pin-level models step it)
//   synchroniser<W, STAGES>        the block: clk, d, q; the stages before q traced as stage1...
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <systemc>
#include <type_traits>

#include "core/timed_block.h"

namespace shading {

template <unsigned W, unsigned STAGES = 2>
class synchroniser_chain {
    static_assert(W >= 1 && W <= 64, "a synchroniser of 1..64 wires");
    static_assert(STAGES >= 2, "one flip-flop alone may hand on a metastable value: two at least");

public:
    static constexpr uint64_t mask = W == 64 ? ~uint64_t{0} : (uint64_t{1} << W) - 1;

    // A rising edge: every stage takes the one before it, the first takes d (all at once).
    void rising(uint64_t d) {
        for (unsigned i = STAGES - 1; i > 0; --i) s_[i] = s_[i - 1];
        s_[0] = d & mask;
    }
    uint64_t q() const { return s_[STAGES - 1]; }
    uint64_t stage(unsigned i) const { return s_[i]; }  // 0: the flip-flop that samples d

private:
    std::array<uint64_t, STAGES> s_{};  // no reset, as the registers: 0 at power-up
};

template <unsigned W, unsigned STAGES = 2>
class synchroniser : public sc_core::sc_module, public timed_block {
public:
    using word = std::conditional_t<W == 1, bool, sc_dt::sc_uint<W>>;
    sc_core::sc_in<bool> clk{"clk"};
    sc_core::sc_in<word> d{"d"};
    sc_core::sc_out<word> q{"q"};

    SC_HAS_PROCESS(synchroniser);
    explicit synchroniser(const sc_core::sc_module_name& name) : sc_module(name) {
        for (unsigned i = 0; i + 1 < STAGES; ++i)
            stage_[i] = std::make_unique<sc_core::sc_signal<word>>(("stage" + std::to_string(i + 1)).c_str());
        SC_METHOD(on_rising);
        sensitive << clk.pos();
        dont_initialize();
    }

    // timed_block: a register clocked by clk whose output switches at the rising edge (no
    // clock-to-q modelled, as the controllers it feeds): paths start at q and end at d.
    const sc_core::sc_time& delay() const override { return sc_core::SC_ZERO_TIME; }
    const sc_core::sc_port_base* clock_port() const override { return &clk; }
    bool switches_on_rising_edge() const override { return true; }
    const sc_core::sc_port_base* data_port() const override { return &d; }
    const synchroniser_chain<W, STAGES>& chain() const { return chain_; }

private:
    void on_rising() {
        chain_.rising(static_cast<uint64_t>(d.read()));
        for (unsigned i = 0; i + 1 < STAGES; ++i) stage_[i]->write(word(chain_.stage(i)));
        q.write(word(chain_.q()));
    }

    synchroniser_chain<W, STAGES> chain_;
    std::array<std::unique_ptr<sc_core::sc_signal<word>>, STAGES - 1> stage_;
};

}  // namespace shading
