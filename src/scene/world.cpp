#include "scene/world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "formats/ua60553_formats.h"

namespace shading::scene {

namespace {
constexpr double pi = 3.14159265358979323846;

bool unit_colour(const rgb& c) {
    return c.x >= 0.0 && c.x <= 1.0 && c.y >= 0.0 && c.y <= 1.0 && c.z >= 0.0 && c.z <= 1.0;
}

// Direction from azimuth (degrees, positive = towards +x from +z) and elevation (degrees, up).
glm::dvec3 direction(double azimuth_deg, double elevation_deg) {
    const double az = azimuth_deg * pi / 180.0, el = elevation_deg * pi / 180.0;
    return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

// A perspective camera that sees the whole bounding sphere from the given direction.
camera frame(const bounds& b, const glm::dvec3& dir, unsigned width, unsigned height) {
    camera c;
    c.width = width;
    c.height = height;
    c.fov_y_deg = 30.0;
    c.target = b.centre();
    // Fit the box's larger cross extent (with a margin), plus half its depth.
    const glm::dvec3 e = b.hi - b.lo;
    const double half = 0.5 * c.fov_y_deg * pi / 180.0;
    const double dist = 0.62 * std::max({e.x, e.y, e.z}) / std::tan(half) + 0.5 * glm::length(e);
    c.position = c.target + dist * glm::normalize(dir);
    c.z_near = 0.05 * dist;
    c.z_far = 4.0 * dist;
    return c;
}
}  // namespace

glm::dvec3 light_towards(double azimuth_deg, double elevation_deg) {
    constexpr double pi = 3.14159265358979323846;
    const double a = azimuth_deg * pi / 180.0, e = elevation_deg * pi / 180.0;
    return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}

material skin_material() {
    material m;
    m.ambient = {0.07, 0.05, 0.045};
    m.k_d = {0.66, 0.50, 0.42};
    m.k_s = {0.40, 0.40, 0.40};
    m.n = 20;
    return m;
}

void validate(const world& s) {
    const camera& c = s.cam;
    if (c.width == 0 || c.height == 0) throw scene_error("scene '" + s.name + "': empty image size");
    if (glm::length(c.position - c.target) == 0.0)
        throw scene_error("scene '" + s.name + "': the camera's position equals its target");
    if (!c.orthographic() && c.fov_y_deg >= 180.0)
        throw scene_error("scene '" + s.name + "': field of view must be below 180 degrees");
    if (s.lights.empty()) throw scene_error("scene '" + s.name + "': no light");
    for (const auto& l : s.lights)
        if (!(l.intensity.x >= 0.0 && l.intensity.y >= 0.0 && l.intensity.z >= 0.0))
            throw scene_error("scene '" + s.name + "': a light with a negative intensity");
    for (const auto& o : s.objects) {
        const material& m = o.mat;
        if (m.n < ua60553::n_min || m.n > ua60553::n_max)
            throw scene_error("object '" + o.name + "': exponent n = " + std::to_string(m.n) +
                              " outside " + std::to_string(ua60553::n_min) + "..." +
                              std::to_string(ua60553::n_max));
        if (!unit_colour(m.ambient) || !unit_colour(m.k_d) || !unit_colour(m.k_s))
            throw scene_error("object '" + o.name + "': a material colour outside [0, 1]");
    }
}

std::vector<std::string> builtin_scene_names() { return {"sphere", "torus", "head"}; }

world builtin_scene(const std::string& name, const std::string& data_dir, unsigned width, unsigned height) {
    world s;
    s.name = name;
    if (name == "sphere") {
        object o{"sphere", make_sphere(1.0, 96, 48), material{}};
        o.mat.k_d = {0.75, 0.25, 0.20};
        o.mat.k_s = {0.45, 0.45, 0.45};
        o.mat.n = 40;
        s.cam = frame(mesh_bounds(o.geometry), {0.0, 0.0, 1.0}, width, height);
        s.lights.push_back({light::kind::directional, direction(-35.0, 35.0), {1.0, 1.0, 1.0}});
        s.objects.push_back(std::move(o));
    } else if (name == "torus") {
        object o{"torus", make_torus(1.0, 0.38, 96, 48), material{}};
        o.mat.k_d = {0.25, 0.45, 0.75};
        o.mat.k_s = {0.50, 0.50, 0.50};
        o.mat.n = 60;
        s.cam = frame(mesh_bounds(o.geometry), direction(0.0, 40.0), width, height);
        s.lights.push_back({light::kind::directional, direction(-30.0, 50.0), {1.0, 1.0, 1.0}});
        s.objects.push_back(std::move(o));
    } else if (name == "head") {
        std::string root = data_dir.empty() ? std::string(".") : data_dir;
        if (root.back() != '/') root += '/';
        s = obj_scene(root + head_obj_relpath, width, height);
        s.name = "head";
        s.objects.front().name = "head";
    } else {
        std::string known;
        for (const auto& n : builtin_scene_names()) known += (known.empty() ? "" : ", ") + n;
        throw scene_error("unknown scene '" + name + "' (built in: " + known + ")");
    }
    return s;
}

world obj_scene(const std::string& path, unsigned width, unsigned height) {
    world s;
    s.name = path;
    object o{path, load_obj(path), skin_material()};
    // Front three-quarter view: 30 degrees to the model's left of the face (+z), 8 degrees above,
    // framing the top 60 % of the model's height (a bust's head, not its shoulders).
    const bounds all = mesh_bounds(o.geometry);
    // The framing and the rasteriser square coordinates and extents: beyond these limits they
    // overflow (an empty picture) or underflow (a camera on its target), so the model is refused.
    const double largest = std::max({std::abs(all.lo.x), std::abs(all.lo.y), std::abs(all.lo.z), std::abs(all.hi.x),
                                     std::abs(all.hi.y), std::abs(all.hi.z)});
    const glm::dvec3 e = all.hi - all.lo;
    const double extent = std::max({e.x, e.y, e.z});
    if (!(largest <= obj_coordinate_max) || !(extent >= obj_extent_min)) {
        char msg[200];
        std::snprintf(msg, sizeof msg,
                      "a coordinate of magnitude %.3g and an extent of %.3g: the framing needs coordinates "
                      "within +-%.0e and an extent of at least %.0e (scale the model)",
                      largest, extent, obj_coordinate_max, obj_extent_min);
        throw scene_error("scene '" + path + "': " + msg);
    }
    const double y_cut = all.hi.y - 0.6 * (all.hi.y - all.lo.y);
    bounds b{all.hi, all.lo};
    for (const auto& p : o.geometry.positions)
        if (p.y >= y_cut) {
            b.lo = glm::min(b.lo, p);
            b.hi = glm::max(b.hi, p);
        }
    s.cam = frame(b, direction(30.0, 8.0), width, height);
    // Key light from the upper front, left of the camera: Blinn's H = (L + V)/|L + V| then points
    // at forehead, nose bridge and the near cheek, where the scan's surface faces it.
    s.lights.push_back({light::kind::directional, direction(-5.0, 28.0), {1.0, 1.0, 1.0}});
    s.objects.push_back(std::move(o));
    return s;
}

}  // namespace shading::scene
