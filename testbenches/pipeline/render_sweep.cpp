// render_pipeline --sweep (render_program.h): a grid of configurations on the golden model, one child
// process of this program per configuration (--jobs in parallel), merged into one CSV
// (scripts/plot_pipeline.py draws it).
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "render_program.h"

extern char** environ;

namespace shading::render_program {

namespace fs = std::filesystem;

namespace {

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


// The light as a CSV field: "az:el" (the option's comma would split the row), "default" for the scene's.
std::string light_field(std::string l) {
    if (l == "scene default") return "default";
    std::replace(l.begin(), l.end(), ',', ':');
    return l;
}

}  // namespace

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
                                      "--depth-step", num(o.pc.depth_step), "--unit", o.unit,
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
           "phong_long_per_px,phong_add_per_px,ratio_long,intervals,mean_len,quadratic_px,cubic_px,exact_px,"
           "scanline_long_per_px,ratio_long_scanline,nmse_interp_8bit,nmse_phong_8bit,light\n";
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
            << ',' << j["plan"]["exact_pixels"].get<std::size_t>() << ','
            << num(j["ops_per_pixel"]["phong_scanline"]["total"]["long"].get<double>()) << ','
            << num(j["ops_per_pixel"]["scanline_phong_long_over_hardware_long"].get<double>()) << ','
            << num(e["interpolation"]["displayed_8bit"]["nmse"].get<double>()) << ','
            << num(e["total"]["displayed_8bit"]["nmse"].get<double>()) << ','
            << light_field(j["config"]["light"].get<std::string>()) << '\n';
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
}  // namespace shading::render_program
