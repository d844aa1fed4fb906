// Renders a scene's two per-pixel references to PNG: Phong with exact cos^n, and per-pixel shading
// through a specular device's bit-accurate golden model; prints the counted operations per pixel,
// the device image's error against Phong and the time taken. --compare adds compare.png: Phong and
// several devices' images above their error maps, all at one --error-scale.
//   build/bin/render_reference --scene head --size 256 --device minimax --out out/scene
//   build/bin/render_reference --scene head --size 512 --n 20 --compare patent,squared --out out/scene/compare
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "testbenches/common/exit_status.h"
#include "testbenches/options/tool_options.h"
#include "scene/image.h"
#include "scene/raster.h"
#include "scene/shade.h"

using namespace shading;
using namespace shading::scene;

namespace {
void print_counts(const char* what, const render_stats& st) {
    const double n = static_cast<double>(st.pixels);
    auto row = [n](const char* part, const op_counts& c) {
        std::printf("  %-9s mul %6.2f  div %5.2f  sqrt %5.2f  add %6.2f  cmp %5.2f  long (mul+div+sqrt) %6.2f\n",
                    part, c.mul / n, c.div / n, c.sqrt / n, c.add / n, c.cmp / n, c.long_ops() / n);
    };
    std::printf("%s: %zu pixels shaded in %.3f s (%.2f us/pixel); operations per pixel:\n", what, st.pixels,
                st.seconds, 1e6 * st.seconds / n);
    row("geometry", st.geometry);
    row("shading", st.shading);
    row("total", st.total());
}
}  // namespace

int main(int argc, char* argv[]) {
    tb::render_reference_options o;
    if (auto rc = tb::parse_render_reference(argc, argv, o)) return *rc;  // names, ranges, numbers: exit 2
    const std::string &scene_arg = o.scene, &out_dir = o.out, &device_arg = o.device, &mode_arg = o.mode;
    const std::string& data_dir = o.data_dir;
    const unsigned size = o.size, n_override = o.n;
    const double err_scale = o.error_scale, depth_step_arg = o.depth_step;
    const std::vector<std::string>& compare_arg = o.compare;

    // A name that is no file and does not end in .obj is taken as a built-in scene's name: an unknown
    // one is bad usage, reported with the list of names. A missing or malformed OBJ file is a failure.
    const bool looks_like_obj = scene_arg.size() > 4 && scene_arg.substr(scene_arg.size() - 4) == ".obj";
    const bool builtin = !looks_like_obj && !std::filesystem::is_regular_file(scene_arg);
    if (builtin) {
        const auto names = builtin_scene_names();
        if (std::find(names.begin(), names.end(), scene_arg) == names.end()) {
            std::string known;
            for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
            std::fprintf(stderr, "render_reference: --scene '%s' is neither a file nor a built-in scene (%s)\n",
                         scene_arg.c_str(), known.c_str());
            return tb::exit_usage;
        }
    }

    try {
        const device_config dev{parse_device(device_arg),
                                mode_arg == "wrap" ? overflow_mode::wrap : overflow_mode::saturate};
        std::vector<device_config> compare_devs;  // checked before any rendering
        for (const std::string& name : compare_arg) compare_devs.push_back({parse_device(name), dev.mode});
        world s = builtin ? builtin_scene(scene_arg, data_dir, size, size) : obj_scene(scene_arg, size, size);
        if (n_override != 0)
            for (auto& o : s.objects) o.mat.n = n_override;
        const auto t0 = std::chrono::steady_clock::now();
        const rasterised r = rasterise(s);
        const double t_raster = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

        render_stats sp, sd;
        const shaded_image phong = render_phong(r, &sp);
        const shaded_image device = render_device(r, dev, &sd);

        // NMSE of the device image against Phong over the covered pixels and channels.
        const image_diff diff = compare_images(device, phong);
        const auto err = abs_error(device, phong);

        // The places where the visible surface jumps along each line, drawn over a dimmed Phong image:
        // depth steps and object changes red, coverage edges green (on the first covered pixel).
        rgb_image edges = to_rgb8(phong);
        for (auto& v : edges.data) v = static_cast<uint8_t>(v / 3);
        std::size_t n_steps = 0, n_cover = 0;
        for (unsigned y = 0; y < r.height; ++y)
            for (const discontinuity& d : line_discontinuities(r, y, depth_step_arg)) {
                const bool step = d.kinds & (depth_step | object_change);
                (step ? n_steps : n_cover) += 1;
                const unsigned x = (d.kinds & coverage_end) && !step ? d.x - 1 : std::min(d.x, r.width - 1);
                uint8_t* p = edges.at(x, y);
                p[0] = step ? 255 : 0;
                p[1] = step ? 40 : 200;
                p[2] = step ? 40 : 0;
            }

        std::filesystem::create_directories(out_dir);
        const std::string dname = device_name(dev.device);
        const rgb_image a = to_rgb8(phong), b = to_rgb8(device);
        const rgb_image h = heat_map(err, err.empty() ? 0 : phong.width, phong.height, err_scale, &phong.covered);
        save_png(a, out_dir + "/phong.png");
        save_png(b, out_dir + "/device_" + dname + ".png");
        save_png(h, out_dir + "/error_" + dname + ".png");
        save_png(edges, out_dir + "/discontinuities.png");
        char label[64];
        std::snprintf(label, sizeof label, "ERROR X%.0f (WHITE = %.0f)", 255.0 / err_scale, err_scale);
        save_png(side_by_side({a, b, h}, {"PHONG, EXACT COS^N", "DEVICE " + dname + " (" + mode_arg + ")", label}),
                 out_dir + "/sheet_" + dname + ".png");

        std::printf("scene %s, %ux%u, %zu triangles set up, %zu pixels covered; rasterised in %.3f s\n",
                    s.name.c_str(), r.width, r.height, r.setups.size(), r.covered_pixels(), t_raster);
        std::printf("material n = %u; device %s, %s\n", s.objects.front().mat.n, dname.c_str(), mode_arg.c_str());
        print_counts("Phong reference", sp);
        print_counts("device reference", sd);
        std::printf("discontinuities along the lines: %zu depth steps (> %g) or object changes, %zu coverage edges\n",
                    n_steps, depth_step_arg, n_cover);
        std::printf("device vs Phong: NMSE %.3e, largest error %.2f (8-bit levels)\n", diff.nmse, diff.max_abs);
        if (!compare_arg.empty()) {
            // One sheet: Phong and each device on top, a key and each device's error map below it.
            char key[96];
            std::snprintf(key, sizeof key, "ERROR AGAINST PHONG, 8-BIT LEVELS (WHITE: %g AND ABOVE)", err_scale);
            std::vector<rgb_image> top{a}, bottom{heat_map_legend(a.width, a.height, err_scale, key)};
            std::vector<std::string> top_labels{"PHONG, EXACT COS^N"}, bottom_labels{""};
            for (const device_config& cd : compare_devs) {
                const std::string name = device_name(cd.device);
                const shaded_image img = render_device(r, cd);
                const image_diff d = compare_images(img, phong);
                char label[96];
                std::snprintf(label, sizeof label, "DEVICE %s, N = %u", name.c_str(), s.objects.front().mat.n);
                top.push_back(to_rgb8(img));
                top_labels.emplace_back(label);
                std::snprintf(label, sizeof label, "%s - PHONG: NMSE %.1e, MAX %.2f", name.c_str(), d.nmse, d.max_abs);
                bottom.push_back(heat_map(abs_error(img, phong), phong.width, phong.height, err_scale, &phong.covered));
                bottom_labels.emplace_back(label);
                std::printf("compare %s vs Phong: NMSE %.3e, largest error %.2f (8-bit levels)\n", name.c_str(), d.nmse,
                            d.max_abs);
            }
            save_png(stacked({side_by_side(top, top_labels), side_by_side(bottom, bottom_labels)}), out_dir + "/compare.png");
            std::printf("wrote %s/compare.png (error maps white at %g levels)\n", out_dir.c_str(), err_scale);
        }
        std::printf("wrote %s/{phong,device_%s,error_%s,sheet_%s,discontinuities}.png\n", out_dir.c_str(), dname.c_str(), dname.c_str(),
                    dname.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "render_reference: %s\n", e.what());
        return tb::exit_failure;
    }
    return tb::exit_success;
}
