// Scenes: camera, lights, materials and meshes, and the built-in scenes (sphere, torus, head).
// Colours and intensities are reals in [0, 1] per channel; images are 8-bit (255 = 1.0).
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh.h"

namespace shading::scene {

using rgb = glm::dvec3;

// Right-handed, looking from `position` at `target`; `fov_y_deg` > 0: perspective with that
// vertical field of view; 0: orthographic, `ortho_height` world units tall. Pixel (0, 0) is the
// top-left one; the pixel centre of (x, y) is (x + 0.5, y + 0.5).
struct camera {
    glm::dvec3 position{0.0, 0.0, 3.0};
    glm::dvec3 target{0.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fov_y_deg = 30.0;
    double ortho_height = 2.0;
    unsigned width = 256;
    unsigned height = 256;
    double z_near = 0.01;
    double z_far = 100.0;
    bool orthographic() const { return fov_y_deg <= 0.0; }
};

// Directional: `vector` points from the surface towards the light (L is constant);
// point: `vector` is the light's position (L varies per pixel). No fall-off.
struct light {
    enum class kind { directional, point } type = kind::directional;
    glm::dvec3 vector{0.0, 0.0, 1.0};
    rgb intensity{1.0, 1.0, 1.0};
};

// Phong/Blinn material: I = ambient + sum over lights of I_l * (k_d * N.L + k_s * (N.H)^n).
// `n` is an integer because the specular devices take it as a 10-bit code (1..1000).
struct material {
    rgb ambient{0.05, 0.05, 0.05};
    rgb k_d{0.6, 0.6, 0.6};
    rgb k_s{0.4, 0.4, 0.4};
    unsigned n = 32;
};

struct object {
    std::string name;
    mesh geometry;
    material mat;
};

// A whole scene (called world: the namespace is already scene).
struct world {
    std::string name;
    camera cam;
    std::vector<light> lights;
    std::vector<object> objects;
};

// An unknown scene name, a bad material or camera.
class scene_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws scene_error unless n is in 1..1000, every colour in [0, 1], the image non-empty and the
// camera's position differs from its target.
void validate(const world& s);

// The repository-relative path of the head scan ("Infinite, 3D Head Scan" by Lee Perry-Smith,
// CC BY 3.0, based on a work at triplegangers.com; data/head/README.md).
inline constexpr const char* head_obj_relpath = "data/head/lee_perry_smith_head.obj";

// Names of the built-in scenes: "sphere", "torus", "head".
std::vector<std::string> builtin_scene_names();

// A built-in scene at width x height. `data_dir` is the repository root (the head scan is read
// from data_dir/head_obj_relpath). Throws scene_error for an unknown name, obj_error if the head
// scan cannot be read.
world builtin_scene(const std::string& name, const std::string& data_dir, unsigned width, unsigned height);

// The range of models obj_scene frames: every coordinate within +-obj_coordinate_max and the
// bounding box at least obj_extent_min along its longest side (the framing squares both).
inline constexpr double obj_coordinate_max = 1e100, obj_extent_min = 1e-100;

// A scene around a user's OBJ file: the mesh framed by a front three-quarter camera (looking
// along -z, +y up), one white light from the upper left front, the head's skin material. Throws
// obj_error for a file load_obj refuses, scene_error for a model outside the range above.
world obj_scene(const std::string& path, unsigned width, unsigned height);

// The defaults for the head (and for user OBJ files).
material skin_material();

// The direction towards a directional light at azimuth and elevation in degrees (azimuth positive
// towards +x from +z, elevation up), in the built-in scenes' world coordinates.
glm::dvec3 light_towards(double azimuth_deg, double elevation_deg);

}  // namespace shading::scene
