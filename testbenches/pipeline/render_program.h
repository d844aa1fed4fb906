// render_pipeline's parts (testbenches/pipeline/), split by what they do:
//   render_pipeline.cpp   the command line, main and sc_main
//   render_setup.cpp      options to a scene and a plan configuration
//   render_run.cpp        one render: plan, golden frame, references, SystemC run, comparisons, counts
//   render_report.cpp     report.json, report.md and the summary printed
//   render_images.cpp     the PNGs
//   render_sweep.cpp      --sweep: the grids, shards, --emit-jobs, child processes and the CSV
// All but render_pipeline.cpp are the library shading_render, which a study may render with in
// place of make_plan's plan (plan_maker: studies/yardsticks/yardstick_study).
#pragma once

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "testbenches/options/render_options.h"
#include "golden_pipeline/pipeline.h"
#include "scene/image.h"
#include "scene/raster.h"
#include "scene/shade.h"

namespace shading::render_program {

using json = nlohmann::json;
using namespace shading::pipeline;

// True while a progress line on a terminal has no newline yet (an error message then starts a new line).
extern bool progress_open;

double seconds_since(std::chrono::steady_clock::time_point t0);
plan_config plan_config_of(const options& o);
// --kd/--ks/--ambient ("v" or "r,g,b" in [0, 1]) and --light ("azimuth,elevation" in degrees); a
// value that does not parse throws scene::scene_error naming the option.
scene::rgb parse_colour(const std::string& opt, const std::string& s);
glm::dvec3 parse_light(const std::string& s);
// --shard "I/N" as (I - 1, N); throws scene::scene_error unless 1 <= I <= N.
std::pair<std::size_t, std::size_t> parse_shard(const std::string& s);
// Throws scene_error for a bad size, scene, light, material value.
scene::world load_world(const options& o);
// Bad usage found from the command line alone, before any work (exit 2, common/exit_status.h): an
// unknown built-in scene, a light or colour that does not parse, a plan the units cannot run. Empty
// when none. A missing or malformed OBJ file is found later, and is a failure (exit 1).
std::string usage_problem(const options& o);

struct render_data;

// A plan made otherwise than by make_plan (a study's yardstick), rendered, simulated and reported as
// a policy's plan is: the name and the fact the report gives for its length policy, a note for
// report.md's length settings, what it adds to report.json and, after report.md's plan line, a
// paragraph. make is called with d.r, d.k, d.dev and d.cfg set.
struct plan_maker {
    std::string length_name;
    bool runs_on_geometry_side = false;
    std::string length_note;
    std::function<plan(const render_data& d)> make;
    std::function<void(const render_data& d, json& report)> add_json;
    std::function<std::string(const render_data& d)> md_after_plan;
};

// Everything one render computed, for the report and the images.
struct render_data {
    const plan_maker* maker = nullptr;  // null: make_plan's plan
    plan_config cfg;
    scene::device_config dev;
    scene::world s;
    scene::rasterised r;
    frame_constants k;
    plan p;
    frame hw, pp;
    scene::shaded_image phong, devref, hw_img, pp_img;
    scene::render_stats sp, sl, sd;  // Phong from scratch, scan-line Phong, device reference
    scene::stepping_stats sl_steps;
    hardware_counts hc, hc_other;    // the configured geometry unit, and the other one
    json sim_j = {{"ran", false}};
    double sim_clocks_per_px = 0.0, sim_px_per_s = 0.0, sr_cpu = 0.0, sim_px_per_cpu_s = 0.0;
    std::map<std::string, double> wall;
    // The compared pairs, whole image (NMSE etc.) and their JSON with the zones.
    struct pair_def {
        const char* key;
        const scene::shaded_image* a;
        const scene::shaded_image* ref;
        const char* what;
    };
    std::vector<pair_def> pairs;
    std::map<std::string, error_stats> whole;
    json errors;
    std::vector<std::size_t> zone_px;
    // The 8-bit displayed images (rounded, as the PNGs): their NMSE beside the frame buffer's.
    error_stats interp_8bit, total_8bit;
    std::vector<std::string> written;  // the PNGs
};

// One render (render_run.cpp): returns the process's exit status. With a maker, its plan.
int render(const options& o, const plan_maker* maker = nullptr);
// The comparisons of a finished render (render_run.cpp).
void compare_all(render_data& d);
// report.json (render_report.cpp).
json report_json(const options& o, const render_data& d);
// report.md and the printed summary.
std::string report_md(const options& o, const render_data& d);
void print_summary(const options& o, const render_data& d);
// The PNGs into the staging folder; names appended to d.written (render_images.cpp).
class staged_output;
void write_images(const options& o, render_data& d, staged_output& out);
// An image as the 8-bit display shows it: each value rounded to an integer level.
scene::shaded_image displayed(const scene::shaded_image& img);

// The sweep (render_sweep.cpp).
int run_sweep(const options& o);

// Report pieces.
json stats_json(const error_stats& s);
// "4 / 16 / 64" (error_levels) and a stats' pixels beyond them, "12 / 3 / 0": the report's columns.
std::string over_levels_text();
std::string over_counts_text(const error_stats& s);
json ops_json(const scene::op_counts& c, double pixels);
std::string fmt(const char* f, double v);
std::string fmt_psnr(double db);
std::string num(double v);
void write_text(const std::string& path, const std::string& text);

// Files are written under temporary names in a staging folder inside --out and renamed into place
// only when everything succeeded; on failure the staging folder is removed.
class staged_output {
public:
    explicit staged_output(const std::string& out);
    ~staged_output();
    std::string path(const std::string& name);
    void commit();

private:
    std::string out_, stage_;
    std::vector<std::string> names_;
};

}  // namespace shading::render_program
