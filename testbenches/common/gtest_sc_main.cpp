// main() of every GoogleTest suite: gtest parses its flags, then SystemC elaborates and calls
// sc_main, which runs the tests. Any SystemC warning/error a test did not announce fails it.
#include <gtest/gtest.h>

#include <systemc>

#include "testbenches/common/report_log.h"

namespace {
void fail_test(const sc_core::sc_report& r) {
    ADD_FAILURE() << "unexpected SystemC report " << r.get_msg_type() << ": " << r.get_msg();
}
}  // namespace

int sc_main(int, char*[]) { return RUN_ALL_TESTS(); }

int main(int argc, char* argv[]) {
    ::testing::InitGoogleTest(&argc, argv);
    shading::tb::report_log::install(&fail_test);
    return sc_core::sc_elab_and_sim(argc, argv);
}
