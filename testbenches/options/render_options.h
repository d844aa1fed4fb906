// render_pipeline's command line (testbenches/pipeline/render_pipeline.cpp) as a plain struct, and
// its parse function (render_options.cpp, the options library's only source that needs the
// plan's settings): the struct filled, an exit status returned when the program must stop (0 after
// --help, 2 for bad usage), nothing when it runs. The checks that need the scene library (a built-in
// scene's name, a light or colour that parses, a plan the units can run) stay in the program. The
// options come in groups (its --help shows them apart), which a program that renders as
// render_pipeline does (a study's) may add to its own CLI11 App.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "golden_pipeline/pipeline.h"
#include "testbenches/options/tool_options.h"

namespace CLI {
class App;
}

namespace shading::render_program {

using pipeline::plan_config;

// The largest --size: a frame costs about 250 bytes per pixel here (depth and triangle buffers, the
// reference and hardware images as doubles, the frames' codes, the maps), so 4096 x 4096 needs
// about 4 GB; beyond that the program refuses rather than failing half-way through.
constexpr unsigned max_size = 4096;

struct options {
    std::string scene = "head", data_dir = tb::default_data_dir(), out = "out/pipeline";
    unsigned size = 256;
    std::string light;                  // "azimuth,elevation" in degrees; empty: the scene's own
    int n = -1;                         // -1: the scene's material
    std::string kd, ks, ambient;        // "v" or "r,g,b" in [0, 1]; empty: the scene's material
    std::string length = "fixed", degree = "cubic", eval = "horner", set = "case1", div3 = "shift_add";
    std::string unit = "stepped";       // the geometry side's unit: stepped or scratch
    plan_config pc;                     // the numeric and boolean settings, defaults from pipeline.h
    std::string device = "sqmul", mode = "saturate";  // the device table's pick for the pipeline (docs/devices.md)
    bool device_given = false;          // --sweep: without --device, the grid's devices
    bool sim = true, images = true;
    std::string abstraction = "block";  // the SystemC pipeline's level: block or fast (interp/abstraction.h)
    std::string vcd, json_name = "report.json", md_name = "report.md";
    double error_scale = 2.0, error_scale_total = 16.0;
    bool inject_mismatch = false;       // (hidden, for the tests) corrupt one golden pixel before the comparison
    // --sweep
    bool sweep = false;
    unsigned jobs = 0;
    std::string grid = "small", csv;
    std::string shard;                  // "I/N": only the configurations i with i % N == I - 1
    bool emit_jobs = false;             // print one command line per configuration instead of running
    // --grid claims: the lists (a light is "azimuth,elevation")
    std::vector<std::string> claims_scenes{"head", "sphere", "torus"}, claims_lights{"-40,25", "35,20", "10,60"};
    std::vector<int> claims_ns{5, 20, 100, 500};
    std::vector<unsigned> claims_sizes{512, 1024};
    bool sim_available = false;         // --sim-available: only report whether --sim is built in
    std::vector<std::string> argv;      // the command line, for --emit-jobs
};

std::optional<int> parse_render_pipeline(int argc, char** argv, options& o);

// The groups: the scene (--scene, --size, --light, the material), the device (the specular device and
// the units it is built with: evaluator, coefficient unit, sample stage, geometry unit), the plan
// (length and degree policies and their settings; with `length` false, no --length: the caller
// chooses the length its own way), the simulation, the output, the sweep.
void add_scene_options(CLI::App& app, options& o);
void add_device_options(CLI::App& app, options& o);
void add_plan_options(CLI::App& app, options& o, bool length = true);
void add_simulation_options(CLI::App& app, options& o);
void add_output_options(CLI::App& app, options& o);
void add_sweep_options(CLI::App& app, options& o);
// What a parse leaves to set once it succeeded: the command line (--emit-jobs), whether --device was given.
void record_command_line(const CLI::App& app, int argc, char** argv, options& o);

// render_pipeline_rtl (testbenches/rtl/): a scene's planned frame through the shading pipeline's
// Verilog twin beside the SystemC model. The scene options are render_pipeline's (add_scene_options:
// --scene, --size, --data-dir, --light and the material, in `scene`); variant: the verilated
// variant, horner, fd_any or fd_m4 (testbenches/rtl/rtl_pipeline_variants.h).
struct rtl_frame_options {
    options scene;
    std::string variant = "fd_any";
    std::string degree = "cubic";  // the plan's degree policy: cubic or quadratic
};
std::optional<int> parse_render_pipeline_rtl(int argc, char** argv, rtl_frame_options& o);

}  // namespace shading::render_program
