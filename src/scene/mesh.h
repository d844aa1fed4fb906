// Triangle meshes with per-vertex normals: the OBJ loader (Debian's tinyobjloader), normals from the
// faces when the file has none, and the built-in sphere and torus. Plain C++ with GLM, no SystemC.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace shading::scene {

// A missing, unreadable, malformed or empty OBJ file. what() names the file and the problem; the
// program layer prints it and exits non-zero.
class obj_error : public std::runtime_error {
public:
    obj_error(const std::string& path, const std::string& problem)
        : std::runtime_error("OBJ file '" + path + "': " + problem), path_(path) {}
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

// Indexed triangles; normals[i] belongs to positions[i] and has unit length.
struct mesh {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals;
    std::vector<std::array<uint32_t, 3>> triangles;
    // What the file held before triangulation (for the loader's report and tests).
    std::size_t file_faces = 0;
    std::size_t file_quads = 0;
    bool file_had_normals = false;
};

// How compute_normals weights each face's normal at a vertex: by the face's area (the unnormalised
// cross product), or by the face's angle at that vertex (Thürmer & Wüthrich 1998), which does not
// depend on how a quad was split.
enum class normal_weighting { area, angle };

// Per-vertex normals from the faces; a vertex whose weighted sum vanishes gets (0, 0, 1).
void compute_normals(mesh& m, normal_weighting w = normal_weighting::angle);

// Loads an OBJ: polygons are split into triangles (a quad v0 v1 v2 v3 -> (v0 v1 v2), (v0 v2 v3),
// tinyobjloader's fan). Normals from the file are used when every face corner has one
// (averaged per position index, renormalised); otherwise they are computed with `w`.
// Throws obj_error when the file is missing or unreadable, the parser reports an error, a face
// refers to a vertex that does not exist, or there is no face.
mesh load_obj(const std::string& path, normal_weighting w = normal_weighting::angle);

// Built-in shapes with exact analytic normals (not computed from faces).
mesh make_sphere(double radius, unsigned slices, unsigned stacks);
mesh make_torus(double major_radius, double minor_radius, unsigned rings, unsigned sides);

// Axis-aligned bounds of the positions.
struct bounds {
    glm::dvec3 lo, hi;
    glm::dvec3 centre() const { return 0.5 * (lo + hi); }
    double radius() const { return 0.5 * glm::length(hi - lo); }
};
bounds mesh_bounds(const mesh& m);

}  // namespace shading::scene
