// render_pipeline --sweep (render_program.h): a grid of configurations on the golden model, one child
// process of this program per configuration (--jobs in parallel), merged into one CSV
// (scripts/plot_pipeline.py draws it).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "testbenches/common/child_processes.h"
#include "render_program.h"

namespace shading::render_program {

namespace fs = std::filesystem;

namespace {

struct sweep_point {
    std::string device, length, degree, eval;
    unsigned m = 4;
    double length_tol = 0.5, degree_tol = 0.25;
    int n = -1;  // -1: --n or the scene's
    std::string scene, light;  // empty: --scene, --light
    unsigned size = 0;         // 0: --size
    bool split = false;        // --split-at-check (or the command line's)
    bool carry = false;        // --carry-samples (or the command line's)
};

// small: two devices x the degree policies x fixed m = 3..5 and three adaptive-length tolerances,
// each with the Horner unit and the forward differences; full: every device, m = 2..6, five
// tolerances, three adaptive-degree tolerances, and the geometry-only policies; exponents: every
// device x n = 2..500 with the command line's own plan settings (the total error against Phong per
// device and n); claims: scenes (--scenes, default head, sphere, torus) x light directions (--lights)
// x n (--ns) x sizes (--sizes) x devices x sixteen policies (eight, each through both evaluators).
std::vector<sweep_point> sweep_grid(const std::string& grid, const std::string& only_device, const options& o) {
    std::vector<std::string> devices = grid != "small" ? scene::device_names() : std::vector<std::string>{"patent", "minimax"};
    if (!only_device.empty()) devices = {only_device};
    if (grid == "exponents") {
        std::vector<sweep_point> g;
        for (const auto& d : devices)
            for (int n : {2, 5, 10, 20, 50, 100, 200, 500})
                g.push_back({d, o.length, o.degree, o.eval, o.pc.m, o.pc.length_tol, o.pc.degree_tol, n, "", "", 0});
        return g;
    }
    if (grid == "claims") {
        // The policies whose worst case and median the claims are about: the program's default, the
        // interpolation paper's zones, the colour-checked adaptive ones (host only) and the
        // geometry-only ones, each through both evaluators.
        struct pol {
            const char* length;
            unsigned m;
            double ltol;
            const char* degree;
            double dtol;
            bool split;  // split at the check point, and the sample stage's carry
        };
        // The last two: the head's cheapest at NMSE <= 1e-5 with each checking policy, split at the
        // check and with the carry.
        const pol policies[] = {{"fixed", 4, 0.5, "cubic", 0.5, false},       {"fixed", 3, 0.5, "zones", 0.5, false},
                                {"adaptive", 4, 1.0, "adaptive", 0.5, false}, {"adaptive", 4, 2.0, "adaptive", 0.5, false},
                                {"geometry", 4, 1.0, "geometry", 0.5, false}, {"geometry", 4, 2.0, "geometry", 0.5, false},
                                {"adaptive", 4, 1.3, "cubic", 0.5, true},     {"geometry", 4, 2.0, "geometry", 0.5, true}};
        std::vector<sweep_point> g;
        for (const auto& sc : o.claims_scenes)
            for (const auto& li : o.claims_lights)
                for (int n : o.claims_ns)
                    for (unsigned sz : o.claims_sizes)
                        for (const auto& d : devices)
                            for (const pol& p : policies)
                                for (const char* ev : {"fd", "horner"})
                                    g.push_back({d, p.length, p.degree, ev, p.m, p.ltol, p.dtol, n, sc, li, sz, p.split, p.split});
        return g;
    }
    const std::vector<unsigned> ms = grid == "full" ? std::vector<unsigned>{2, 3, 4, 5, 6} : std::vector<unsigned>{3, 4, 5};
    const std::vector<double> ltols = grid == "full" ? std::vector<double>{0.125, 0.25, 0.5, 1.0, 2.0}
                                                     : std::vector<double>{0.25, 0.5, 1.0};
    const std::vector<std::pair<std::string, double>> degrees =
        grid == "full" ? std::vector<std::pair<std::string, double>>{{"cubic", 0.5},     {"quadratic", 0.5},
                                                                     {"zones", 0.5},    {"adaptive", 0.25},
                                                                     {"adaptive", 0.5},  {"adaptive", 1.0},
                                                                     {"geometry", 0.5}}
                       : std::vector<std::pair<std::string, double>>{
                             {"cubic", 0.5}, {"quadratic", 0.5}, {"zones", 0.5}, {"adaptive", 0.5}};
    std::vector<sweep_point> g;
    for (const auto& d : devices)
        for (const auto& [deg, dtol] : degrees) {
            for (unsigned m : ms)
                for (const char* ev : {"horner", "fd"}) g.push_back({d, "fixed", deg, ev, m, 0.5, dtol, -1, "", "", 0});
            for (double lt : ltols)
                for (const char* ev : {"horner", "fd"})
                    g.push_back({d, "adaptive", deg, ev, 4, lt, dtol, -1, "", "", 0});
            if (grid == "full")
                for (double lt : {0.5, 1.0, 2.0, 4.0, 8.0})
                    for (const char* ev : {"horner", "fd"})
                        g.push_back({d, "geometry", deg, ev, 4, lt, dtol, -1, "", "", 0});
        }
    return g;
}

}  // namespace

// "I/N" -> (I - 1, N); throws scene_error unless 1 <= I <= N.
std::pair<std::size_t, std::size_t> parse_shard(const std::string& s) {
    const std::size_t slash = s.find('/');
    try {
        if (slash == std::string::npos) throw std::invalid_argument("");
        std::size_t u1 = 0, u2 = 0;
        const std::string a = s.substr(0, slash), b = s.substr(slash + 1);
        const unsigned long i = std::stoul(a, &u1), n = std::stoul(b, &u2);
        if (u1 != a.size() || u2 != b.size() || i < 1 || i > n) throw std::invalid_argument("");
        return {i - 1, n};
    } catch (const std::exception&) {
        throw scene::scene_error("--shard '" + s + "': expected I/N with 1 <= I <= N");
    }
}

namespace {

// The light as a CSV field: "az:el" (the option's comma would split the row), "default" for the scene's.
std::string light_field(std::string l) {
    if (l == "scene default") return "default";
    std::replace(l.begin(), l.end(), ',', ':');
    return l;
}

// The configurations of one shard, and each one's index in the whole grid.
struct shard_configs {
    std::vector<sweep_point> grid;
    std::vector<std::size_t> index;
};

// Index i of the whole grid runs in shard i % N (the CSV's `config` column keeps i, so the shards'
// rows merge back into the whole grid's by sorting).
shard_configs shard_of(const std::vector<sweep_point>& full_grid, const std::string& shard) {
    shard_configs out;
    const auto [shard_i, shard_n] = shard.empty() ? std::pair<std::size_t, std::size_t>{0, 1} : parse_shard(shard);
    for (std::size_t i = 0; i < full_grid.size(); ++i)
        if (i % shard_n == shard_i) {
            out.grid.push_back(full_grid[i]);
            out.index.push_back(i);
        }
    return out;
}

// Every scene, light, size and n of the grid checked once here, so a bad one is one message and
// not one per child.
void check_grid(const options& o, const std::vector<sweep_point>& full_grid) {
    options probe = o;
    probe.size = 8;
    for (const auto& sp : full_grid) {
        if (!sp.scene.empty()) probe.scene = sp.scene;
        if (!sp.light.empty()) probe.light = sp.light;
        (void)load_world(probe);
        if (sp.size > max_size || (o.grid == "claims" && sp.size == 0))
            throw scene::scene_error("--sizes: " + std::to_string(sp.size) + " outside 1..4096");
        if (sp.n != -1 && (sp.n < 1 || sp.n > 1000))
            throw scene::scene_error("--ns: " + std::to_string(sp.n) + " outside 1..1000");
    }
}

// --emit-jobs: one command line per configuration, this program with the same options and a shard of one.
void emit_jobs(const options& o, std::size_t configs) {
    for (std::size_t i = 0; i < configs; ++i) {
        std::string cmd;
        for (const std::string& arg : o.argv) {
            if (arg == "--emit-jobs") continue;
            cmd += "'" + arg + "' ";
        }
        cmd += "--shard " + std::to_string(i + 1) + "/" + std::to_string(configs) + " --csv '" +
               (fs::path(o.out) / ("config_" + std::to_string(i) + ".csv")).string() + "'";
        std::printf("%s\n", cmd.c_str());
    }
}

// The command line of the child that renders configuration sp into <tmp>/<i>: the sweep's own
// options, the configuration's settings over them, golden model only, report.json only.
std::vector<std::string> child_args(const options& o, const std::string& self, const fs::path& tmp,
                                    const sweep_point& sp, std::size_t i) {
    const std::string scene = sp.scene.empty() ? o.scene : sp.scene;
    const unsigned size = sp.size ? sp.size : o.size;
    std::vector<std::string> a = {self, "--scene", scene, "--data-dir", o.data_dir, "--size", std::to_string(size),
                                  "--device", sp.device, "--mode", o.mode, "--length", sp.length, "--m",
                                  std::to_string(sp.m), "--m-min", std::to_string(o.pc.m_min), "--m-max",
                                  std::to_string(o.pc.m_max),
                                  "--length-tol", num(sp.length_tol), "--degree", sp.degree, "--degree-tol",
                                  num(sp.degree_tol), "--eval", sp.eval, "--set", o.set, "--div3", o.div3,
                                  "--depth-step", num(o.pc.depth_step), "--unit", o.unit,
                                  o.pc.walk_edges ? "--walk-edges" : "--no-walk-edges",
                                  "--above-slack", std::to_string(o.pc.above_slack),
                                  o.pc.lit_guard ? "--lit-guard" : "--no-lit-guard",
                                  o.pc.exact_fallback ? "--exact-fallback" : "--no-exact-fallback",
                                  sp.split || o.pc.split_at_check ? "--split-at-check" : "--no-split-at-check",
                                  sp.carry || o.pc.carry_samples ? "--carry-samples" : "--no-carry-samples",
                                  o.pc.surface_breaks ? "--surface-breaks" : "--no-surface-breaks", "--no-sim", "--no-images", "--md", "",
                                  "--json", "report.json", "--out", (tmp / std::to_string(i)).string()};
    const std::string light = sp.light.empty() ? o.light : sp.light;
    if (!light.empty()) a.insert(a.end(), {"--light", light});
    a.insert(a.end(), {"--lobe-tol", num(o.pc.lobe_tol)});
    const int n = sp.n != -1 ? sp.n : o.n;
    if (n != -1) a.insert(a.end(), {"--n", std::to_string(n)});
    if (!o.kd.empty()) a.insert(a.end(), {"--kd", o.kd});
    if (!o.ks.empty()) a.insert(a.end(), {"--ks", o.ks});
    if (!o.ambient.empty()) a.insert(a.end(), {"--ambient", o.ambient});
    return a;
}

// Runs every configuration of the shard, `jobs` children at a time, with a progress line; returns
// the configurations whose child did not exit 0 (not started, failed or killed).
std::vector<std::size_t> run_configs(const options& o, const std::string& self, const fs::path& tmp,
                                     const std::vector<sweep_point>& grid, unsigned jobs,
                                     std::chrono::steady_clock::time_point t0) {
    std::vector<std::size_t> failed;
    std::size_t started = 0, done = 0;
    // Each child's standard output and error go to <i>.log in the temporary folder.
    auto spec = [&](std::size_t i) {
        ++started;
        return tb::child_spec{self, child_args(o, self, tmp, grid[i], i), (tmp / (std::to_string(i) + ".log")).string(),
                              true};
    };
    const bool tty = ::isatty(2);
    auto progress = [&](bool final) {
        progress_open = tty && !final;
        if (tty)
            std::fprintf(stderr, "\rsweep: %zu/%zu configurations done, %zu running, %zu failed, %.0f s%s", done,
                         grid.size(), started - done, failed.size(), seconds_since(t0), final ? "\n" : "");
        else if (final || (done < grid.size() && done % std::max<std::size_t>(1, grid.size() / 10) == 0))
            std::fprintf(stderr, "sweep: %zu/%zu configurations done, %zu failed, %.0f s\n", done, grid.size(),
                         failed.size(), seconds_since(t0));
    };
    tb::run_children(grid.size(), jobs, spec, [&](std::size_t i, int status) {
        if (status != 0) failed.push_back(i);
        ++done;
        progress(false);
    });
    progress(true);
    return failed;
}

const char* const csv_header =
    "config,scene,size,n,device,mode,length,m,m_min,m_max,length_tol,degree,degree_tol,eval,set,"
    "nmse_interp,psnr_interp,max_interp,px_over_16_interp,nmse_phong,max_phong,nmse_brdf,"
    "long_per_px,mul_per_px,div_per_px,sqrt_per_px,add_per_px,interp_long_per_px,clocks_per_px,"
    "phong_long_per_px,phong_add_per_px,ratio_long,intervals,mean_len,quadratic_px,cubic_px,exact_px,"
    "scanline_long_per_px,ratio_long_scanline,nmse_interp_8bit,nmse_phong_8bit,light,geometry_side,split,carry\n";

// One CSV row from configuration `config`'s report.json (j).
void csv_row(std::ostream& csv, std::size_t config, const json& j) {
    const json& c = j["config"];
    const json& e = j["errors"];
    const json& hw = j["ops_per_pixel"]["hardware"];
    const json& ph = j["ops_per_pixel"]["phong"]["total"];
    auto d = [](const json& v) { return v.is_null() ? std::string("inf") : num(v.get<double>()); };
    csv << config << ',' << c["scene"].get<std::string>() << ',' << c["width"].get<unsigned>() << ',' << c["n"].get<unsigned>() << ','
        << c["device"].get<std::string>() << ',' << c["mode"].get<std::string>() << ','
        << c["length"].get<std::string>() << ',' << c["m"].get<unsigned>() << ',' << c["m_min"].get<unsigned>()
        << ',' << c["m_max"].get<unsigned>() << ',' << num(c["length_tol"].get<double>()) << ','
        << c["degree"].get<std::string>() << ',' << num(c["degree_tol"].get<double>()) << ','
        << c["eval"].get<std::string>() << ',' << c["set"].get<std::string>() << ','
        << num(e["interpolation"]["image"]["nmse"].get<double>()) << ','
        << d(e["interpolation"]["image"]["psnr_db"]) << ','
        << num(e["interpolation"]["image"]["max_abs"].get<double>()) << ','
        << e["interpolation"]["image"]["pixels_over"]["16"].get<std::size_t>() << ','
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
        << ',' << j["plan"]["exact_pixels"].get<std::size_t>() << ','
        << num(j["ops_per_pixel"]["phong_scanline"]["total"]["long"].get<double>()) << ','
        << num(j["ops_per_pixel"]["scanline_phong_long_over_hardware_long"].get<double>()) << ','
        << num(e["interpolation"]["displayed_8bit"]["nmse"].get<double>()) << ','
        << num(e["total"]["displayed_8bit"]["nmse"].get<double>()) << ','
        << light_field(j["config"]["light"].get<std::string>()) << ','
        << (c["runs_on_geometry_side"].get<bool>() ? "yes" : "no") << ','
        << (c["split_at_check"].get<bool>() ? 1 : 0) << ',' << (c["carry_samples"].get<bool>() ? 1 : 0) << '\n';
}

// The CSV of the shard: one row per configuration, from each child's report.json.
std::string sweep_csv(const shard_configs& shard, const fs::path& tmp) {
    std::ostringstream csv;
    csv << csv_header;
    csv.precision(6);
    for (std::size_t i = 0; i < shard.grid.size(); ++i) {
        std::ifstream f(tmp / std::to_string(i) / "report.json");
        json j;
        try {
            j = json::parse(f);
        } catch (const std::exception& e) {
            throw std::runtime_error("sweep configuration " + std::to_string(i) + ": unreadable report.json: " + e.what());
        }
        csv_row(csv, shard.index[i], j);
    }
    return csv.str();
}

}  // namespace

int run_sweep(const options& o) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<sweep_point> full_grid =
        sweep_grid(o.grid, !o.device_given || o.device == "all" ? "" : o.device, o);
    const shard_configs shard = shard_of(full_grid, o.shard);
    const std::vector<sweep_point>& grid = shard.grid;
    const unsigned jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
    check_grid(o, full_grid);
    if (o.emit_jobs) {
        emit_jobs(o, full_grid.size());
        return 0;
    }
    std::error_code ec;
    const std::string self = fs::read_symlink("/proc/self/exe", ec).string();
    if (ec) throw std::runtime_error("cannot find this program's path (/proc/self/exe)");
    fs::create_directories(o.out);
    const fs::path tmp = fs::path(o.out) / (".sweep.tmp." + std::to_string(::getpid()));
    fs::remove_all(tmp);
    fs::create_directories(tmp);

    if (o.grid == "claims")
        std::fprintf(stderr, "sweep: %zu configurations of the claims grid in %u processes\n", grid.size(), jobs);
    else
        std::fprintf(stderr, "sweep: %zu configurations of %s %ux%u in %u processes\n", grid.size(), o.scene.c_str(),
                     o.size, o.size, jobs);
    const std::vector<std::size_t> failed = run_configs(o, self, tmp, grid, jobs, t0);
    if (!failed.empty()) {
        std::fprintf(stderr, "render_pipeline: %zu sweep configurations failed; logs kept in %s:\n", failed.size(),
                     tmp.c_str());
        for (std::size_t i : failed) {
            std::string cmd;
            for (const auto& s : child_args(o, self, tmp, grid[i], i)) cmd += s + ' ';
            std::fprintf(stderr, "  %zu.log: %s\n", i, cmd.c_str());
        }
        return 1;
    }

    const std::string csv = sweep_csv(shard, tmp);
    const std::string csv_path = o.csv.empty() ? (fs::path(o.out) / "sweep.csv").string() : o.csv;
    if (fs::path(csv_path).has_parent_path()) fs::create_directories(fs::path(csv_path).parent_path());
    const std::string csv_tmp = csv_path + ".tmp." + std::to_string(::getpid());
    write_text(csv_tmp, csv);
    fs::rename(csv_tmp, csv_path);
    fs::remove_all(tmp);
    std::printf("sweep: %zu configurations (grid %s%s%s) in %.1f s (%u processes); wrote %s\n", grid.size(),
                o.grid.c_str(), o.shard.empty() ? "" : ", shard ", o.shard.c_str(), seconds_since(t0), jobs,
                csv_path.c_str());
    return 0;
}
}  // namespace shading::render_program
