// Helpers shared by the golden pipeline's tests (test_pipeline_golden.cpp, test_pipeline_frame.cpp):
// frame constants with the diffuse term alone, a pixel's geometry from three vectors, every device.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "golden_pipeline/pipeline.h"
#include "scene/scene.h"

namespace golden_test {

using namespace shading;
using namespace shading::pipeline;


// Frame constants with no specular term (k_s*I = 0, so the device adds 0) and k_d*I = 128.0
// (Q8.8 0x8000): 0x8000 x cos_nl >> 15 = cos_nl, so a sample's code is ambient + cos_nl, chosen
// freely up to 0x8000. kdi in whole levels (times 256 here).
inline frame_constants diffuse_only(uint64_t kdi = 128, uint64_t ambient = 0) {
    kdi *= 256;
    frame_constants k;
    k.n = 32;
    k.ksi = {0, 0, 0};
    k.kdi = {kdi, kdi, kdi};
    k.ambient = {ambient, ambient, ambient};
    return k;
}

inline sample_geometry diffuse_sample(uint32_t cos_nl) { return {0, cos_nl}; }

inline scene::cvec3 vec(double x, double y, double z) { return {scene::cnum(x, nullptr), scene::cnum(y, nullptr), scene::cnum(z, nullptr)}; }

inline scene::pixel_geometry geometry(scene::cvec3 n, scene::cvec3 l, scene::cvec3 h) {
    scene::pixel_geometry g;
    g.n = n;
    g.v = vec(0.0, 0.0, 1.0);
    g.l = {l};
    g.h = {h};
    return g;
}

const scene::device_config patent{};

inline std::vector<scene::device_config> all_devices() {
    std::vector<scene::device_config> d;
    for (const auto& name : scene::device_names()) d.push_back({scene::parse_device(name), overflow_mode::saturate});
    return d;
}

// Sample codes at the points of a set for I(t) = codes, via diffuse_only (code = cos_nl).
inline interval_job job_of(const std::array<uint32_t, 4>& codes, unsigned m, bool deg2, unsigned len = 0) {
    interval_job job;
    job.m = m;
    job.len = len ? len : 1u << m;
    job.deg2 = deg2;
    for (int i = 0; i < 4; ++i) job.s[i] = diffuse_sample(codes[i]);
    return job;
}

}  // namespace golden_test
