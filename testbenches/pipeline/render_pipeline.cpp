// Seed 004's shading system end to end: a scene is rasterised, the geometry side plans every raster
// line into intervals (src/pipeline/plan.cpp), the bit-accurate golden pipeline shades the frame
// (golden_frame), and with --sim the SystemC pipeline shades it again and must agree bit for bit.
// The hardware image is measured against per-pixel shading through the same device (the
// interpolation's error), exact Phong (the total) and the two references against each other (the
// device BRDF's own error), whole image and per zone of the head; operations per pixel are counted
// for Phong and the hardware path. Writes PNGs and report.md / report.json into --out.
//   build/bin/render_pipeline --scene head --size 512 --out out/pipeline/head
// --sweep runs a grid of configurations on the golden model, one child process of this program per
// configuration (--jobs in parallel), and merges their reports into one CSV (scripts/plot_pipeline.py
// draws it).
//   build/bin/render_pipeline --sweep --scene head --size 256 --out out/pipeline/sweep
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "pipeline/pipeline.h"
#include "scene/image.h"
#include "scene/raster.h"
#include "scene/shade.h"

#ifndef SHADING_PIPELINE_SIM
#define SHADING_PIPELINE_SIM 0
#endif
#if SHADING_PIPELINE_SIM
#include <systemc>

#include "common/exit_status.h"
#include "common/report_log.h"
#include "pipeline_sim.h"
#endif

extern char** environ;

using namespace shading;
using namespace shading::pipeline;
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

// The largest --size: a frame costs about 250 bytes per pixel here (depth and triangle buffers, the
// four reference and hardware images as doubles, the frames' codes, the maps), so 4096 x 4096 needs
// about 4 GB; beyond that the program refuses rather than failing half-way through.
constexpr unsigned max_size = 4096;

constexpr double pi = 3.14159265358979323846;

// True while a progress line on a terminal has no newline yet (an error message then starts a new line).
bool progress_open = false;

struct options {
    std::string scene = "head", data_dir = SHADING_SOURCE_DIR, out = "out/pipeline";
    unsigned size = 256;
    std::string light;                  // "azimuth,elevation" in degrees; empty: the scene's own
    int n = -1;                         // -1: the scene's material
    std::string kd, ks, ambient;        // "v" or "r,g,b" in [0, 1]; empty: the scene's material
    std::string length = "fixed", degree = "cubic", eval = "horner", set = "case1", div3 = "shift_add";
    plan_config pc;                     // the numeric and boolean settings, defaults from pipeline.h
    std::string device = "patent", mode = "saturate";
    bool device_given = false;          // --sweep: without --device, the grid's devices
    bool sim = true, images = true;
    std::string abstraction = "block";  // the SystemC pipeline's level: block or fast (interp/abstraction.h)
    std::string vcd, json_name = "report.json", md_name = "report.md";
    double error_scale = 2.0, error_scale_total = 16.0;
    // --sweep
    bool inject_mismatch = false;       // (hidden, for the tests) corrupt one golden pixel before the comparison
    bool sweep = false;
    unsigned jobs = 0;
    std::string grid = "small", csv;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

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
    const double a = az * pi / 180.0, e = el * pi / 180.0;
    return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}

plan_config plan_config_of(const options& o) {
    plan_config c = o.pc;
    c.set = o.set == "case2" ? interp::sample_set::case2 : interp::sample_set::case1;
    c.div = o.div3 == "exact" ? interp::div3_mode::exact : interp::div3_mode::shift_add;
    c.length = o.length == "adaptive" ? length_policy::adaptive : length_policy::fixed;
    c.degree = o.degree == "quadratic" ? degree_policy::quadratic
               : o.degree == "zones"   ? degree_policy::zones
               : o.degree == "adaptive" ? degree_policy::adaptive
                                        : degree_policy::cubic;
    c.eval = o.eval == "fd" ? evaluator::fd : evaluator::horner;
    return c;
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

// ---- Images ----

// A map: each covered pixel gets colour_of(i), darkened by the Phong image's brightness so the face
// stays legible; empty pixels dark grey (as heat_map draws them).
scene::rgb_image shaded_map(const frame& f, const scene::shaded_image& shade,
                            const std::function<std::array<double, 3>(std::size_t)>& colour_of) {
    scene::rgb_image img(f.width, f.height, 40);
    for (unsigned y = 0; y < f.height; ++y)
        for (unsigned x = 0; x < f.width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * f.width + x;
            if (!f.covered[i]) continue;
            const auto& v = shade.value[i];
            const double lum = (0.299 * v[0] + 0.587 * v[1] + 0.114 * v[2]) / 255.0;
            const double k = 0.45 + 0.55 * std::min(1.0, lum);
            const auto c = colour_of(i);
            uint8_t* p = img.at(x, y);
            for (int ch = 0; ch < 3; ++ch) p[ch] = static_cast<uint8_t>(std::lround(std::clamp(c[ch] * k, 0.0, 255.0)));
        }
    return img;
}

// Degree map: exact pixels white, quadratic orange, cubic blue.
std::array<double, 3> degree_colour(uint8_t d) {
    switch (d) {
        case 1: return {235, 235, 235};
        case 2: return {245, 150, 40};
        case 3: return {60, 125, 235};
        default: return {40, 40, 40};
    }
}
// Interval map by log2 of the interval length: exact white, m = 2 red, 3 orange, 4 green, 5 cyan, 6 violet.
std::array<double, 3> length_colour(uint8_t m) {
    switch (m) {
        case 0: return {235, 235, 235};
        case 1: return {250, 120, 160};
        case 2: return {225, 50, 50};
        case 3: return {245, 160, 40};
        case 4: return {80, 195, 80};
        case 5: return {60, 175, 225};
        case 6: return {150, 85, 225};
        default: return {255, 0, 255};
    }
}
// Zone map: other grey, forehead, brows, eyes, nose, cheeks, mouth, chin.
std::array<double, 3> zone_colour(uint8_t z) {
    static constexpr std::array<std::array<double, 3>, zone_count> c{{{150, 150, 150},
                                                                      {90, 170, 235},
                                                                      {150, 95, 60},
                                                                      {60, 200, 200},
                                                                      {235, 90, 60},
                                                                      {245, 190, 110},
                                                                      {215, 60, 150},
                                                                      {120, 200, 80}}};
    return z < zone_count ? c[z] : std::array<double, 3>{255, 0, 255};
}

// Sheets one above the other, left-aligned, on side_by_side's dark background.
scene::rgb_image stack_rows(const std::vector<scene::rgb_image>& rows) {
    unsigned w = 0, h = 0;
    for (const auto& r : rows) {
        w = std::max(w, r.width);
        h += r.height;
    }
    scene::rgb_image img(w, h, 24);
    unsigned y0 = 0;
    for (const auto& r : rows) {
        for (unsigned y = 0; y < r.height; ++y) std::copy_n(r.at(0, y), 3 * r.width, img.at(0, y0 + y));
        y0 += r.height;
    }
    return img;
}

// ---- Report pieces ----

json stats_json(const error_stats& s) {
    json j;
    j["nmse"] = s.nmse;
    j["psnr_db"] = std::isfinite(s.psnr_db) ? json(s.psnr_db) : json(nullptr);  // null: identical images
    j["max_abs"] = s.max_abs;
    j["pixels"] = s.pixels;
    return j;
}

json ops_json(const scene::op_counts& c, double pixels) {
    const double n = pixels > 0 ? pixels : 1.0;
    return {{"mul", c.mul / n}, {"div", c.div / n}, {"sqrt", c.sqrt / n}, {"add", c.add / n},
            {"cmp", c.cmp / n}, {"long", c.long_ops() / n}};
}

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}
std::string fmt_psnr(double db) { return std::isfinite(db) ? fmt("%.2f", db) : std::string("inf"); }

// Files are written under temporary names in a staging folder inside --out and renamed into place
// only when everything succeeded; on failure the staging folder is removed.
class staged_output {
public:
    explicit staged_output(const std::string& out) : out_(out) {
        fs::create_directories(out_);
        stage_ = out_ / (".render_pipeline.tmp." + std::to_string(::getpid()));
        fs::remove_all(stage_);
        fs::create_directories(stage_);
    }
    ~staged_output() {
        std::error_code ec;
        fs::remove_all(stage_, ec);
    }
    std::string path(const std::string& name) {
        names_.push_back(name);
        return (stage_ / name).string();
    }
    void commit() {
        for (const auto& n : names_) fs::rename(stage_ / n, out_ / n);
        names_.clear();
    }

private:
    fs::path out_, stage_;
    std::vector<std::string> names_;
};

void write_text(const std::string& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    f << text;
    f.close();
    if (!f) throw std::runtime_error("cannot write " + path);
}

// ---- The render ----

int render(const options& o) {
    const auto t_start = std::chrono::steady_clock::now();
    std::map<std::string, double> wall;

    const plan_config cfg = plan_config_of(o);
    validate(cfg);
    const scene::device_config dev{scene::parse_device(o.device),
                                   o.mode == "wrap" ? overflow_mode::wrap : overflow_mode::saturate};
    auto t = std::chrono::steady_clock::now();
    const scene::world s = load_world(o);
    wall["load"] = seconds_since(t);
    const frame_constants k = frame_constants_of(s);

    t = std::chrono::steady_clock::now();
    const scene::rasterised r = scene::rasterise(s);
    wall["rasterise"] = seconds_since(t);
    t = std::chrono::steady_clock::now();
    const plan p = make_plan(r, k, dev, cfg);
    wall["plan"] = seconds_since(t);
    t = std::chrono::steady_clock::now();
    const frame hw = golden_frame(p, k, dev, cfg);
    wall["golden_frame"] = seconds_since(t);
    t = std::chrono::steady_clock::now();
    const frame pp = per_pixel_frame(r, k, dev);
    wall["per_pixel_frame"] = seconds_since(t);
    scene::render_stats sp, sd;
    t = std::chrono::steady_clock::now();
    const scene::shaded_image phong = scene::render_phong(r, &sp);
    wall["phong"] = seconds_since(t);
    t = std::chrono::steady_clock::now();
    const scene::shaded_image devref = scene::render_device(r, dev, &sd);
    wall["device_reference"] = seconds_since(t);
    const hardware_counts hc = hardware_ops(p, cfg, dev, k.n);

    // The SystemC pipeline: the same plan through the hardware, which must give the golden frame.
    json sim_j = {{"ran", false}};
    double sim_clocks_per_px = std::numeric_limits<double>::quiet_NaN(), sim_px_per_s = sim_clocks_per_px;
    double sr_cpu = 0.0, sim_px_per_cpu_s = sim_clocks_per_px;  // by the process's CPU time (wall time counts other processes)
    if (o.sim) {
#if SHADING_PIPELINE_SIM
        sim_options so;
        so.vcd_path = o.vcd;
        parse_abstraction(o.abstraction, so.level);
        if (!o.vcd.empty() && fs::path(o.vcd).has_parent_path()) fs::create_directories(fs::path(o.vcd).parent_path());
        const bool tty = ::isatty(2);
        auto last = std::chrono::steady_clock::now();
        const auto t_sim = last;
        int last_quarter = 0;
        so.progress = [&](std::size_t done, std::size_t total) {
            const auto now = std::chrono::steady_clock::now();
            if (tty) {
                if (std::chrono::duration<double>(now - last).count() < 0.25 && done < total) return;
                last = now;
                std::fprintf(stderr, "\rsim: %zu/%zu pixels (%.0f %%), %.1f s", done, total,
                             total ? 100.0 * done / total : 100.0, seconds_since(t_sim));
                progress_open = done < total;
                if (!progress_open) std::fputc('\n', stderr);
            } else if (total > 0 && seconds_since(t_sim) > 2.0) {
                const int quarter = static_cast<int>(4 * done / total);
                if (quarter > last_quarter) {
                    last_quarter = quarter;
                    std::fprintf(stderr, "sim: %zu/%zu pixels (%d %%), %.1f s\n", done, total, 25 * quarter,
                                 seconds_since(t_sim));
                }
            }
        };
        const sim_result sr = simulate_frame(p, k, dev, cfg, so);
        wall["sim"] = sr.seconds;
        sr_cpu = sr.cpu_seconds;
        // A SystemC warning or error during the run is a failure too (the project's rule), reported
        // by report_log as it happened.
        if (tb::report_log::get().unexpected() != 0) {
            std::fprintf(stderr, "render_pipeline: the SystemC pipeline reported %u warnings or errors\n",
                         tb::report_log::get().unexpected());
            return 1;
        }
        // Bit for bit: every pixel's codes and coverage. (--inject-mismatch: the check must fail.)
        frame golden = hw;
        if (o.inject_mismatch)
            for (std::size_t i = 0; i < golden.px.size(); ++i)
                if (golden.covered[i]) {
                    golden.px[i][1] ^= 1u;
                    break;
                }
        std::size_t diff = 0, first = 0;
        const bool same_size = sr.f.width == golden.width && sr.f.height == golden.height && sr.f.px.size() == golden.px.size();
        if (same_size)
            for (std::size_t i = 0; i < golden.px.size(); ++i)
                if (sr.f.px[i] != golden.px[i] || (!sr.f.covered.empty() && sr.f.covered[i] != golden.covered[i]))
                    if (diff++ == 0) first = i;
        if (!same_size || diff != 0 || sr.mismatches != 0) {
            if (!same_size)
                std::fprintf(stderr, "render_pipeline: the SystemC frame is %ux%u, the golden frame %ux%u\n", sr.f.width,
                             sr.f.height, golden.width, golden.height);
            else if (diff != 0) {
                const auto& a = sr.f.px[first];
                const auto& b = golden.px[first];
                std::fprintf(stderr,
                             "render_pipeline: the SystemC pipeline differs from the golden frame at %zu pixels; first "
                             "at (%zu, %zu): sim %04llx %04llx %04llx, golden %04llx %04llx %04llx\n",
                             diff, first % golden.width, first / golden.width, (unsigned long long)a[0], (unsigned long long)a[1],
                             (unsigned long long)a[2], (unsigned long long)b[0], (unsigned long long)b[1],
                             (unsigned long long)b[2]);
            }
            if (sr.mismatches != 0)
                std::fprintf(stderr, "render_pipeline: the simulation reported %zu mismatches\n", sr.mismatches);
            return 1;
        }
        const double px = static_cast<double>(hc.pixels ? hc.pixels : 1);
        sim_clocks_per_px = sr.clocks / px;
        sim_px_per_s = sr.seconds > 0 ? hc.pixels / sr.seconds : 0.0;
        sim_px_per_cpu_s = sr.cpu_seconds > 0 ? hc.pixels / sr.cpu_seconds : 0.0;
        sim_j = {{"ran", true},          {"abstraction", o.abstraction}, {"clocks", sr.clocks},        {"seconds", sr.seconds},
                 {"pixels", hc.pixels},  {"pixels_per_second", sim_px_per_s},
                 {"cpu_seconds", sr.cpu_seconds}, {"pixels_per_cpu_second", sim_px_per_cpu_s},
                 {"clocks_per_pixel", sim_clocks_per_px}, {"mismatches", 0},
                 {"bit_exact_vs_golden", true}, {"vcd", o.vcd.empty() ? json(nullptr) : json(o.vcd)}};
#else
        throw scene::scene_error("--sim: this build has no SystemC pipeline (target shading_pipeline_sim); use --no-sim");
#endif
    }

    // ---- Errors: the pairs, whole image and per zone ----
    t = std::chrono::steady_clock::now();
    const scene::shaded_image hw_img = to_image(hw), pp_img = to_image(pp);
    struct pair_def {
        const char* key;
        const scene::shaded_image* a;
        const scene::shaded_image* ref;
        const char* what;
    };
    const pair_def pairs[] = {
        {"interpolation", &hw_img, &pp_img, "hardware vs per-pixel shading through the same device (golden)"},
        {"total", &hw_img, &phong, "hardware vs Phong with exact cos^n"},
        {"brdf", &devref, &phong, "device reference (double) vs Phong: the device BRDF's own error"},
        {"sample_stage", &pp_img, &devref,
         "per-pixel golden vs device reference (double): the fixed-point sample stage's own error"},
    };
    std::array<std::size_t, zone_count> zone_px{};
    for (std::size_t i = 0; i < hw.zone.size(); ++i)
        if (hw.covered[i] && hw.zone[i] < zone_count) ++zone_px[hw.zone[i]];
    json errors;
    std::map<std::string, error_stats> whole;
    for (const auto& pd : pairs) {
        json e;
        e["what"] = pd.what;
        const error_stats w = compare(*pd.a, *pd.ref);
        whole[pd.key] = w;
        e["image"] = stats_json(w);
        json zones = json::object();
        for (unsigned z = 0; z < zone_count; ++z)
            if (zone_px[z]) zones[zone_name(z)] = stats_json(compare(*pd.a, *pd.ref, &hw.zone, static_cast<int>(z)));
        e["zones"] = zones;
        errors[pd.key] = e;
    }
    wall["metrics"] = seconds_since(t);

    // ---- Operations per pixel ----
    const double phong_px = static_cast<double>(sp.pixels), hw_px = static_cast<double>(hc.pixels);
    const scene::op_counts hw_total = hc.total();
    const double phong_long = phong_px > 0 ? sp.total().long_ops() / phong_px : 0.0;
    const double hw_long = hw_px > 0 ? hw_total.long_ops() / hw_px : 0.0;
    const double ratio = hw_long > 0 ? phong_long / hw_long : 0.0;
    std::size_t n_deg[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < hw.degree.size(); ++i)
        if (hw.covered[i] && hw.degree[i] < 4) ++n_deg[hw.degree[i]];

    json rep;
    rep["program"] = "render_pipeline";
    const scene::material& mat = s.objects.front().mat;
    const glm::dvec3 lv = s.lights.front().vector;
    rep["config"] = {{"scene", s.name},
                     {"width", r.width},
                     {"height", r.height},
                     {"light", o.light.empty() ? json("scene default") : json(o.light)},
                     {"light_vector", {lv.x, lv.y, lv.z}},
                     {"n", mat.n},
                     {"k_d", {mat.k_d.x, mat.k_d.y, mat.k_d.z}},
                     {"k_s", {mat.k_s.x, mat.k_s.y, mat.k_s.z}},
                     {"ambient", {mat.ambient.x, mat.ambient.y, mat.ambient.z}},
                     {"device", scene::device_name(dev.device)},
                     {"mode", o.mode},
                     {"length", length_policy_name(cfg.length)},
                     {"m", cfg.m},
                     {"m_min", cfg.m_min},
                     {"m_max", cfg.m_max},
                     {"length_tol", cfg.length_tol},
                     {"exact_fallback", cfg.exact_fallback},
                     {"surface_breaks", cfg.surface_breaks},
                     {"degree", degree_policy_name(cfg.degree)},
                     {"degree_tol", cfg.degree_tol},
                     {"eval", evaluator_name(cfg.eval)},
                     {"set", o.set},
                     {"div3", o.div3},
                     {"depth_step", cfg.depth_step},
                     {"sim", o.sim}};
    rep["frame_constants"] = {{"n", k.n}, {"ksi", k.ksi}, {"kdi", k.kdi}, {"ambient", k.ambient}};
    rep["plan"] = {{"intervals", p.jobs.size()},
                   {"pixels", p.pixels},
                   {"geometry_points", p.geometry_points},
                   {"check_samples", p.check_samples},
                   {"samples", hc.samples},
                   {"mean_interval_pixels", p.jobs.empty() ? 0.0 : double(p.pixels) / p.jobs.size()},
                   {"exact_pixels", n_deg[1]},
                   {"quadratic_pixels", n_deg[2]},
                   {"cubic_pixels", n_deg[3]}};
    rep["scene_stats"] = {{"triangles", r.setups.size()}, {"covered_pixels", r.covered_pixels()}};
    rep["errors"] = errors;
    rep["ops_per_pixel"] = {
        {"phong", {{"geometry", ops_json(sp.geometry, phong_px)}, {"shading", ops_json(sp.shading, phong_px)},
                   {"total", ops_json(sp.total(), phong_px)}}},
        {"device_reference", {{"total", ops_json(sd.total(), double(sd.pixels))}}},
        {"hardware", {{"geometry", ops_json(hc.geometry, hw_px)}, {"sample_stage", ops_json(hc.sample_stage, hw_px)},
                      {"interpolation", ops_json(hc.interpolation, hw_px)}, {"total", ops_json(hw_total, hw_px)}}},
        {"phong_long_over_hardware_long", ratio}};
    rep["clocks_per_pixel"] = {{"hardware_ops", hw_px > 0 ? hc.clocks / hw_px : 0.0},
                               {"sim", std::isfinite(sim_clocks_per_px) ? json(sim_clocks_per_px) : json(nullptr)}};
    rep["sim"] = sim_j;

    // ---- Images ----
    staged_output out(o.out);
    std::vector<std::string> written;
    if (o.images) {
        t = std::chrono::steady_clock::now();
        const unsigned w = r.width, h = r.height;
        const scene::rgb_image a = scene::to_rgb8(phong), b = scene::to_rgb8(hw_img), c = scene::to_rgb8(pp_img);
        const scene::rgb_image e1 = scene::heat_map(scene::abs_error(hw_img, pp_img), w, h, o.error_scale, &hw.covered);
        const scene::rgb_image e2 = scene::heat_map(scene::abs_error(hw_img, phong), w, h, o.error_scale_total, &hw.covered);
        const scene::rgb_image dm = shaded_map(hw, phong, [&](std::size_t i) { return degree_colour(hw.degree[i]); });
        const scene::rgb_image im = shaded_map(hw, phong, [&](std::size_t i) { return length_colour(hw.log2_len[i]); });
        const scene::rgb_image zm = shaded_map(hw, phong, [&](std::size_t i) { return zone_colour(hw.zone[i]); });
        // The interval map marks each interval's first pixel darker, so the intervals can be counted.
        scene::rgb_image im_marked = im;
        for (const auto& j : p.jobs)
            if (j.len > 1)
                for (int ch = 0; ch < 3; ++ch) im_marked.at(j.x0, j.y)[ch] = static_cast<uint8_t>(im.at(j.x0, j.y)[ch] / 2);
        auto save = [&](const scene::rgb_image& img, const std::string& name) {
            scene::save_png(img, out.path(name));
            written.push_back(name);
        };
        save(a, "phong.png");
        save(b, "hardware.png");
        save(c, "per_pixel.png");
        save(scene::to_rgb8(devref), "device_reference.png");
        save(e1, "error_interp.png");
        save(e2, "error_total.png");
        save(dm, "degree_map.png");
        save(im_marked, "interval_map.png");
        save(zm, "zone_map.png");
        char l_hw[96], l_e1[64], l_e2[64];
        std::snprintf(l_hw, sizeof l_hw, "HARDWARE: %s%s, %s, %s, %s", o.length.c_str(),
                      cfg.length == length_policy::fixed ? (" M=" + std::to_string(cfg.m)).c_str() : "", o.degree.c_str(),
                      o.eval.c_str(), o.device.c_str());
        std::snprintf(l_e1, sizeof l_e1, "VS PER-PIXEL (WHITE = %g)", o.error_scale);
        std::snprintf(l_e2, sizeof l_e2, "VS PHONG (WHITE = %g)", o.error_scale_total);
        save(stack_rows({scene::side_by_side({a, b, dm}, {"PHONG N=" + std::to_string(mat.n), l_hw, "DEGREE"}),
                         scene::side_by_side({e2, e1, im_marked}, {l_e2, l_e1, "INTERVAL LENGTH 2 POWER M"})}),
             "sheet.png");
        wall["images"] = seconds_since(t);
    }
    wall["total"] = seconds_since(t_start);
    rep["wall_seconds"] = wall;
    rep["files"] = written;

    // ---- report.md ----
    std::ostringstream md;
    md << "# Shading pipeline report: " << s.name << ", " << r.width << "x" << r.height << "\n\n";
    md << "Configuration: device " << scene::device_name(dev.device) << " (" << o.mode << "), n = " << mat.n
       << ", length " << length_policy_name(cfg.length);
    if (cfg.length == length_policy::fixed)
        md << " (m = " << cfg.m << ", " << (1u << cfg.m) << " pixels)";
    else
        md << " (m " << cfg.m_min << ".." << cfg.m_max << ", tolerance " << cfg.length_tol << " levels, exact fallback "
           << (cfg.exact_fallback ? "on" : "off") << ")";
    md << ", degree " << degree_policy_name(cfg.degree);
    if (cfg.degree == degree_policy::adaptive) md << " (tolerance " << cfg.degree_tol << ")";
    md << ", evaluator " << evaluator_name(cfg.eval) << ", sample set " << o.set << ", /3 " << o.div3
       << ", depth step " << cfg.depth_step << (cfg.surface_breaks ? ", segments also end at folds" : "") << ".\n\n";
    md << "Plan: " << p.jobs.size() << " intervals over " << p.pixels << " covered pixels (mean "
       << fmt("%.2f", p.jobs.empty() ? 0.0 : double(p.pixels) / p.jobs.size()) << " pixels), " << hc.samples
       << " samples through the sample stage; pixels exact " << n_deg[1] << ", quadratic " << n_deg[2] << ", cubic "
       << n_deg[3] << ".\n\n";
    md << "## Errors (8-bit levels, covered pixels, three channels)\n\n";
    md << "| pair | what | NMSE | PSNR dB | max |\n|---|---|---|---|---|\n";
    for (const auto& pd : pairs) {
        const error_stats& w = whole[pd.key];
        md << "| " << pd.key << " | " << pd.what << " | " << fmt("%.3e", w.nmse) << " | " << fmt_psnr(w.psnr_db)
           << " | " << fmt("%.2f", w.max_abs) << " |\n";
    }
    md << "\n### Per zone (NMSE; the zone map shows them)\n\n| zone | pixels |";
    for (const auto& pd : pairs) md << ' ' << pd.key << " |";
    md << "\n|---|---|";
    for (std::size_t i = 0; i < std::size(pairs); ++i) md << "---|";
    md << '\n';
    for (unsigned z = 0; z < zone_count; ++z) {
        if (!zone_px[z]) continue;
        md << "| " << zone_name(z) << (zone_is_quadratic(z) ? " (quadratic under zones)" : "") << " | " << zone_px[z]
           << " |";
        for (const auto& pd : pairs) md << ' ' << fmt("%.3e", errors[pd.key]["zones"][zone_name(z)]["nmse"].get<double>()) << " |";
        md << '\n';
    }
    md << "\n## Operations per pixel (counted)\n\n| path | mul | div | sqrt | add | long (mul+div+sqrt) |\n"
          "|---|---|---|---|---|---|\n";
    auto ops_row = [&](const std::string& name, const scene::op_counts& c, double n) {
        md << "| " << name << " | " << fmt("%.2f", c.mul / n) << " | " << fmt("%.2f", c.div / n) << " | "
           << fmt("%.2f", c.sqrt / n) << " | " << fmt("%.2f", c.add / n) << " | " << fmt("%.2f", c.long_ops() / n)
           << " |\n";
    };
    if (phong_px > 0 && hw_px > 0) {
        ops_row("Phong: geometry", sp.geometry, phong_px);
        ops_row("Phong: shading", sp.shading, phong_px);
        ops_row("**Phong: total**", sp.total(), phong_px);
        ops_row("hardware: geometry side", hc.geometry, hw_px);
        ops_row("hardware: sample stage", hc.sample_stage, hw_px);
        ops_row("hardware: interpolation", hc.interpolation, hw_px);
        ops_row("**hardware: total**", hw_total, hw_px);
    }
    md << "\nPhong's long operations / the hardware path's: **" << fmt("%.2f", ratio) << "x**.\n\n";
    md << "Clocks per pixel (evaluator, counted): " << fmt("%.3f", hw_px > 0 ? hc.clocks / hw_px : 0.0);
    if (sim_j["ran"].get<bool>())
        md << "; simulated: " << fmt("%.3f", sim_clocks_per_px) << " clocks per pixel, "
           << fmt("%.0f", sim_px_per_s) << " pixels per second (" << fmt("%.2f", wall["sim"])
           << " s wall; " << fmt("%.0f", sim_px_per_cpu_s) << " per CPU second, " << fmt("%.2f", sr_cpu) << " s; "
           << o.abstraction << " abstraction), bit-exact against the golden frame";
    else
        md << "; SystemC pipeline not run (--no-sim)";
    md << ".\n\n## Images\n\n"
          "- phong.png: Phong with exact cos^n (double, per pixel); device_reference.png: the same with the device's "
          "specular term (double geometry); per_pixel.png: the golden sample stage at every pixel (the interpolation's "
          "reference); hardware.png: the frame buffer of the pipeline.\n"
          "- error_interp.png: |hardware - per-pixel| per pixel (largest channel), white = "
       << o.error_scale << " levels; error_total.png: |hardware - Phong|, white = " << o.error_scale_total
       << " levels (black, blue, red, yellow, white).\n"
          "- degree_map.png: exact pixels white, quadratic orange, cubic blue. interval_map.png: interval length 2^m: "
          "exact white, m=2 red, 3 orange, 4 green, 5 cyan, 6 violet; each interval's first pixel darker. "
          "zone_map.png: other grey, forehead light blue, brows brown, eyes cyan, nose red, cheeks tan, mouth magenta, "
          "chin green.\n"
          "- sheet.png: Phong, hardware and the degree map above; the errors against Phong and against per-pixel "
          "shading and the interval map below.\n\n";
    md << "Wall times (s):";
    for (const auto& [name, sec] : wall) md << ' ' << name << ' ' << fmt("%.3f", sec) << ';';
    md << '\n';

    if (!o.md_name.empty()) write_text(out.path(o.md_name), md.str());
    if (!o.json_name.empty()) write_text(out.path(o.json_name), rep.dump(2) + "\n");
    out.commit();

    std::printf("%s %ux%u: %zu intervals, %zu pixels; device %s (%s), n = %u\n", s.name.c_str(), r.width, r.height,
                p.jobs.size(), p.pixels, scene::device_name(dev.device), o.mode.c_str(), mat.n);
    for (const auto& pd : pairs) {
        const error_stats& w = whole[pd.key];
        std::printf("  %-13s NMSE %.3e  PSNR %s dB  max %.2f  (%s)\n", pd.key, w.nmse, fmt_psnr(w.psnr_db).c_str(),
                    w.max_abs, pd.what);
    }
    std::printf("  long ops/pixel: Phong %.2f, hardware %.2f (geometry %.2f, sample stage %.2f, interpolation %.2f); "
                "ratio %.2f\n",
                phong_long, hw_long, hw_px > 0 ? hc.geometry.long_ops() / hw_px : 0.0,
                hw_px > 0 ? hc.sample_stage.long_ops() / hw_px : 0.0, hw_px > 0 ? hc.interpolation.long_ops() / hw_px : 0.0,
                ratio);
    if (sim_j["ran"].get<bool>())
        std::printf("  sim (%s): bit-exact, %.3f clocks/pixel, %.0f pixels/s (%.2f s), %.0f pixels per CPU second "
                    "(%.2f s)\n", o.abstraction.c_str(), sim_clocks_per_px, sim_px_per_s, wall["sim"], sim_px_per_cpu_s,
                    sr_cpu);
    std::string files = written.empty() ? "" : "*.png";
    for (const std::string& n : {o.md_name, o.json_name})
        if (!n.empty()) files += (files.empty() ? "" : ", ") + n;
    std::printf("  wall %.2f s; wrote %s/{%s}\n", wall["total"], o.out.c_str(), files.c_str());
    return 0;
}

// ---- The sweep ----

struct sweep_point {
    std::string device, length, degree, eval;
    unsigned m = 4;
    double length_tol = 0.5, degree_tol = 0.25;
    int n = -1;  // -1: --n or the scene's
};

// small: two devices x the degree policies x fixed m = 3..5 and three adaptive-length tolerances,
// each with the Horner unit and the forward differences; full: every device, m = 2..6, five tolerances, three adaptive-degree tolerances;
// exponents: every device x n = 2..500 with the command line's own plan settings (the total error
// against Phong per device and n).
std::vector<sweep_point> sweep_grid(const std::string& grid, const std::string& only_device, const options& o) {
    std::vector<std::string> devices = grid != "small" ? scene::device_names() : std::vector<std::string>{"patent", "minimax"};
    if (!only_device.empty()) devices = {only_device};
    if (grid == "exponents") {
        std::vector<sweep_point> g;
        for (const auto& d : devices)
            for (int n : {2, 5, 10, 20, 50, 100, 200, 500})
                g.push_back({d, o.length, o.degree, o.eval, o.pc.m, o.pc.length_tol, o.pc.degree_tol, n});
        return g;
    }
    const std::vector<unsigned> ms = grid == "full" ? std::vector<unsigned>{2, 3, 4, 5, 6} : std::vector<unsigned>{3, 4, 5};
    const std::vector<double> ltols = grid == "full" ? std::vector<double>{0.125, 0.25, 0.5, 1.0, 2.0}
                                                     : std::vector<double>{0.25, 0.5, 1.0};
    const std::vector<std::pair<std::string, double>> degrees =
        grid == "full" ? std::vector<std::pair<std::string, double>>{{"cubic", 0.5},     {"quadratic", 0.5},
                                                                     {"zones", 0.5},    {"adaptive", 0.25},
                                                                     {"adaptive", 0.5},  {"adaptive", 1.0}}
                       : std::vector<std::pair<std::string, double>>{
                             {"cubic", 0.5}, {"quadratic", 0.5}, {"zones", 0.5}, {"adaptive", 0.5}};
    std::vector<sweep_point> g;
    for (const auto& d : devices)
        for (const auto& [deg, dtol] : degrees) {
            for (unsigned m : ms)
                for (const char* ev : {"horner", "fd"}) g.push_back({d, "fixed", deg, ev, m, 0.5, dtol});
            for (double lt : ltols)
                for (const char* ev : {"horner", "fd"}) g.push_back({d, "adaptive", deg, ev, 4, lt, dtol});
        }
    return g;
}

std::string num(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

int run_sweep(const options& o) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<sweep_point> grid = sweep_grid(o.grid, !o.device_given || o.device == "all" ? "" : o.device, o);
    const unsigned jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
    // Checked once here, so a bad scene is one message and not one per child.
    {
        options probe = o;
        probe.size = 8;
        (void)load_world(probe);
    }
    std::error_code ec;
    const std::string self = fs::read_symlink("/proc/self/exe", ec).string();
    if (ec) throw std::runtime_error("cannot find this program's path (/proc/self/exe)");
    fs::create_directories(o.out);
    const fs::path tmp = fs::path(o.out) / (".sweep.tmp." + std::to_string(::getpid()));
    fs::remove_all(tmp);
    fs::create_directories(tmp);

    auto args_of = [&](std::size_t i) {
        const sweep_point& sp = grid[i];
        std::vector<std::string> a = {self, "--scene", o.scene, "--data-dir", o.data_dir, "--size", std::to_string(o.size),
                                      "--device", sp.device, "--mode", o.mode, "--length", sp.length, "--m",
                                      std::to_string(sp.m), "--m-min", std::to_string(o.pc.m_min), "--m-max",
                                      std::to_string(o.pc.m_max),
                                      "--length-tol", num(sp.length_tol), "--degree", sp.degree, "--degree-tol",
                                      num(sp.degree_tol), "--eval", sp.eval, "--set", o.set, "--div3", o.div3,
                                      "--depth-step", num(o.pc.depth_step),
                                      o.pc.exact_fallback ? "--exact-fallback" : "--no-exact-fallback",
                                      o.pc.surface_breaks ? "--surface-breaks" : "--no-surface-breaks", "--no-sim", "--no-images", "--md", "",
                                      "--json", "report.json", "--out", (tmp / std::to_string(i)).string()};
        if (!o.light.empty()) a.insert(a.end(), {"--light", o.light});
        const int n = sp.n != -1 ? sp.n : o.n;
        if (n != -1) a.insert(a.end(), {"--n", std::to_string(n)});
        if (!o.kd.empty()) a.insert(a.end(), {"--kd", o.kd});
        if (!o.ks.empty()) a.insert(a.end(), {"--ks", o.ks});
        if (!o.ambient.empty()) a.insert(a.end(), {"--ambient", o.ambient});
        return a;
    };
    auto spawn = [&](std::size_t i) -> pid_t {
        const std::vector<std::string> a = args_of(i);
        std::vector<char*> argv;
        for (const auto& s : a) argv.push_back(const_cast<char*>(s.c_str()));
        argv.push_back(nullptr);
        const std::string log = (tmp / (std::to_string(i) + ".log")).string();
        posix_spawn_file_actions_t fa;
        posix_spawn_file_actions_init(&fa);
        posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_adddup2(&fa, 1, 2);
        pid_t pid = -1;
        const int rc = posix_spawn(&pid, self.c_str(), &fa, nullptr, argv.data(), environ);
        posix_spawn_file_actions_destroy(&fa);
        if (rc != 0) throw std::runtime_error("posix_spawn failed: " + std::string(std::strerror(rc)));
        return pid;
    };

    std::map<pid_t, std::size_t> running;
    std::vector<std::size_t> failed;
    std::size_t next = 0, done = 0;
    const bool tty = ::isatty(2);
    auto progress = [&](bool final) {
        progress_open = tty && !final;
        if (tty)
            std::fprintf(stderr, "\rsweep: %zu/%zu configurations done, %zu running, %zu failed, %.0f s%s", done,
                         grid.size(), running.size(), failed.size(), seconds_since(t0), final ? "\n" : "");
        else if (final || (done < grid.size() && done % std::max<std::size_t>(1, grid.size() / 10) == 0))
            std::fprintf(stderr, "sweep: %zu/%zu configurations done, %zu failed, %.0f s\n", done, grid.size(),
                         failed.size(), seconds_since(t0));
    };
    std::fprintf(stderr, "sweep: %zu configurations of %s %ux%u in %u processes\n", grid.size(), o.scene.c_str(),
                 o.size, o.size, jobs);
    while (done < grid.size()) {
        while (running.size() < jobs && next < grid.size()) {
            running[spawn(next)] = next;
            ++next;
        }
        int status = 0;
        const pid_t pid = ::waitpid(-1, &status, 0);
        if (pid < 0) throw std::runtime_error("waitpid failed");
        auto it = running.find(pid);
        if (it == running.end()) continue;
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) failed.push_back(it->second);
        running.erase(it);
        ++done;
        progress(false);
    }
    progress(true);
    if (!failed.empty()) {
        std::fprintf(stderr, "render_pipeline: %zu sweep configurations failed; logs kept in %s:\n", failed.size(),
                     tmp.c_str());
        for (std::size_t i : failed) {
            std::string cmd;
            for (const auto& s : args_of(i)) cmd += s + ' ';
            std::fprintf(stderr, "  %zu.log: %s\n", i, cmd.c_str());
        }
        return 1;
    }

    // One CSV row per configuration, from each child's report.json.
    std::ostringstream csv;
    csv << "scene,size,n,device,mode,length,m,m_min,m_max,length_tol,degree,degree_tol,eval,set,"
           "nmse_interp,psnr_interp,max_interp,nmse_phong,max_phong,nmse_brdf,"
           "long_per_px,mul_per_px,div_per_px,sqrt_per_px,add_per_px,interp_long_per_px,clocks_per_px,"
           "phong_long_per_px,phong_add_per_px,ratio_long,intervals,mean_len,quadratic_px,cubic_px,exact_px\n";
    csv.precision(6);
    for (std::size_t i = 0; i < grid.size(); ++i) {
        std::ifstream f(tmp / std::to_string(i) / "report.json");
        json j;
        try {
            j = json::parse(f);
        } catch (const std::exception& e) {
            throw std::runtime_error("sweep configuration " + std::to_string(i) + ": unreadable report.json: " + e.what());
        }
        const json& c = j["config"];
        const json& e = j["errors"];
        const json& hw = j["ops_per_pixel"]["hardware"];
        const json& ph = j["ops_per_pixel"]["phong"]["total"];
        auto d = [](const json& v) { return v.is_null() ? std::string("inf") : num(v.get<double>()); };
        csv << c["scene"].get<std::string>() << ',' << c["width"].get<unsigned>() << ',' << c["n"].get<unsigned>() << ','
            << c["device"].get<std::string>() << ',' << c["mode"].get<std::string>() << ','
            << c["length"].get<std::string>() << ',' << c["m"].get<unsigned>() << ',' << c["m_min"].get<unsigned>()
            << ',' << c["m_max"].get<unsigned>() << ',' << num(c["length_tol"].get<double>()) << ','
            << c["degree"].get<std::string>() << ',' << num(c["degree_tol"].get<double>()) << ','
            << c["eval"].get<std::string>() << ',' << c["set"].get<std::string>() << ','
            << num(e["interpolation"]["image"]["nmse"].get<double>()) << ','
            << d(e["interpolation"]["image"]["psnr_db"]) << ','
            << num(e["interpolation"]["image"]["max_abs"].get<double>()) << ','
            << num(e["total"]["image"]["nmse"].get<double>()) << ',' << num(e["total"]["image"]["max_abs"].get<double>())
            << ',' << num(e["brdf"]["image"]["nmse"].get<double>()) << ','
            << num(hw["total"]["long"].get<double>()) << ',' << num(hw["total"]["mul"].get<double>()) << ','
            << num(hw["total"]["div"].get<double>()) << ',' << num(hw["total"]["sqrt"].get<double>()) << ','
            << num(hw["total"]["add"].get<double>()) << ',' << num(hw["interpolation"]["long"].get<double>()) << ','
            << num(j["clocks_per_pixel"]["hardware_ops"].get<double>()) << ',' << num(ph["long"].get<double>()) << ','
            << num(ph["add"].get<double>()) << ',' << num(j["ops_per_pixel"]["phong_long_over_hardware_long"].get<double>())
            << ',' << j["plan"]["intervals"].get<std::size_t>() << ','
            << num(j["plan"]["mean_interval_pixels"].get<double>()) << ','
            << j["plan"]["quadratic_pixels"].get<std::size_t>() << ',' << j["plan"]["cubic_pixels"].get<std::size_t>()
            << ',' << j["plan"]["exact_pixels"].get<std::size_t>() << '\n';
    }
    const std::string csv_path = o.csv.empty() ? (fs::path(o.out) / "sweep.csv").string() : o.csv;
    if (fs::path(csv_path).has_parent_path()) fs::create_directories(fs::path(csv_path).parent_path());
    const std::string csv_tmp = csv_path + ".tmp." + std::to_string(::getpid());
    write_text(csv_tmp, csv.str());
    fs::rename(csv_tmp, csv_path);
    fs::remove_all(tmp);
    std::printf("sweep: %zu configurations of %s %ux%u in %.1f s (%u processes); wrote %s\n", grid.size(),
                o.scene.c_str(), o.size, o.size, seconds_since(t0), jobs, csv_path.c_str());
    return 0;
}

options g_options;  // handed from main() to sc_main() when the SystemC pipeline runs

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
        validate(plan_config_of(o));
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

int run(const options& o) {
    try {
        return o.sweep ? run_sweep(o) : render(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%srender_pipeline: %s\n", progress_open ? "\n" : "", e.what());
        return 1;
    }
}

}  // namespace

#if SHADING_PIPELINE_SIM
// SystemC's reports through the testbenches' log: info (the kernel's "stopped by user") silent,
// warnings and errors shown with their ids and counted.
int sc_main(int, char*[]) {
    shading::tb::report_log::install();
    return run(g_options);
}
#endif

int main(int argc, char* argv[]) {
    options& o = g_options;
    CLI::App app{"Seed 004's shading system: a scene through the planned, interpolating pipeline (golden model and "
                 "SystemC), against per-pixel and Phong references; PNGs and a report. --sweep: a grid of "
                 "configurations in parallel processes, one CSV."};
    app.add_option("--scene", o.scene, "built-in scene (sphere, torus, head) or a path to an OBJ file");
    app.add_option("--size", o.size, "image width and height in pixels (1.." + std::to_string(max_size) + ")")
        ->check(CLI::Range(1u, max_size));
    app.add_option("--data-dir", o.data_dir, "repository root holding data/head/ (for the built-in head)");
    app.add_option("--light", o.light, "one directional light from azimuth,elevation (degrees; azimuth towards +x "
                                       "from +z); default: the scene's light");
    app.add_option("--n", o.n, "the material's exponent n (1..1000); default: the scene's")->check(CLI::Range(1, 1000));
    app.add_option("--kd", o.kd, "k_d: one value or r,g,b in [0, 1]");
    app.add_option("--ks", o.ks, "k_s: one value or r,g,b in [0, 1]");
    app.add_option("--ambient", o.ambient, "ambient: one value or r,g,b in [0, 1]");
    app.add_option("--length", o.length, "interval length policy")->check(CLI::IsMember({"fixed", "adaptive"}));
    app.add_option("--m", o.pc.m, "fixed length: intervals of 2^m pixels");
    app.add_option("--m-min", o.pc.m_min, "adaptive length: shortest interval 2^m_min");
    app.add_option("--m-max", o.pc.m_max, "adaptive length: longest interval 2^m_max");
    app.add_option("--length-tol", o.pc.length_tol, "adaptive length: largest accepted error estimate (8-bit levels)");
    app.add_flag("--exact-fallback,!--no-exact-fallback", o.pc.exact_fallback,
                 "adaptive length: exact pixels where even 2^m_min misses the tolerance (default on)");
    app.add_flag("--surface-breaks,!--no-surface-breaks", o.pc.surface_breaks,
                 "also end segments at folds (neighbouring pixels' triangles share no vertex; default on)");
    app.add_option("--degree", o.degree, "degree policy")
        ->check(CLI::IsMember({"cubic", "quadratic", "zones", "adaptive"}));
    app.add_option("--degree-tol", o.pc.degree_tol, "adaptive degree: largest accepted quadratic error estimate");
    app.add_option("--eval", o.eval, "evaluator: the Fig. 4 Horner unit or our forward differences")
        ->check(CLI::IsMember({"horner", "fd"}));
    app.add_option("--set", o.set, "cubic sample points: case1 (0, 1/4, 1/2, 1) or case2 (0, 1/2, 3/4, 1)")
        ->check(CLI::IsMember({"case1", "case2"}));
    app.add_option("--div3", o.div3, "division by 3 in the coefficient unit")->check(CLI::IsMember({"shift_add", "exact"}));
    app.add_option("--device", o.device, "specular device: patent, minimax, rom_matched, ua22802, squared (--sweep: default all of the grid's)")
        ->check(CLI::IsMember({"patent", "minimax", "rom_matched", "ua22802", "squared", "all"}));
    app.add_option("--mode", o.mode, "overflow mode of the device's ADD11")->check(CLI::IsMember({"saturate", "wrap"}));
    app.add_option("--depth-step", o.pc.depth_step, "depth jump (world units) that ends a segment of a raster line")
        ->check(CLI::PositiveNumber);
    app.add_option("--out", o.out, "output folder");
    app.add_flag("--sim,!--no-sim", o.sim, "run the SystemC pipeline and require its frame to equal the golden one "
                                           "(default on)");
    app.add_flag("--images,!--no-images", o.images, "write the PNGs (default on)");
    app.add_option("--vcd", o.vcd, "with --sim: VCD file of the SystemC pipeline");
    app.add_option("--abstraction", o.abstraction,
                   "with --sim: the SystemC pipeline's level: block (every block of the figures, default) or fast "
                   "(the same pins and timing at them, one process)")
        ->check(CLI::IsMember({"block", "fast"}));
    app.add_option("--json", o.json_name, "report file name in --out (empty: none)");
    app.add_option("--md", o.md_name, "Markdown report file name in --out (empty: none)");
    app.add_option("--error-scale", o.error_scale, "error vs per-pixel shown white in error_interp.png (8-bit levels)")
        ->check(CLI::PositiveNumber);
    app.add_option("--error-scale-total", o.error_scale_total, "error vs Phong shown white in error_total.png")
        ->check(CLI::PositiveNumber);
    app.add_flag("--sweep", o.sweep, "run the grid of configurations on the golden model, one CSV (--csv)");
    app.add_option("--jobs", o.jobs, "--sweep: parallel processes (default: the hardware's cores)");
    app.add_option("--grid", o.grid, "--sweep: small, full, or exponents (every device x n = 2..500, this command's plan settings)")
        ->check(CLI::IsMember({"small", "full", "exponents"}));
    app.add_option("--csv", o.csv, "--sweep: CSV path (default: <out>/sweep.csv)");
    app.add_flag("--inject-mismatch", o.inject_mismatch, "")->group("");
    bool sim_available = false;
    app.add_flag("--sim-available", sim_available, "exit 0 if this build has the SystemC pipeline (--sim), 1 if not");
    SHADING_CLI_PARSE(app, argc, argv);  // help 0, a bad option 2 (common/exit_status.h)
    if (sim_available) return SHADING_PIPELINE_SIM ? 0 : 1;
    o.device_given = app.count("--device") > 0;
    if (const std::string why = usage_problem(o); !why.empty()) {
        std::fprintf(stderr, "render_pipeline: %s\n", why.c_str());
        return tb::exit_usage;
    }
#if SHADING_PIPELINE_SIM
    if (o.sim && !o.sweep) {
        ::setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
        return sc_core::sc_elab_and_sim(argc, argv);
    }
#endif
    return run(o);
}
