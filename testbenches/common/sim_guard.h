// Runs a simulation to completion with a watchdog: a bench that never finishes its stimulus
// within `limit` of simulated time is a failure, not a hang.
#pragma once

#include <systemc>

namespace shading::tb {

template <typename Bench>
bool run_to_completion(Bench& bench, const sc_core::sc_time& limit) {
    sc_core::sc_start(limit);
    return bench.finished();
}

}  // namespace shading::tb
