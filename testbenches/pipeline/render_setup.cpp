// render_pipeline's options to a scene and a plan configuration (render_program.h).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "render_program.h"
#include "scene/scene.h"

namespace shading::render_program {

namespace fs = std::filesystem;

// "v" or "r,g,b" -> a colour; throws scene_error naming the option.
scene::rgb parse_colour(const std::string& opt, const std::string& s) {
    std::vector<double> v;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ',')) {
        std::size_t used = 0;
        double x = 0.0;
        try {
            x = std::stod(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != item.size()) throw scene::scene_error(opt + " '" + s + "': not a number or r,g,b");
        v.push_back(x);
    }
    if (v.size() == 1) return {v[0], v[0], v[0]};
    if (v.size() == 3) return {v[0], v[1], v[2]};
    throw scene::scene_error(opt + " '" + s + "': give one value or r,g,b");
}

// "azimuth,elevation" (degrees; azimuth positive towards +x from +z, elevation up) -> the direction
// towards a directional light, in the scene's world coordinates (as the built-in scenes place theirs).
glm::dvec3 parse_light(const std::string& s) {
    const std::size_t comma = s.find(',');
    double az = 0.0, el = 0.0;
    try {
        std::size_t u1 = 0, u2 = 0;
        if (comma == std::string::npos) throw std::invalid_argument("");
        const std::string a = s.substr(0, comma), b = s.substr(comma + 1);
        az = std::stod(a, &u1);
        el = std::stod(b, &u2);
        if (u1 != a.size() || u2 != b.size()) throw std::invalid_argument("");
    } catch (const std::exception&) {
        throw scene::scene_error("--light '" + s + "': expected azimuth,elevation in degrees");
    }
    return scene::light_towards(az, el);
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

plan_config plan_config_of(const options& o) {
    plan_config c = o.pc;
    c.set = o.set == "case2" ? interp::sample_set::case2 : interp::sample_set::case1;
    c.div = o.div3 == "exact" ? interp::div3_mode::exact : interp::div3_mode::shift_add;
    c.length = o.length == "adaptive"   ? length_policy::adaptive
               : o.length == "geometry" ? length_policy::geometry
                                        : length_policy::fixed;
    c.degree = o.degree == "quadratic" ? degree_policy::quadratic
               : o.degree == "zones"   ? degree_policy::zones
               : o.degree == "adaptive" ? degree_policy::adaptive
               : o.degree == "geometry" ? degree_policy::geometry
                                        : degree_policy::cubic;
    c.eval = o.eval == "fd" ? evaluator::fd : evaluator::horner;
    c.unit = o.unit == "scratch" ? geometry_unit::scratch : geometry_unit::stepped;
    return c;
}

// Bad usage found from the command line alone, before any work (exit 2, common/exit_status.h): an
// unknown built-in scene, a light or colour that does not parse, a plan the units cannot run. Empty
// when none. A missing or malformed OBJ file is found later, and is a failure (exit 1).
std::string usage_problem(const options& o) {
    if (!o.sweep && o.device == "all") return "--device all is for --sweep";
    const bool looks_like_obj = o.scene.size() > 4 && o.scene.substr(o.scene.size() - 4) == ".obj";
    if (!looks_like_obj && !fs::is_regular_file(o.scene)) {
        const auto names = scene::builtin_scene_names();
        if (std::find(names.begin(), names.end(), o.scene) == names.end())
            return "--scene '" + o.scene + "' is neither a file nor a built-in scene (sphere, torus, head)";
    }
    try {
        if (!o.light.empty()) parse_light(o.light);
        if (!o.kd.empty()) parse_colour("--kd", o.kd);
        if (!o.ks.empty()) parse_colour("--ks", o.ks);
        if (!o.ambient.empty()) parse_colour("--ambient", o.ambient);
        if (!o.shard.empty()) parse_shard(o.shard);
        validate(plan_config_of(o));
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

scene::world load_world(const options& o) {
    if (o.size == 0 || o.size > max_size)
        throw scene::scene_error("--size " + std::to_string(o.size) + ": outside 1.." + std::to_string(max_size) +
                                 " (a frame needs about 250 bytes per pixel; the limit keeps it below 4 GB)");
    // A name that is no file and does not end in .obj is a built-in scene's name (so an unknown one
    // is reported as such, with the list of names), as render_reference decides.
    const bool looks_like_obj = o.scene.size() > 4 && o.scene.substr(o.scene.size() - 4) == ".obj";
    const bool builtin = !looks_like_obj && !fs::is_regular_file(o.scene);
    scene::world s = builtin ? scene::builtin_scene(o.scene, o.data_dir, o.size, o.size)
                             : scene::obj_scene(o.scene, o.size, o.size);
    if (!o.light.empty()) {
        const scene::rgb intensity = s.lights.empty() ? scene::rgb{1.0, 1.0, 1.0} : s.lights.front().intensity;
        s.lights = {{scene::light::kind::directional, parse_light(o.light), intensity}};
    }
    for (auto& obj : s.objects) {
        if (o.n != -1) {
            if (o.n < 1 || o.n > 1000) throw scene::scene_error("--n " + std::to_string(o.n) + ": outside 1..1000");
            obj.mat.n = static_cast<unsigned>(o.n);
        }
        if (!o.kd.empty()) obj.mat.k_d = parse_colour("--kd", o.kd);
        if (!o.ks.empty()) obj.mat.k_s = parse_colour("--ks", o.ks);
        if (!o.ambient.empty()) obj.mat.ambient = parse_colour("--ambient", o.ambient);
    }
    scene::validate(s);
    return s;
}

}  // namespace shading::render_program
