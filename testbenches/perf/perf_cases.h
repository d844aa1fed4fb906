// The rows perf_models registers (perf_models.cpp), shared with perf_specular.cpp, the specular
// devices' rows (kept in their own translation unit: each file compiles in parallel).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "perf_harness.h"
#include "testbenches/tlm/tlm_initiator.h"
#include "tlm_utils/tlm_quantumkeeper.h"

namespace shading::perf {

struct sc_case {
    std::string name, golden, unit;
    std::function<std::unique_ptr<harness>()> make;  // a harness advanced in batches
    bool traced = false;
    // Or a run that cannot be cut into batches (the pipeline's frame): returns items, seconds, mismatches.
    std::function<void(double& items, double& seconds, double& mismatches)> once;
    // false: mismatches are reported (counter, table) but do not fail the run (the RTL twin, whose
    // correctness is its own suite's business, testbenches/rtl).
    bool strict = true;
};
std::vector<sc_case>& sc_cases();

// Adds a SystemC row: `make` builds its harness in the child process.
sc_case& add_sc(const std::string& name, const std::string& golden, const std::string& unit,
                std::function<std::unique_ptr<harness>()> make, bool traced = false);

// Wraps a module-type harness (sc_module + harness) built by `new`.
template <class H, typename... Args>
std::function<std::unique_ptr<harness>()> module(Args... args) {
    return [=] { return std::unique_ptr<harness>(new H("top", args...)); };
}

// Loosely-timed practice (TLM-2.0 temporal decoupling): the initiator passes its local time into
// each access, keeps the annotated delay it gets back (tlm_utils::tlm_quantumkeeper) and waits only
// when the local time reaches the global quantum, 1 ms (about 49 lines of 1024 pixels
// at 20 ns a pixel, 6 bursts of the line wrapper); a batch
// is one quantum. Pin-accurate accesses wait inside b_transport and annotate nothing.
inline sc_core::sc_time lt_quantum() { return sc_core::sc_time(1, sc_core::SC_MS); }

// One access with the quantum keeper's local time as its incoming delay; keeps the annotated delay.
inline void lt_access(tb::tlm_initiator& i, tlm_utils::tlm_quantumkeeper& qk, tlm::tlm_command cmd, uint64_t addr,
                      unsigned char* data, unsigned len) {
    i.delay_in = qk.get_local_time();
    i.access(cmd, addr, data, len);
    qk.set(i.last_delay);
    if (qk.need_sync()) qk.sync();
}

// A TLM wrapper shading whole lines from an initiator thread (lt_access: simulated time advances in
// both modes, so sc_start(batch) returns).
class tlm_harness : public sc_core::sc_module, public harness {
public:
    tb::tlm_initiator init;
    explicit tlm_harness(const sc_core::sc_module_name& n, std::function<void(tlm_harness&)> script,
                         sc_core::sc_time batch, sc_core::sc_time period)
        : sc_module(n), init("init", [this, script](tb::tlm_initiator&) { script(*this); }), batch_(batch),
          period_(period) {}
    sc_core::sc_object& root() override { return *this; }
    uint64_t items() const override { return items_; }
    uint64_t mismatches() const override { return mismatches_; }
    sc_core::sc_time batch() const override { return batch_; }
    sc_core::sc_time period() const override { return period_; }
    uint64_t items_ = 0, mismatches_ = 0;

private:
    sc_core::sc_time batch_, period_;
};

// perf_specular.cpp: the specular devices (block level, fast, the Verilator twin) and the UA 60553
// TLM wrapper in one timing mode (loosely timed, or pin-accurate when `pin`).
void register_specular_cases();
// perf_floor.cpp: the harnesses with nothing inside (the floors under the speed targets).
void register_floor_cases();
void add_specular_tlm(const std::string& name, bool pin);

}  // namespace shading::perf
