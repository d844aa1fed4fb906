// Runs a simulation to completion with a watchdog: a bench that never finishes its stimulus
// within `limit` of simulated time is a failure, not a hang.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <systemc>

#include "core/trace.h"

namespace shading::tb {

// "Suite.Test" of the running test, '/' of parameterised names made '_' (a file name).
inline std::string current_test_name() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    if (info == nullptr) return "no_test";
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    for (char& ch : name)
        if (ch == '/') ch = '_';
    return name;
}

// With SHADING_TRACE=<dir>, the test's first run writes <dir>/<Suite.Test>.vcd of the whole bench
// (one name per test: ctest runs tests in parallel; a trace file can only open before sc_start).
template <typename Bench>
bool run_to_completion(Bench& bench, const sc_core::sc_time& limit) {
    std::unique_ptr<vcd_file> vcd;
    if (sc_core::sc_get_status() == sc_core::SC_ELABORATION) {
        vcd = vcd_from_env(current_test_name());
        if (vcd) vcd->trace(bench);
    }
    sc_core::sc_start(limit);
    return bench.finished();
}

}  // namespace shading::tb
