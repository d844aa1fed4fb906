// The SystemC kernel's own cost per event on this machine: what one process wakeup, one
// timed or delta notification, one signal write with a reader costs, in CPU nanoseconds, with
// nothing computed. A model's speed is bounded by how many of these it needs per pixel.
//
//   kernel_cost [N]     N activations per case (default 2000000); prints ns per activation
// Exit 2 on bad usage (N not a whole number in 1..10^10, an unknown case), as every program here.
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <systemc>

namespace {

using sc_core::SC_NS;
using sc_core::sc_time;

enum class cost_case { timed_method, delta_method, thread_wait, signal_bool, signal_uint, event_method };
const char* label(cost_case k) {
    switch (k) {
        case cost_case::timed_method: return "method, next_trigger(1 ns) (timed wakeup)";
        case cost_case::delta_method: return "method, next_trigger(SC_ZERO_TIME) (delta wakeup)";
        case cost_case::thread_wait: return "thread, wait(1 ns) (coroutine switch + timed wakeup)";
        case cost_case::signal_bool: return "method writes sc_signal<bool> each ns, 1 reader method";
        case cost_case::signal_uint: return "method writes sc_signal<sc_uint<16>> each ns, 1 reader method";
        case cost_case::event_method: return "method notifies an event 1 ns ahead, 1 waiting method";
    }
    return "";
}

struct bench : sc_core::sc_module {
    sc_core::sc_signal<bool> b{"b"};
    sc_core::sc_signal<sc_dt::sc_uint<16>> u{"u"};
    sc_core::sc_event ev{"ev"};
    cost_case what;
    long n, count = 0, seen = 0;

    SC_HAS_PROCESS(bench);
    bench(const sc_core::sc_module_name& name, cost_case k_, long n_) : sc_module(name), what(k_), n(n_) {
        if (what == cost_case::thread_wait) {
            SC_THREAD(thread);
        } else {
            SC_METHOD(driver);
        }
        if (what == cost_case::signal_bool) {
            SC_METHOD(reader);
            sensitive << b;
            dont_initialize();
        } else if (what == cost_case::signal_uint) {
            SC_METHOD(reader);
            sensitive << u;
            dont_initialize();
        } else if (what == cost_case::event_method) {
            SC_METHOD(reader);
            sensitive << ev;
            dont_initialize();
        }
    }
    void driver() {
        if (++count > n) return;
        switch (what) {
            case cost_case::delta_method: next_trigger(sc_core::SC_ZERO_TIME); return;
            case cost_case::signal_bool: b.write(!b.read()); break;
            case cost_case::signal_uint: u.write(u.read() + 1); break;
            case cost_case::event_method: ev.notify(1, SC_NS); break;
            default: break;
        }
        next_trigger(1, SC_NS);
    }
    void thread() {
        while (++count <= n) wait(1, SC_NS);
    }
    void reader() { ++seen; }
};

}  // namespace

// A whole number in [lo, hi] (decimal digits only), or -1.
long parse_count(const char* s, long lo, long hi) {
    char* end = nullptr;
    if (*s < '0' || *s > '9') return -1;
    const long v = std::strtol(s, &end, 10);
    return *end == '\0' && v >= lo && v <= hi ? v : -1;
}

int sc_main(int argc, char* argv[]) {
    const int last_case = static_cast<int>(cost_case::event_method);
    const long n = argc > 1 ? parse_count(argv[1], 1, 10'000'000'000L) : 2000000;
    const long kc = argc > 2 ? parse_count(argv[2], 0, last_case) : 0;
    if (argc > 3 || n < 0 || kc < 0) {
        std::fprintf(stderr, "usage: %s [N (activations per case, 1..10^10) [case 0..%d]]\n", argv[0], last_case);
        return 2;
    }
    const cost_case k = static_cast<cost_case>(kc);
    if (argc <= 2) {  // every case, each in its own process (one elaboration per process)
        for (int i = 0; i <= static_cast<int>(cost_case::event_method); ++i) {
            const std::string cmd = std::string(argv[0]) + " " + std::to_string(n) + " " + std::to_string(i);
            if (std::system(cmd.c_str()) != 0) return 1;
        }
        return 0;
    }
    sc_core::sc_report_handler::set_actions("/IEEE_Std_1666/deprecated", sc_core::SC_DO_NOTHING);
    bench b("b", k, n);
    const std::clock_t t0 = std::clock();
    sc_core::sc_start();
    const double cpu = static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
    std::printf("%-64s %7.1f ns per activation (%ld activations, %ld reader wakeups, %.2f s CPU)\n", label(k),
                1e9 * cpu / static_cast<double>(n), n, b.seen, cpu);
    return 0;
}
