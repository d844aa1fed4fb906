// A scene's frame, its reference and its baselines (frame_setup.h).
#include "golden_pipeline/frame_setup.h"

#include "scene/shade.h"

namespace shading::pipeline {

namespace {

scene::world with(scene::world w, const std::vector<double>& light, unsigned n) {
    if (!light.empty()) {
        if (light.size() != 2) throw scene::scene_error("frame_setup: a light is {azimuth, elevation}");
        const scene::rgb intensity = w.lights.empty() ? scene::rgb{1.0, 1.0, 1.0} : w.lights.front().intensity;
        w.lights = {{scene::light::kind::directional, scene::light_towards(light[0], light[1]), intensity}};
    }
    if (n != 0)
        for (auto& o : w.objects) o.mat.n = n;
    scene::validate(w);
    return w;
}

bool ends_with_obj(const std::string& s) { return s.size() > 4 && s.compare(s.size() - 4, 4, ".obj") == 0; }

}  // namespace

scene::world scene_of(const std::string& scene, const std::string& data_dir, unsigned size,
                      const std::vector<double>& light, unsigned n) {
    return with(ends_with_obj(scene) ? scene::obj_scene(scene, size, size)
                                     : scene::builtin_scene(scene, data_dir, size, size),
                light, n);
}

frame_setup::frame_setup(const std::string& scene, const std::string& data_dir, unsigned size,
                         const std::string& device, bool walk_edges, const std::vector<double>& light, unsigned n)
    : w(scene_of(scene, data_dir, size, light, n)),
      r(scene::rasterise(w)),
      k(frame_constants_of(w)) {
    dev.device = scene::parse_device(device);
    per_pixel = per_pixel_frame(r, k, dev);
    scene::render_stats sl;
    scene::render_phong_scanline(r, &sl, nullptr, walk_edges);
    pixels = sl.pixels;
    scanline = sl.pixels ? double(sl.total().long_ops()) / double(sl.pixels) : 0.0;
    scene::render_stats ph;
    scene::render_phong(r, &ph);
    phong = ph.pixels ? double(ph.total().long_ops()) / double(ph.pixels) : 0.0;
}

}  // namespace shading::pipeline
