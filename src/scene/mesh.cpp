#include "scene/mesh.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include <tiny_obj_loader.h>

namespace shading::scene {

namespace {
constexpr double pi = 3.14159265358979323846;

// The angle between two edge vectors, robust near 0 and pi (atan2 of |cross| and dot).
double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

double max_abs(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// The power of two at or above x > 0 (finite): scaling by its inverse is exact, so a model of
// ordinary size gets the same bits as unscaled.
double pow2_above(double x) {
    int e = 0;
    std::frexp(x, &e);  // x = f 2^e, f in [0.5, 1)
    return std::ldexp(1.0, e);
}

// v / |v|, or +z where v has no direction (zero, or not finite). Scaled by a power of two near its
// largest component first, so |v| neither overflows (components near 1e200) nor underflows (1e-200).
glm::dvec3 unit_or_z(const glm::dvec3& v) {
    const double s = max_abs(v);
    if (!(s > 0.0) || !std::isfinite(s)) return glm::dvec3(0.0, 0.0, 1.0);
    const glm::dvec3 u = v / pow2_above(s);
    return u / glm::length(u);
}
}  // namespace

void compute_normals(mesh& m, normal_weighting w) {
    // The normals do not depend on the model's scale: positions divided by a power of two at or above
    // the largest coordinate, so the cross products of any finite model neither overflow nor underflow.
    double largest = 0.0;
    for (const auto& p : m.positions) largest = std::max(largest, max_abs(p));
    const double scale = largest > 0.0 ? pow2_above(largest) : 1.0;
    std::vector<glm::dvec3> sum(m.positions.size(), glm::dvec3(0.0));
    for (const auto& t : m.triangles) {
        const glm::dvec3 p0 = m.positions[t[0]] / scale;
        const glm::dvec3 p1 = m.positions[t[1]] / scale;
        const glm::dvec3 p2 = m.positions[t[2]] / scale;
        const glm::dvec3 c = glm::cross(p1 - p0, p2 - p0);  // length = 2 * area
        if (w == normal_weighting::area) {
            for (uint32_t v : t) sum[v] += c;
            continue;
        }
        const double len = glm::length(c);
        if (len == 0.0) continue;  // degenerate: no direction, no angle
        const glm::dvec3 n = c / len;
        sum[t[0]] += angle_between(p1 - p0, p2 - p0) * n;
        sum[t[1]] += angle_between(p2 - p1, p0 - p1) * n;
        sum[t[2]] += angle_between(p0 - p2, p1 - p2) * n;
    }
    m.normals.resize(m.positions.size());
    for (std::size_t i = 0; i < sum.size(); ++i) m.normals[i] = unit_or_z(sum[i]);
}

mesh load_obj(const std::string& path, normal_weighting w) {
    {
        std::ifstream probe(path);
        if (!probe) throw obj_error(path, "cannot be opened (missing or unreadable)");
    }
    tinyobj::ObjReaderConfig cfg;
    cfg.triangulate = false;  // split here, so the file's own faces are known (quads: fan v0 v1 v2, v0 v2 v3)
    cfg.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path, cfg)) {
        std::string e = reader.Error();
        while (!e.empty() && (e.back() == '\n' || e.back() == '\r')) e.pop_back();
        throw obj_error(path, "malformed: " + (e.empty() ? std::string("the parser rejected it") : e));
    }
    const auto& attrib = reader.GetAttrib();
    const std::size_t nv = attrib.vertices.size() / 3;
    const std::size_t nn = attrib.normals.size() / 3;
    mesh m;
    m.positions.reserve(nv);
    for (std::size_t i = 0; i < nv; ++i) {
        const glm::dvec3 p(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw obj_error(path, "malformed: vertex " + std::to_string(i + 1) + " is not finite");
        m.positions.push_back(p);
    }
    bool all_normals = nn > 0;
    std::vector<glm::dvec3> file_normals(nv, glm::dvec3(0.0));
    for (const auto& shape : reader.GetShapes()) {
        const auto& sm = shape.mesh;
        std::size_t base = 0;
        for (std::size_t f = 0; f < sm.num_face_vertices.size(); ++f) {
            const std::size_t k = sm.num_face_vertices[f];
            if (k < 3) throw obj_error(path, "malformed: a face with " + std::to_string(k) + " vertices");
            std::vector<uint32_t> idx(k);
            for (std::size_t j = 0; j < k; ++j) {
                const tinyobj::index_t& ix = sm.indices[base + j];
                if (ix.vertex_index < 0 || static_cast<std::size_t>(ix.vertex_index) >= nv)
                    throw obj_error(path, "malformed: face " + std::to_string(m.file_faces + 1) +
                                              " refers to vertex " + std::to_string(ix.vertex_index + 1) +
                                              " of " + std::to_string(nv));
                idx[j] = static_cast<uint32_t>(ix.vertex_index);
                if (ix.normal_index < 0 || static_cast<std::size_t>(ix.normal_index) >= nn) {
                    all_normals = false;
                } else {
                    const std::size_t n = static_cast<std::size_t>(ix.normal_index);
                    file_normals[idx[j]] += glm::dvec3(attrib.normals[3 * n], attrib.normals[3 * n + 1],
                                                       attrib.normals[3 * n + 2]);
                }
            }
            for (std::size_t j = 1; j + 1 < k; ++j) m.triangles.push_back({idx[0], idx[j], idx[j + 1]});
            ++m.file_faces;
            if (k == 4) ++m.file_quads;
            base += k;
        }
    }
    if (m.triangles.empty())
        throw obj_error(path, nv == 0 ? "empty: no vertices and no faces" : "empty: no faces");
    m.file_had_normals = all_normals;
    if (all_normals) {
        m.normals.resize(nv);
        for (std::size_t i = 0; i < nv; ++i) m.normals[i] = unit_or_z(file_normals[i]);
    } else {
        compute_normals(m, w);
    }
    return m;
}

mesh make_sphere(double radius, unsigned slices, unsigned stacks) {
    mesh m;
    slices = std::max(3u, slices);
    stacks = std::max(2u, stacks);
    // Rows of (slices + 1) vertices from the north pole (i = 0) to the south pole (i = stacks); the
    // seam column is duplicated, so the normals on it are still exact.
    for (unsigned i = 0; i <= stacks; ++i) {
        const double th = pi * i / stacks;
        for (unsigned j = 0; j <= slices; ++j) {
            const double ph = 2.0 * pi * j / slices;
            const glm::dvec3 n(std::sin(th) * std::cos(ph), std::cos(th), -std::sin(th) * std::sin(ph));
            m.positions.push_back(radius * n);
            m.normals.push_back(n);
        }
    }
    const unsigned row = slices + 1;
    for (unsigned i = 0; i < stacks; ++i)
        for (unsigned j = 0; j < slices; ++j) {
            const uint32_t a = i * row + j, b = a + 1, c = a + row, d = c + 1;
            if (i != 0) m.triangles.push_back({a, c, b});
            if (i + 1 != stacks) m.triangles.push_back({b, c, d});
        }
    return m;
}

mesh make_torus(double major_radius, double minor_radius, unsigned rings, unsigned sides) {
    mesh m;
    rings = std::max(3u, rings);
    sides = std::max(3u, sides);
    for (unsigned i = 0; i <= rings; ++i) {
        const double u = 2.0 * pi * i / rings;
        const glm::dvec3 centre(major_radius * std::cos(u), 0.0, -major_radius * std::sin(u));
        for (unsigned j = 0; j <= sides; ++j) {
            const double v = 2.0 * pi * j / sides;
            const glm::dvec3 n(std::cos(v) * std::cos(u), std::sin(v), -std::cos(v) * std::sin(u));
            m.positions.push_back(centre + minor_radius * n);
            m.normals.push_back(n);
        }
    }
    const unsigned row = sides + 1;
    for (unsigned i = 0; i < rings; ++i)
        for (unsigned j = 0; j < sides; ++j) {
            const uint32_t a = i * row + j, b = a + 1, c = a + row, d = c + 1;
            m.triangles.push_back({a, b, d});
            m.triangles.push_back({a, d, c});
        }
    return m;
}

bounds mesh_bounds(const mesh& m) {
    bounds b{glm::dvec3(std::numeric_limits<double>::infinity()),
             glm::dvec3(-std::numeric_limits<double>::infinity())};
    for (const auto& p : m.positions) {
        b.lo = glm::min(b.lo, p);
        b.hi = glm::max(b.hi, p);
    }
    return b;
}

}  // namespace shading::scene
