// Procedural models no program has seen, for the race on an OBJ file made at test time: a "blob" (a
// sphere displaced along its radius by a few products of sines, so its surface folds in many small
// triangles) and a "cluster" (a figure of six such blobs of different sizes at different depths,
// overlapping). Normals are exact: the gradient of the implicit surface |p| - R(p / |p|) = 0. Shared
// by make_test_obj (which writes the file) and the race's tests (which read it back).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh.h"

namespace shading::tb::test_obj {

// The radius of a blob along the unit direction u, R(u) = 1 + f(u), and f's gradient in space at u.
// The terms are smooth functions of x, y, z (not of the angles), so the surface is smooth at the
// poles too; |f| <= 0.14 + 0.08 + 0.05 keeps R >= 0.73. `phase` makes the parts of a cluster differ.
struct blob_radius {
    double phase = 0.0;
    double value(const glm::dvec3& u) const {
        return 1.0 + 0.14 * std::sin(5.0 * u.x + phase) * std::sin(4.0 * u.y) + 0.08 * std::cos(7.0 * u.z + 1.0 + phase) +
               0.05 * std::sin(9.0 * u.y + 3.0 * u.x - phase);
    }
    glm::dvec3 gradient(const glm::dvec3& u) const {
        const double a = 5.0 * u.x + phase, b = 4.0 * u.y, c = 7.0 * u.z + 1.0 + phase, d = 9.0 * u.y + 3.0 * u.x - phase;
        return {0.14 * 5.0 * std::cos(a) * std::sin(b) + 0.05 * 3.0 * std::cos(d),
                0.14 * 4.0 * std::sin(a) * std::cos(b) + 0.05 * 9.0 * std::cos(d), -0.08 * 7.0 * std::sin(c)};
    }
};

// The outward unit normal at the blob's point R(u) u: the gradient of |p| - R(p / |p|) there,
// u - (I - u u^T) grad R(u) / R(u) (the radial part of grad R does not move p / |p|).
inline glm::dvec3 blob_normal(const blob_radius& f, const glm::dvec3& u) {
    const glm::dvec3 g = f.gradient(u);
    const glm::dvec3 tangential = g - glm::dot(g, u) * u;
    return glm::normalize(u - tangential / f.value(u));
}

// The direction of latitude ring i (1 .. rings - 1; 0 and rings are the poles) and longitude j of
// `around`, y up.
inline glm::dvec3 direction(unsigned i, unsigned rings, unsigned j, unsigned around) {
    const double pi = 3.14159265358979323846;
    const double theta = pi * i / rings, phi = 2.0 * pi * j / around;
    return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

// One blob of `segments` longitudes and segments / 2 latitude bands (segments even, >= 4), scaled
// by `radius` about `centre`, appended to m: 2 + (segments / 2 - 1) segments vertices and
// segments (segments - 2) triangles (a fan at each pole, two a quad between), counter-clockwise
// seen from outside.
inline void add_blob(scene::mesh& m, unsigned segments, const glm::dvec3& centre, double radius, double phase) {
    const blob_radius f{phase};
    const unsigned rings = segments / 2, base = static_cast<unsigned>(m.positions.size());
    auto add = [&](const glm::dvec3& u) {
        m.positions.push_back(centre + radius * f.value(u) * u);
        m.normals.push_back(blob_normal(f, u));
    };
    add({0.0, 1.0, 0.0});
    for (unsigned i = 1; i < rings; ++i)
        for (unsigned j = 0; j < segments; ++j) add(direction(i, rings, j, segments));
    add({0.0, -1.0, 0.0});
    const unsigned south = base + 1 + (rings - 1) * segments;
    auto ring = [&](unsigned i, unsigned j) { return base + 1 + (i - 1) * segments + j % segments; };
    for (unsigned j = 0; j < segments; ++j) {
        m.triangles.push_back({base, ring(1, j + 1), ring(1, j)});
        for (unsigned i = 1; i + 1 < rings; ++i) {
            m.triangles.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j)});
            m.triangles.push_back({ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j)});
        }
        m.triangles.push_back({south, ring(rings - 1, j), ring(rings - 1, j + 1)});
    }
}

// The shapes by name: "blob" (one blob of radius 1 at the origin) or "cluster" (six: a body, a head
// above it and a little behind, an arm in front and one behind, two small parts in front of the body;
// every part `segments` around, so the small ones' triangles are the smallest). Empty for another name.
inline const std::vector<std::string>& shape_names() {
    static const std::vector<std::string> names{"blob", "cluster"};
    return names;
}
inline scene::mesh make_shape(const std::string& shape, unsigned segments) {
    scene::mesh m;
    if (shape == "blob") {
        add_blob(m, segments, {0.0, 0.0, 0.0}, 1.0, 0.0);
    } else if (shape == "cluster") {
        struct part {
            glm::dvec3 centre;
            double radius, phase;
        };
        const part parts[] = {{{0.0, 0.0, 0.0}, 1.0, 0.0},       {{0.15, 1.25, -0.25}, 0.55, 1.1},
                              {{-1.05, 0.35, 0.45}, 0.45, 2.3},  {{1.0, 0.2, -0.5}, 0.5, 3.7},
                              {{0.25, -0.45, 0.95}, 0.35, 4.9},  {{-0.5, -0.9, 0.7}, 0.25, 0.6}};
        for (const part& p : parts) add_blob(m, segments, p.centre, p.radius, p.phase);
    }
    return m;
}

// Wavefront OBJ with a normal per vertex: "v", "vn", "f a//a b//b c//c" (1-based), 17 significant
// digits so the file reads back to the same doubles. False if the file cannot be written.
inline bool write_obj(const scene::mesh& m, const std::string& path, const std::string& comment) {
    std::ofstream f(path);
    if (!f) return false;
    f.precision(17);
    f << "# " << comment << "\n";
    for (const auto& p : m.positions) f << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& n : m.normals) f << "vn " << n.x << ' ' << n.y << ' ' << n.z << '\n';
    for (const auto& t : m.triangles) {
        f << 'f';
        for (uint32_t i : t) f << ' ' << i + 1 << "//" << i + 1;
        f << '\n';
    }
    return static_cast<bool>(f.flush());
}

}  // namespace shading::tb::test_obj
