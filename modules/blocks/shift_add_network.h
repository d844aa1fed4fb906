// Shift-and-add network: y = sum of +/- (in[k] << s), a multiplication by constants with no
// multiplier (the interpolation paper: "множення замінюється монтажним зсувом ... 10I = 8I + 2I"; Fig. 3 builds
// B this way). Structure, from a term table given at elaboration:
//   each term:  a shifter (wiring, zero delay) aligns its input onto the W-bit output bus;
//   positive terms: a balanced tree of adders -> P;
//   negative terms: a balanced tree of adders -> Q, one inverter bank -> ~Q;
//   one last adder with carry-in 1: y = P + ~Q + 1 = P - Q (two's complement).
// A balanced tree keeps the depth at ceil(log2 n) adders instead of a chain's n - 1. Every adder
// wraps on W wires; the caller's format table must rule out overflow (interp_formats.h does).
// A negative shift drops low wires (floor) of that term before it is added or subtracted.
#pragma once

#include <algorithm>
#include <sstream>
#include <systemc>
#include <utility>
#include <vector>

#include "blocks/adder.h"
#include "blocks/constant.h"
#include "blocks/inverter_bank.h"
#include "core/report_ids.h"
#include "core/timed_block.h"
#include "blocks/shifter.h"

namespace shading {

struct sa_term {
    unsigned input;  // index of the input bus
    int shift;       // output wire of the input's wire 0 (negative: low wires dropped)
    bool negative;   // subtracted
};

template <unsigned WIN, unsigned W, bool IN_SIGNED = false>
class shift_add_network : public sc_core::sc_module, public timed_block {
public:
    using in_word = sc_dt::sc_uint<WIN>;
    using word = sc_dt::sc_uint<W>;

    sc_core::sc_vector<sc_core::sc_in<in_word>> in{"in"};
    sc_core::sc_out<word> y{"y"};

    // Nets: the aligned terms, the adders' outputs (the last one is y), ~Q.
    sc_core::sc_vector<sc_core::sc_signal<word>> term{"term"};
    sc_core::sc_vector<sc_core::sc_signal<word>> node{"node"};
    sc_core::sc_signal<word> neg_inv{"neg_inv"};
    sc_core::sc_signal<bool> carry0{"carry0"}, carry1{"carry1"};

    sc_core::sc_vector<shifter<WIN, W, IN_SIGNED>> sh{"sh"};
    sc_core::sc_vector<adder<W, W, W, true, true>> add{"add"};
    inverter_bank<W, W, 0> inv{"inv"};
    constant<bool> tie0{"tie0", false}, tie1{"tie1", true};

    SC_HAS_PROCESS(shift_add_network);
    shift_add_network(const sc_core::sc_module_name& name, unsigned n_inputs, std::vector<sa_term> terms)
        : sc_module(name), terms_(std::move(terms)) {
        std::vector<std::size_t> pos, neg;
        for (std::size_t i = 0; i < terms_.size(); ++i) {
            if (terms_[i].input >= n_inputs) config_error("a term names an input that does not exist");
            (terms_[i].negative ? neg : pos).push_back(i);
        }
        if (pos.empty() || terms_.size() < 2) {
            config_error("needs a positive term and at least two terms");
            return;
        }
        in.init(n_inputs);
        term.init(terms_.size());
        sh.init(terms_.size(), [this](const char* nm, std::size_t i) {
            return new shifter<WIN, W, IN_SIGNED>(nm, terms_[i].shift);
        });
        const std::size_t n_add = (pos.size() - 1) + (neg.empty() ? 0 : neg.size());
        add.init(n_add);
        node.init(n_add);
        for (std::size_t i = 0; i < terms_.size(); ++i) {
            sh[i].x(in[terms_[i].input]);
            sh[i].y(term[i]);
        }
        tie0.y(carry0);
        tie1.y(carry1);
        sc_core::sc_time p_arrival, q_arrival;
        sc_core::sc_signal<word>* p = reduce(pos, p_arrival);
        sc_core::sc_signal<word>* out = p;
        delay_ = p_arrival;
        if (!neg.empty()) {
            inv.x(*reduce(neg, q_arrival));
            inv.y(neg_inv);
            auto& a = add[next_];
            a.a(*p); a.b(neg_inv); a.cin(carry1); a.s(node[next_]);  // P + ~Q + 1 = P - Q
            out = &node[next_++];
            delay_ = std::max(p_arrival, q_arrival + inv.delay()) + a.delay();
        } else {
            // No subtraction: the inverter bank is left unused; tie its ports off.
            inv.x(neg_inv);
            inv.y(unused_inv_);
        }
        out_ = out;
        SC_METHOD(wire_y);  // the output net is the last adder's sum; zero-delay wire to the port
        sensitive << *out_;
    }

    // Slowest input-to-y path, summed from the adders' and the inverter bank's own delays while
    // the tree was wired (callers need it for their clock-phase requirements).
    const sc_core::sc_time& delay() const override { return delay_; }

private:
    // Balanced tree over the given terms; returns the net carrying their sum. `arrival` becomes
    // the slowest path from an input to that net (shifters are wiring: terms arrive at 0).
    sc_core::sc_signal<word>* reduce(const std::vector<std::size_t>& idx, sc_core::sc_time& arrival) {
        std::vector<std::pair<sc_core::sc_signal<word>*, sc_core::sc_time>> level;
        for (std::size_t i : idx) level.emplace_back(&term[i], sc_core::SC_ZERO_TIME);
        while (level.size() > 1) {
            std::vector<std::pair<sc_core::sc_signal<word>*, sc_core::sc_time>> next;
            for (std::size_t i = 0; i + 1 < level.size(); i += 2) {
                auto& a = add[next_];
                a.a(*level[i].first); a.b(*level[i + 1].first); a.cin(carry0); a.s(node[next_]);
                next.emplace_back(&node[next_++], std::max(level[i].second, level[i + 1].second) + a.delay());
            }
            if (level.size() % 2) next.push_back(level.back());
            level = std::move(next);
        }
        arrival = level.front().second;
        return level.front().first;
    }

    void config_error(const char* why) {
        std::ostringstream os;
        os << name() << ": " << why;
        SC_REPORT_ERROR(msg::config, os.str().c_str());
    }

    void wire_y() { y.write(out_->read()); }

    std::vector<sa_term> terms_;
    std::size_t next_ = 0;
    sc_core::sc_signal<word>* out_ = nullptr;
    sc_core::sc_time delay_;
    sc_core::sc_signal<word> unused_inv_{"unused_inv"};
};

}  // namespace shading
