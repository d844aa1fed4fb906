// A small TLM-2.0 initiator for the wrapper tests and the benchmark: a simple_initiator_socket and
// one SC_THREAD that runs a script (a function given the initiator), then stops the simulation
// (no script: no thread, the socket is driven from another initiator's script).
// Its helpers issue single-word and block accesses with b_transport and keep the annotated delay
// of the last access, so a test can compare it with the simulated time that passed.
// Below it, what the wrappers' tests and benchmarks share, as templates on the wrapper W (a module
// constructed from a name and a tlm_timing, with a target `socket`): an initiator bound to one W,
// an LT and a pin-accurate W side by side, and the benchmarks' timed burst loop and report.
#pragma once

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <systemc>
#include <vector>

#include "tlm/tlm_target_base.h"  // tlm_timing

namespace shading::tb {

class tlm_initiator : public sc_core::sc_module {
public:
    tlm_utils::simple_initiator_socket<tlm_initiator> socket{"socket"};
    using script = std::function<void(tlm_initiator&)>;

    SC_HAS_PROCESS(tlm_initiator);
    tlm_initiator(const sc_core::sc_module_name& name, script s) : sc_module(name), script_(std::move(s)) {
        if (script_) SC_THREAD(run);  // without a script: a socket another initiator's thread drives
    }

    bool finished() const { return finished_; }

    // The last access: its annotated delay (b_transport's delay after the call, starting from
    // `delay_in`) and the simulated time the call took.
    sc_core::sc_time delay_in = sc_core::SC_ZERO_TIME;
    sc_core::sc_time last_delay, last_elapsed;

    tlm::tlm_response_status access(tlm::tlm_command cmd, uint64_t addr, unsigned char* data, unsigned len,
                                    unsigned char* byte_enables = nullptr, unsigned streaming_width = 0) {
        tlm::tlm_generic_payload p;
        p.set_command(cmd);
        p.set_address(addr);
        p.set_data_ptr(data);
        p.set_data_length(len);
        p.set_streaming_width(streaming_width ? streaming_width : len);
        p.set_byte_enable_ptr(byte_enables);
        p.set_byte_enable_length(byte_enables ? len : 0);
        p.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        sc_core::sc_time d = delay_in;
        const sc_core::sc_time t0 = sc_core::sc_time_stamp();
        socket->b_transport(p, d);
        last_delay = d;
        last_elapsed = sc_core::sc_time_stamp() - t0;
        return p.get_response_status();
    }
    tlm::tlm_response_status write32(uint64_t addr, uint32_t v) {
        unsigned char b[4];
        std::memcpy(b, &v, 4);
        return access(tlm::TLM_WRITE_COMMAND, addr, b, 4);
    }
    tlm::tlm_response_status read32(uint64_t addr, uint32_t& v) {
        unsigned char b[4] = {};
        const auto s = access(tlm::TLM_READ_COMMAND, addr, b, 4);
        std::memcpy(&v, b, 4);
        return s;
    }
    uint32_t read32(uint64_t addr) {
        uint32_t v = 0xDEADBEEF;
        read32(addr, v);
        return v;
    }
    // Debug transport: bytes transferred.
    unsigned debug(tlm::tlm_command cmd, uint64_t addr, unsigned char* data, unsigned len) {
        tlm::tlm_generic_payload p;
        p.set_command(cmd);
        p.set_address(addr);
        p.set_data_ptr(data);
        p.set_data_length(len);
        return socket->transport_dbg(p);
    }
    std::vector<unsigned char> debug_read(uint64_t addr, unsigned len) {
        std::vector<unsigned char> v(len);
        v.resize(debug(tlm::TLM_READ_COMMAND, addr, v.data(), len));
        return v;
    }

private:
    void run() {
        script_(*this);
        finished_ = true;
        sc_core::sc_stop();
    }
    script script_;
    bool finished_ = false;
};

// One initiator bound to one wrapper.
template <class W>
struct tlm_bench : sc_core::sc_module {
    W dut;
    tlm_initiator init;
    tlm_bench(const sc_core::sc_module_name& name, tlm_timing t, tlm_initiator::script s)
        : sc_module(name), dut("dut", t), init("init", std::move(s)) {
        init.socket.bind(dut.socket);
    }
    bool finished() const { return init.finished(); }
};

// A loosely-timed and a pin-accurate wrapper, each with its initiator; one thread (init_pin's) runs
// body(init_lt, init_pin), so both are driven from the same script in simulated time. body may be
// given after construction, before the simulation starts.
template <class W>
struct tlm_pair_bench : sc_core::sc_module {
    using pair_script = std::function<void(tlm_initiator&, tlm_initiator&)>;
    W lt, pin;
    tlm_initiator init_lt, init_pin;
    pair_script body;
    bool done = false;
    tlm_pair_bench(const sc_core::sc_module_name& name, pair_script b = nullptr)
        : sc_module(name),
          lt("lt", tlm_timing::loosely_timed),
          pin("pin", tlm_timing::pin_accurate),
          init_lt("init_lt", nullptr),
          init_pin("init_pin", [this](tlm_initiator& p) { body(init_lt, p); done = true; }),
          body(std::move(b)) {
        init_lt.socket.bind(lt.socket);
        init_pin.socket.bind(pin.socket);
    }
    bool finished() const { return done; }
};

// The benchmarks: what one timing mode measured.
struct tlm_figures {
    std::size_t pixels = 0, mismatches = 0;
    double seconds = 0, cpu_seconds = 0;  // wall clock; this process's CPU time (the machine may be shared)
    sc_core::sc_time model_time;          // simulated time passed plus the annotated delay
};

// A block access's payload, reused for every burst.
inline void set_block(tlm::tlm_generic_payload& p, tlm::tlm_command cmd, uint64_t addr, unsigned char* data,
                      std::size_t len) {
    p.set_command(cmd);
    p.set_address(addr);
    p.set_data_ptr(data);
    p.set_data_length(static_cast<unsigned>(len));
    p.set_streaming_width(static_cast<unsigned>(len));
}

// `bursts` times: fill(b) writes burst b's inputs into w's buffer, w then r go through b_transport
// with one running delay, check(b) returns the mismatches in r's buffer. An error response counts
// as a mismatch and ends the run. The check is inside the timed loop (the benchmarks keep it cheap).
template <class Fill, class Check>
tlm_figures time_bursts(tlm_initiator& i, std::size_t bursts, std::size_t pixels_per_burst,
                        tlm::tlm_generic_payload& w, tlm::tlm_generic_payload& r, Fill fill, Check check) {
    tlm_figures f;
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
    const sc_core::sc_time t0 = sc_core::sc_time_stamp();
    const auto c0 = std::chrono::steady_clock::now();
    const std::clock_t cpu0 = std::clock();
    for (std::size_t b = 0; b < bursts; ++b) {
        fill(b);
        w.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        r.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        i.socket->b_transport(w, delay);
        i.socket->b_transport(r, delay);
        if (w.get_response_status() != tlm::TLM_OK_RESPONSE || r.get_response_status() != tlm::TLM_OK_RESPONSE) {
            ++f.mismatches;
            break;
        }
        f.mismatches += check(b);
    }
    f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count();
    f.cpu_seconds = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
    f.model_time = sc_core::sc_time_stamp() - t0 + delay;
    f.pixels = bursts * pixels_per_burst;
    return f;
}

inline void print_figures(const char* what, const tlm_figures& f) {
    std::printf("%-15s %10zu px  %8.3f s  %11.4g px/s  (CPU %.3f s, %.4g px/s)  model time %s (%.2f ns/px)  "
                "mismatches %zu\n",
                what, f.pixels, f.seconds, f.pixels / f.seconds, f.cpu_seconds, f.pixels / f.cpu_seconds,
                f.model_time.to_string().c_str(),
                f.model_time.to_seconds() * 1e9 / static_cast<double>(f.pixels), f.mismatches);
}

// Elaborates an LT and a pin-accurate W side by side, then run(initiator, pixels, wrapper) ->
// tlm_figures through the loosely-timed one (lt_px pixels) and the pin-accurate one (pin_px), in
// that order; prints `title`, both figures and their ratio. Returns 0 only if both shaded pixels
// and nothing mismatched, else 1.
template <class W, class Run>
int tlm_bench_run(std::size_t lt_px, std::size_t pin_px, const std::string& title, Run run) {
    tlm_figures f_lt, f_pin;
    tlm_pair_bench<W> t("top");
    t.body = [&](tlm_initiator& lt, tlm_initiator& pin) {
        f_lt = run(lt, lt_px, t.lt);
        f_pin = run(pin, pin_px, t.pin);
    };
    sc_core::sc_start();
    std::printf("%s\n", title.c_str());
    print_figures("loosely timed", f_lt);
    print_figures("pin-accurate", f_pin);
    std::printf("loosely timed / pin-accurate: %.0fx\n", (f_lt.pixels / f_lt.seconds) / (f_pin.pixels / f_pin.seconds));
    return f_lt.mismatches + f_pin.mismatches == 0 && f_lt.pixels > 0 && f_pin.pixels > 0 ? 0 : 1;
}

}  // namespace shading::tb
