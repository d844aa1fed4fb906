// The studies' and tools' command lines (tool_options.h) parsed with CLI11, with the same names,
// checks and help texts the programs had when each built its own CLI11 App.
#include "tool_options.h"

#include <algorithm>
#include <filesystem>

#include "cli_parse.h"

namespace shading::tb {

const char* default_data_dir() { return SHADING_SOURCE_DIR; }

std::optional<int> parse_interp_study(int argc, char** argv, interp_study_options& o) {
    CLI::App app{"NMSE of the interpolation paper's interpolation against the exact intensity, per interval length"};
    app.add_option("--csv", o.csv, "output CSV");
    app.add_option("--width", o.width, "pixels of the raster line")->check(CLI::Range(8u, 100000u));
    app.add_option("--grouping-csv", o.grouping_csv,
                   "CSV of the /3 grouping study (default: interp_div3_grouping.csv beside --csv)");
    SHADING_CLI_PARSE(app, argc, argv);
    if (o.grouping_csv.empty())
        o.grouping_csv = (std::filesystem::path(o.csv).parent_path() / "interp_div3_grouping.csv").string();
    return std::nullopt;
}

std::optional<int> parse_soak(int argc, char** argv, soak_options& o) {
    CLI::App app{"The head rendered R times in one process by the fast SystemC pipeline; resident memory"};
    app.add_option("--renders", o.renders, "renders of the head")->check(CLI::Range(2u, 100000u));
    app.add_option("--size", o.size, "image width and height")->check(CLI::Range(8u, 1024u));
    SHADING_CLI_PARSE(app, argc, argv);
    return std::nullopt;
}

std::optional<int> parse_render_reference(int argc, char** argv, render_reference_options& o) {
    CLI::App app{"Per-pixel reference renders (Phong, and shading through a specular device's golden model) to PNG"};
    app.add_option("--scene", o.scene, "built-in scene (sphere, torus, head) or a path to an OBJ file");
    app.add_option("--size", o.size, "image width and height in pixels")->check(CLI::Range(1u, 8192u));
    // Names, ranges and numbers are checked by the parser: any bad one is bad usage (exit 2).
    const auto devices = CLI::IsMember(device_names());
    app.add_option("--device", o.device, "specular device: patent, minimax, rom_matched, ua22802, squared")
        ->check(devices);
    app.add_option("--compare", o.compare,
                   "devices (comma-separated) for compare.png: Phong and their images above their error maps")
        ->delimiter(',')
        ->check(devices);
    app.add_option("--mode", o.mode, "overflow mode of the device's ADD11: saturate or wrap")
        ->check(CLI::IsMember({"saturate", "wrap"}));
    app.add_option("--n", o.n, "override the material's exponent n (1..1000)")->check(CLI::Range(1u, 1000u));
    app.add_option("--error-scale", o.error_scale, "8-bit error shown as white in the heat map")->check(CLI::PositiveNumber)->check(not_nan());
    app.add_option("--depth-step", o.depth_step, "depth jump (world units) that splits a raster line")
        ->check(CLI::PositiveNumber)->check(not_nan());
    app.add_option("--out", o.out, "output folder");
    app.add_option("--data-dir", o.data_dir, "repository root holding data/head/ (for the built-in head)");
    SHADING_CLI_PARSE(app, argc, argv);
    return std::nullopt;
}

std::optional<int> parse_bench_specular_tlm(int argc, char** argv, bench_specular_tlm_options& o) {
    CLI::App app{"Throughput of the specular TLM-2.0 wrapper, loosely timed and pin-accurate"};
    app.add_option("--device", o.device, "specular device: patent, minimax, rom_matched, ua22802, squared")
        ->check(CLI::IsMember(device_names()));
    const auto pixels = CLI::Range(std::size_t{1}, std::size_t{1'000'000'000'000});
    app.add_option("--lt-pixels", o.lt_pixels, "pixels shaded loosely timed (whole lines)")->check(pixels);
    app.add_option("--pin-pixels", o.pin_pixels, "pixels shaded pin-accurate (whole lines)")->check(pixels);
    SHADING_CLI_PARSE(app, argc, argv);
    return std::nullopt;
}

std::optional<int> parse_accuracy_study(int argc, char** argv, accuracy_study_options& o) {
    CLI::App app{"accuracy study of the quadratic BRDF, the UA 22802 / UA 60553 devices and the squared-quadratic law"};
    app.add_option("--out", o.out, "output directory");
    app.add_option("--fig2-n", o.fig2_n, "n of the Fig. 2 curve")->check(CLI::Range(1u, 1000u));
    app.add_option("--n-max", o.n_max, "study n in [1, n-max] (a short run for the tests)")->check(CLI::Range(1u, 1000u));
    app.add_option("--size", o.size, "the head's image size for the cos distribution")->check(CLI::Range(16u, 4096u));
    app.add_option("--data-dir", o.data_dir, "repository root holding data/head/");
    SHADING_CLI_PARSE(app, argc, argv);
    o.fig2_n = std::min(o.fig2_n, o.n_max);
    return std::nullopt;
}

std::optional<int> parse_generator_search(int argc, char** argv, generator_search_options& o) {
    CLI::App app{"search for the ROM-free a(n) generator with the smallest worst-case error"};
    app.add_option("--csv", o.csv, "output CSV");
    app.add_option("--keep", o.keep, "keep candidates whose worst max rel error is below this")
        ->check(not_nan());
    SHADING_CLI_PARSE(app, argc, argv);
    return std::nullopt;
}

std::optional<int> parse_head_study(int argc, char** argv, head_study_options& o) {
    CLI::App app{"the head per device and n, and the squared-quadratic device's fit"};
    app.add_option("--out", o.out, "output directory");
    app.add_option("--size", o.size, "the head's image size")->check(CLI::Range(16u, 4096u));
    app.add_option("--n", o.ns, "exponents to render (comma-separated, 1..1000)")->delimiter(',')->check(CLI::Range(1u, 1000u));
    app.add_option("--data-dir", o.data_dir, "repository root holding data/head/");
    app.add_option("--scan-max", o.scan_max,
                   "the baseline and every bend variant (the device is s2) against Phong for every n in [1, scan-max] "
                   "(0: none)")
        ->check(CLI::Range(0u, 1000u));
    SHADING_CLI_PARSE(app, argc, argv);  // an n outside 1..1000 is bad usage (exit 2)
    return std::nullopt;
}

}  // namespace shading::tb
