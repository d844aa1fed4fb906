// Fuzz target: an OBJ file as any modeller (or a broken one) writes it, through the project's loader
// (src/scene/mesh.cpp: Debian's tinyobjloader under load_obj), the scene framing a user's OBJ
// (obj_scene), both normal weightings, and the rasteriser at 24 x 24 pixels with the geometry of
// every covered pixel. Documented outcomes only: a mesh, or obj_error / scene_error; any other
// exception, a non-finite or non-unit normal, an index past the positions, or a sanitizer report
// is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <unistd.h>

#include "fuzz_check.h"
#include "scene/mesh.h"
#include "scene/raster.h"
#include "scene/world.h"

using namespace shading::scene;

namespace {
void check_mesh(const mesh& m) {
    FUZZ_CHECK(!m.triangles.empty(), "a mesh without triangles was returned");
    FUZZ_CHECK(m.normals.size() == m.positions.size(), "%zu normals for %zu positions", m.normals.size(),
               m.positions.size());
    for (const auto& t : m.triangles)
        for (uint32_t i : t) FUZZ_CHECK(i < m.positions.size(), "triangle index %u of %zu", i, m.positions.size());
    for (const auto& n : m.normals) {
        FUZZ_CHECK(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z), "a normal is not finite");
        FUZZ_CHECK(std::abs(glm::length(n) - 1.0) < 1e-9, "a normal of length %g", glm::length(n));
    }
}

const std::string& path() {
    static const std::string p = "/tmp/shading_fuzz_obj_" + std::to_string(getpid()) + ".obj";
    return p;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    {
        std::FILE* f = std::fopen(path().c_str(), "wb");
        FUZZ_CHECK(f != nullptr, "cannot write %s", path().c_str());
        if (size > 0) std::fwrite(data, 1, size, f);
        std::fclose(f);
    }
    try {
        world s = obj_scene(path(), 24, 24);
        mesh& m = s.objects.front().geometry;
        check_mesh(m);
        mesh area = m;
        compute_normals(area, normal_weighting::area);
        check_mesh(area);
        const rasterised r = rasterise(s);
        for (unsigned y = 0; y < r.height; ++y)
            for (unsigned x = 0; x < r.width; ++x) {
                if (!r.covered(x, y)) continue;
                const auto t = static_cast<std::size_t>(r.tri[r.index(x, y)]);
                FUZZ_CHECK(t < r.setups.size(), "pixel (%u, %u) names setup %zu of %zu", x, y, t, r.setups.size());
                (void)geometry_at(r, x, y, nullptr);
            }
        for (unsigned y = 0; y < r.height; ++y) {
            (void)line_spans(r, y);
            (void)line_discontinuities(r, y, 0.02);
        }
    } catch (const obj_error&) {
    } catch (const scene_error&) {
    }
    std::remove(path().c_str());
    return 0;
}
