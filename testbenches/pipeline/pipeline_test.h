// What the pipeline's GoogleTest suites share (test_pipeline_sim, test_pipeline_fast): the written
// order a plan asks for, the frame against golden_frame, and the small renders' set-up (a built-in
// scene rasterised, its frame constants, a device and an evaluator).
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "golden_pipeline/pipeline.h"
#include "pipeline_sim.h"

namespace shading::pipeline {

// Every written pixel in the order the jobs list them (line by line, left to right).
inline std::vector<std::size_t> job_order(const plan& p) {
    std::vector<std::size_t> o;
    for (const auto& j : p.jobs)
        for (unsigned i = 0; i < j.len; ++i) o.push_back(std::size_t(j.y) * p.width + j.x0 + i);
    return o;
}

// The frame's pixels against golden_frame, bit for bit (independent of the bench's own checker).
inline void expect_golden_frame(const sim_result& r, const plan& p, const frame_constants& k,
                                const scene::device_config& dev, const plan_config& c) {
    const frame g = golden_frame(p, k, dev, c);
    ASSERT_EQ(r.f.px.size(), g.px.size());
    std::size_t diff = 0;
    for (std::size_t i = 0; i < g.px.size(); ++i)
        if (r.f.px[i] != g.px[i] || r.f.covered[i] != g.covered[i]) ++diff;
    EXPECT_EQ(diff, 0u) << "pixels differing from golden_frame";
}

// A small render: a built-in scene at size x size through one device and evaluator. adaptive:
// adaptive length and degree (test_pipeline_fast), left to the test otherwise.
struct render_case {
    const char* scene;
    unsigned size;
    scene::specular_device device;
    evaluator e;
    bool adaptive = false;
};
inline void PrintTo(const render_case& c, std::ostream* os) {
    *os << c.scene << c.size << " " << scene::device_name(c.device) << " " << evaluator_name(c.e);
}
// The test's name in INSTANTIATE_TEST_SUITE_P: scene, size, device, evaluator.
inline std::string render_case_name(const ::testing::TestParamInfo<render_case>& i) {
    return std::string(i.param.scene) + std::to_string(i.param.size) + "_" + scene::device_name(i.param.device) + "_" +
           evaluator_name(i.param.e);
}

// Its scene rasterised, frame constants, device and the plan's evaluator (the rest of c is the
// test's). Built in place: the raster points at the world.
struct render_setup {
    const scene::world w;
    const scene::rasterised r;
    const frame_constants k;
    scene::device_config dev;
    plan_config c;
    explicit render_setup(const render_case& rc)
        : w(scene::builtin_scene(rc.scene, SHADING_SOURCE_DIR, rc.size, rc.size)), r(scene::rasterise(w)),
          k(frame_constants_of(w)) {
        dev.device = rc.device;
        c.eval = rc.e;
    }
    render_setup(const render_setup&) = delete;
    render_setup& operator=(const render_setup&) = delete;
};

}  // namespace shading::pipeline
