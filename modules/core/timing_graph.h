// Timing paths derived from the elaborated design, not summed by hand. After binding (from
// end_of_elaboration on), timing_graph walks the module hierarchy below a top: every module that
// implements timed_block (core/timed_block.h; every block in modules/blocks does) is a step whose
// inputs and outputs are the channels its ports are bound to (sc_port_base::get_interface());
// a module without the interface is descended into. The longest combinational path between two
// sets of channels is then a longest path in that DAG: registers start paths (at q, after their
// clock-to-q) and end them (at d); constants and wires count 0.
//
// A module without timed_block that reads a net on a path and drives nets of its own would make
// the path silently short: it is reported (shading/config) and counted as 0. Monitors, which only
// read, are not on any path. A combinational loop is reported the same way.
//
//   timing_graph g(device);                       // device: any module, after elaboration
//   g.to_outputs(device.rg2).to_string()          // "rg2 -> mul7 -> ... -> mul12 = 11.2 ns"
//   g.longest_from_registers(regs, {g.d_of(r)})   // register to register (setup time excluded)
//   g.longest_from_channels(g.inputs(), ...)      // from the top's input pins
#pragma once

#include <algorithm>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <systemc>
#include <vector>

#include "core/report_ids.h"
#include "core/timed_block.h"

namespace shading {

// One longest path: the blocks it crosses (names relative to the graph's top; the source register
// or source net first) and its length (including the source register's clock-to-q).
struct timing_path {
    bool found = false;  // false: no sink is reachable from the sources
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
    std::vector<std::string> blocks;

    std::string to_string() const {
        std::ostringstream os;
        for (std::size_t i = 0; i < blocks.size(); ++i) os << (i ? " -> " : "") << blocks[i];
        os << " = " << delay.to_seconds() * 1e9 << " ns";
        return os.str();
    }
};

class timing_graph {
public:
    using channel = const void*;  // the bound channel, by its most-derived address

    explicit timing_graph(const sc_core::sc_object& top) : top_(&top) {
        prefix_ = std::string(top.name()) + ".";
        for (auto* p : own_ports(top)) {
            const channel c = channel_of(*p);
            if (c == nullptr) continue;
            (is_output(*p) ? outputs_ : inputs_).push_back(c);
        }
        for (auto* child : top.get_child_objects()) walk(*child);
    }

    // The channel a port is bound to (nullptr before elaboration has completed the binding).
    static channel channel_of(const sc_core::sc_port_base& p) {
        const sc_core::sc_interface* i = p.get_interface();
        return i == nullptr ? nullptr : dynamic_cast<const void*>(i);
    }
    static channel channel_of(const sc_core::sc_interface& i) { return dynamic_cast<const void*>(&i); }

    const std::vector<channel>& outputs() const { return outputs_; }  // the top's output pins
    const std::vector<channel>& inputs() const { return inputs_; }    // the top's input pins
    std::vector<const sc_core::sc_object*> registers() const {
        std::vector<const sc_core::sc_object*> r;
        for (const auto& n : nodes_)
            if (n.tb != nullptr && n.tb->is_register()) r.push_back(n.obj);
        return r;
    }
    std::vector<const sc_core::sc_object*> registers_clocked_by(channel clk) const {
        std::vector<const sc_core::sc_object*> r;
        for (const auto& n : nodes_)
            if (n.tb != nullptr && n.tb->is_register() && n.clock == clk) r.push_back(n.obj);
        return r;
    }
    // The channels a clocked block takes at its edge: its data input and any other input (a
    // controller's next-state inputs), not its clock.
    std::vector<channel> taken_by(const sc_core::sc_object& reg) const {
        const node& n = node_of(reg);
        std::vector<channel> c = n.ins;
        if (n.data != nullptr) c.push_back(n.data);
        return c;
    }
    channel q_of(const sc_core::sc_object& reg) const { return node_of(reg).outs.at(0); }
    channel d_of(const sc_core::sc_object& reg) const { return node_of(reg).data; }
    channel clock_of(const sc_core::sc_object& reg) const { return node_of(reg).clock; }
    // Hierarchical name relative to the top ("a_gen.mul6").
    std::string relative(const sc_core::sc_object& o) const { return relative_name(o.name()); }

    // Longest path from the q of any of `from` (a register) to any of the channels `to`.
    timing_path longest_from_registers(const std::vector<const sc_core::sc_object*>& from,
                                       const std::vector<channel>& to) const {
        std::vector<source> src;
        for (auto* r : from) {
            const node& n = node_of(*r);
            if (n.tb == nullptr || !n.tb->is_register()) {
                error(std::string(r->name()) + " is not a register (timed_block with a clock port)");
                continue;
            }
            for (channel q : n.outs) src.push_back({q, n.tb->delay(), relative(*r)});
        }
        return longest(src, to);
    }
    // Longest path from any of the channels `from` (arrival 0) to any of the channels `to`.
    timing_path longest_from_channels(const std::vector<channel>& from, const std::vector<channel>& to) const {
        std::vector<source> src;
        for (channel c : from) src.push_back({c, sc_core::SC_ZERO_TIME, channel_name(c)});
        return longest(src, to);
    }
    timing_path to_outputs(const sc_core::sc_object& reg) const { return longest_from_registers({&reg}, outputs_); }
    // From `from`'s q to `to`'s d input (`to`'s setup time not included: setup_time() of the block).
    timing_path to_register(const sc_core::sc_object& from, const sc_core::sc_object& to) const {
        return longest_from_registers({&from}, {d_of(to)});
    }

    // Every register's longest path to the top's outputs, one line each.
    std::string describe() const {
        std::ostringstream os;
        for (auto* r : registers()) os << relative(*r) << ": " << to_outputs(*r).to_string() << '\n';
        return os.str();
    }

private:
    struct node {
        const sc_core::sc_object* obj;
        const timed_block* tb;  // nullptr: a leaf module without the interface
        std::vector<channel> ins, outs;
        channel clock = nullptr, data = nullptr;
    };
    struct source {
        channel c;
        sc_core::sc_time at;
        std::string name;
    };
    struct best {
        bool reach = false;
        sc_core::sc_time rest = sc_core::SC_ZERO_TIME;  // from this channel to the farthest sink
        std::size_t via = npos;                         // node taken (npos: the path ends here)
        channel next = nullptr;
    };
    static constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();

    static bool is_output(const sc_core::sc_port_base& p) {
        const std::string k = p.kind();
        return k.rfind("sc_out", 0) == 0 || k.rfind("sc_inout", 0) == 0 || k == "sc_fifo_out";
    }

    // A module's own ports, also those inside its sc_vectors (not those of child modules).
    static std::vector<const sc_core::sc_port_base*> own_ports(const sc_core::sc_object& m) {
        std::vector<const sc_core::sc_port_base*> ports;
        std::set<const sc_core::sc_object*> seen;
        collect_ports(m, ports, seen);
        return ports;
    }
    static void collect_ports(const sc_core::sc_object& o, std::vector<const sc_core::sc_port_base*>& ports,
                              std::set<const sc_core::sc_object*>& seen) {
        for (auto* c : o.get_child_objects()) {
            if (!seen.insert(c).second || dynamic_cast<const sc_core::sc_module*>(c) != nullptr) continue;
            if (auto* p = dynamic_cast<const sc_core::sc_port_base*>(c)) ports.push_back(p);
            else collect_ports(*c, ports, seen);  // e.g. an sc_vector of ports
        }
    }

    static bool has_child_module(const sc_core::sc_object& o) {
        for (auto* c : o.get_child_objects())
            if (dynamic_cast<const sc_core::sc_module*>(c) != nullptr ||
                (dynamic_cast<const sc_core::sc_port_base*>(c) == nullptr && has_child_module(*c)))
                return true;
        return false;
    }

    void walk(const sc_core::sc_object& o) {
        auto* m = dynamic_cast<const sc_core::sc_module*>(&o);
        if (m == nullptr) {
            if (dynamic_cast<const sc_core::sc_port_base*>(&o) == nullptr)
                for (auto* c : o.get_child_objects()) walk(*c);  // sc_vector of modules
            return;
        }
        auto* tb = dynamic_cast<const timed_block*>(m);
        if (tb == nullptr && has_child_module(*m)) {  // a hierarchical unit: its blocks are the steps
            for (auto* c : m->get_child_objects()) walk(*c);
            return;
        }
        node n{m, tb, {}, {}, nullptr, nullptr};
        const sc_core::sc_port_base* clk = tb ? tb->clock_port() : nullptr;
        const sc_core::sc_port_base* d = tb ? tb->data_port() : nullptr;
        for (auto* p : own_ports(*m)) {
            const channel c = channel_of(*p);
            if (c == nullptr) {
                error(std::string(p->name()) + " is not bound yet: build the timing graph after elaboration "
                      "(end_of_elaboration or later)");
                continue;
            }
            if (p == clk) n.clock = c;
            else if (p == d) n.data = c;
            else (is_output(*p) ? n.outs : n.ins).push_back(c);
        }
        const std::size_t idx = nodes_.size();
        index_[m] = idx;
        if (tb == nullptr || !tb->is_register())
            for (channel c : n.ins) readers_[c].push_back(idx);
        nodes_.push_back(std::move(n));
    }

    const node& node_of(const sc_core::sc_object& o) const {
        auto it = index_.find(&o);
        if (it == index_.end()) {
            error(std::string(o.name()) + " is not a block below " + top_->name());
            static const node none{nullptr, nullptr, {nullptr}, {nullptr}, nullptr, nullptr};
            return none;
        }
        return nodes_[it->second];
    }

    std::string relative_name(const std::string& full) const {
        return full.rfind(prefix_, 0) == 0 ? full.substr(prefix_.size()) : full;
    }
    std::string channel_name(channel c) const {
        // Channels are sc_objects (sc_signal...): find the one at this address by a port bound to it.
        for (const auto& n : nodes_)
            for (auto* p : own_ports(*n.obj))
                if (channel_of(*p) == c)
                    if (auto* o = dynamic_cast<const sc_core::sc_object*>(p->get_interface()))
                        return relative_name(o->name());
        return "?";
    }

    timing_path longest(const std::vector<source>& from, const std::vector<channel>& to) const {
        const std::set<channel> sinks(to.begin(), to.end());
        std::map<channel, best> memo;
        std::set<channel> on_stack;
        std::set<std::size_t> reported;
        timing_path out;
        const source* start = nullptr;
        best start_best;
        for (const auto& s : from) {
            const best b = solve(s.c, sinks, memo, on_stack, reported);
            if (b.reach && (!out.found || s.at + b.rest > out.delay)) {
                out.found = true;
                out.delay = s.at + b.rest;
                start = &s;
                start_best = b;
            }
        }
        if (!out.found) return out;
        out.blocks.push_back(start->name);
        for (best b = start_best; b.via != npos; b = memo.at(b.next))
            out.blocks.push_back(relative(*nodes_[b.via].obj));
        return out;
    }

    best solve(channel c, const std::set<channel>& sinks, std::map<channel, best>& memo,
               std::set<channel>& on_stack, std::set<std::size_t>& reported) const {
        if (auto it = memo.find(c); it != memo.end()) return it->second;
        best b;
        if (sinks.count(c)) b.reach = true;
        if (!on_stack.insert(c).second) {
            error("combinational loop through " + channel_name(c));
            return b;
        }
        auto rd = readers_.find(c);
        if (rd != readers_.end())
            for (std::size_t i : rd->second) {
                const node& n = nodes_[i];
                if (n.tb == nullptr) {
                    if (n.outs.empty()) continue;  // a monitor: reads only
                    if (reported.insert(i).second)
                        error(std::string(n.obj->name()) + " reads " + channel_name(c) +
                              " on a timing path and drives nets, but has no timed_block interface "
                              "(core/timed_block.h): its delay is unknown, counted as 0");
                }
                const sc_core::sc_time d = n.tb ? n.tb->delay() : sc_core::SC_ZERO_TIME;
                for (channel o : n.outs) {
                    const best nb = solve(o, sinks, memo, on_stack, reported);
                    if (nb.reach && (!b.reach || d + nb.rest > b.rest)) b = {true, d + nb.rest, i, o};
                }
            }
        on_stack.erase(c);
        memo[c] = b;
        return b;
    }

    void error(const std::string& what) const {
        SC_REPORT_ERROR(msg::config, (std::string("timing_graph(") + top_->name() + "): " + what).c_str());
    }

    const sc_core::sc_object* top_;
    std::string prefix_;
    std::vector<channel> inputs_, outputs_;
    std::vector<node> nodes_;
    std::map<const sc_core::sc_object*, std::size_t> index_;
    std::map<channel, std::vector<std::size_t>> readers_;
};

}  // namespace shading
