#include "study_frame.h"

#include "scene/shade.h"
#include "line_kinks.h"

namespace shading::study {

study_frame::study_frame(const std::string& scene, const std::string& data_dir, unsigned size,
                         const std::string& device, bool walk_edges)
    : w(scene::builtin_scene(scene, data_dir, size, size)), r(scene::rasterise(w)), k(pipeline::frame_constants_of(w)) {
    dev.device = scene::parse_device(device);
    per_pixel = pipeline::per_pixel_frame(r, k, dev);
    colour = levels_of(per_pixel);
    scene::render_stats sl;
    scene::render_phong_scanline(r, &sl, nullptr, walk_edges);
    pixels = sl.pixels;
    scanline = sl.pixels ? double(sl.total().long_ops()) / double(sl.pixels) : 0.0;
}

}  // namespace shading::study
