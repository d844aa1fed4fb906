// The VCD writer on the whole shading pipeline (testbenches/pipeline/pipeline_sim.h) against
// SystemC's own writer in the same run: the same file byte for byte from $timescale on. Apart from
// test_vcd_writer.cpp so that suite needs the modules only (a SystemC 3.0 check builds it alone).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "testbenches/common/report_log.h"
#include "testbenches/pipeline/pipeline_sim.h"
#include "testbenches/trace/vcd_compare.h"

using namespace shading;
using namespace shading::tb;

TEST(VcdWriter, SameFileAsSystemCOnThePipeline) {
    // simulate_frame opens its vcd_file itself: SHADING_TRACE_WRITER=both makes it write both files.
    ASSERT_EQ(setenv("SHADING_TRACE_WRITER", "both", 1), 0);
    const std::string base = temp_base("vcd_writer_pipeline");
    pipeline::plan p;
    p.width = 8;
    p.height = 1;
    pipeline::interval_job j;
    j.m = 2;
    j.len = 4;
    const uint32_t nh[4] = {30000, 32600, 32200, 29000}, nl[4] = {20000, 22000, 24000, 26000};
    for (int i = 0; i < 4; ++i) j.s[i] = {nh[i], nl[i]};
    p.jobs.push_back(j);
    j.x0 = 4;
    j.deg2 = true;
    p.jobs.push_back(j);
    p.pixels = 8;
    pipeline::frame_constants k;
    k.n = 32;
    k.ksi = {200, 180, 90};
    k.kdi = {150 * 256, 100 * 256, 60 * 256};  // Q8.8
    k.ambient = {10 * 256, 8 * 256 + 77, 12 * 256 + 3};
    pipeline::plan_config c;
    c.eval = pipeline::evaluator::horner;
    c.m = 2;
    pipeline::sim_options o;
    o.vcd_path = base;
    const auto r = pipeline::simulate_frame(p, k, scene::device_config{}, c, o);
    EXPECT_EQ(r.mismatches, 0u);
    expect_same_files(base, 100, 60);
}

