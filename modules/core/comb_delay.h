// Inertial propagation delay for combinational blocks: every input change recomputes the output,
// which appears `delay` later; a newer value cancels one still in flight, as a gate swallows
// pulses shorter than its delay. Lets a VCD show the network settling after each latch.
#pragma once

#ifndef SC_INCLUDE_DYNAMIC_PROCESSES
#define SC_INCLUDE_DYNAMIC_PROCESSES  // sc_spawn
#endif
#include <systemc>

namespace shading {

template <typename T>
class inertial_driver {
public:
    // Must be constructed inside a module's constructor: it spawns that module's settle process.
    // A zero delay spawns none: drive() writes the output itself, a delta cycle after its input
    // changed, instead of two (a notification, a settle process and a delta per block
    // that no waveform shows). The block's one process is then the output's only writer.
    inertial_driver(sc_core::sc_out<T>& out, const sc_core::sc_time& delay) : out_(out), delay_(delay) {
        if (delay_ == sc_core::SC_ZERO_TIME) return;
        sc_core::sc_spawn_options opt;
        opt.spawn_method();
        opt.set_sensitivity(&settle_);
        opt.dont_initialize();
        sc_core::sc_spawn(
            [this] {
                out_.write(pending_);
                written_ = pending_;
                in_flight_ = false;
            },
            "settle", &opt);
    }

    void drive(const T& v) {
        // The output already carries v: nothing to schedule, and a change still in flight is a pulse
        // shorter than the delay, swallowed. (Saves the simulator a timed event per unchanged
        // recomputation, e.g. a clocked register latching the value it holds; the first drive always
        // goes out, so an output starts as the block computes it.)
        if (!first_ && v == written_) {
            if (in_flight_) settle_.cancel();
            in_flight_ = false;
            return;
        }
        first_ = false;
        if (delay_ == sc_core::SC_ZERO_TIME) {
            written_ = v;
            out_.write(v);
            return;
        }
        pending_ = v;
        in_flight_ = true;
        settle_.cancel();
        settle_.notify(delay_);
    }

    const sc_core::sc_time& delay() const { return delay_; }

private:
    sc_core::sc_out<T>& out_;
    sc_core::sc_time delay_;
    sc_core::sc_event settle_;
    T pending_{}, written_{};
    bool first_ = true, in_flight_ = false;
};

// Default propagation delays (documented in the README): a 16x16 array multiplier, a 32-bit
// carry-lookahead adder, one inverter, a register's clock-to-output. Every instance can override.
namespace delay_default {
inline const sc_core::sc_time reg_clk_to_q{200, sc_core::SC_PS};
inline const sc_core::sc_time inverter{100, sc_core::SC_PS};
inline const sc_core::sc_time adder{1000, sc_core::SC_PS};
inline const sc_core::sc_time multiplier{3000, sc_core::SC_PS};
inline const sc_core::sc_time mux{300, sc_core::SC_PS};
}  // namespace delay_default

}  // namespace shading
