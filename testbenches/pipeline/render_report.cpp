// render_pipeline's report (render_program.h): report.json, report.md and the summary it prints.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "render_program.h"

namespace shading::render_program {

namespace fs = std::filesystem;

json stats_json(const error_stats& s) {
    json j;
    j["nmse"] = s.nmse;
    j["psnr_db"] = std::isfinite(s.psnr_db) ? json(s.psnr_db) : json(nullptr);  // null: identical images
    j["max_abs"] = s.max_abs;
    j["pixels"] = s.pixels;
    json over = json::object();  // {"4": n, "16": n, "64": n}: pixels beyond each level
    for (std::size_t k = 0; k < error_levels.size(); ++k) over[fmt("%g", error_levels[k])] = s.pixels_over[k];
    j["pixels_over"] = over;
    return j;
}

std::string over_levels_text() {
    std::string t;
    for (double l : error_levels) t += (t.empty() ? "" : " / ") + fmt("%g", l);
    return t;
}

std::string over_counts_text(const error_stats& s) {
    std::string t;
    for (std::size_t n : s.pixels_over) t += (t.empty() ? "" : " / ") + std::to_string(n);
    return t;
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

std::string num(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

staged_output::staged_output(const std::string& out) : out_(out) {
    fs::create_directories(out_);
    stage_ = (fs::path(out_) / (".render_pipeline.tmp." + std::to_string(::getpid()))).string();
    fs::remove_all(stage_);
    fs::create_directories(stage_);
}
staged_output::~staged_output() {
    std::error_code ec;
    fs::remove_all(stage_, ec);
}
std::string staged_output::path(const std::string& name) {
    names_.push_back(name);
    return (fs::path(stage_) / name).string();
}
void staged_output::commit() {
    for (const auto& n : names_) fs::rename(fs::path(stage_) / n, fs::path(out_) / n);
    names_.clear();
}

void write_text(const std::string& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    f << text;
    f.close();
    if (!f) throw std::runtime_error("cannot write " + path);
}

namespace {
// The operation figures per pixel of a render: both baselines and the hardware path.
struct figures {
    double phong_px, hw_px, phong_long, scan_long, hw_long, hw_other_long, ratio, ratio_scan;
    std::size_t n_deg[4];
};
figures figures_of(const render_data& d) {
    figures f{};
    f.phong_px = static_cast<double>(d.sp.pixels);
    f.hw_px = static_cast<double>(d.hc.pixels);
    f.phong_long = f.phong_px > 0 ? d.sp.total().long_ops() / f.phong_px : 0.0;
    f.scan_long = f.phong_px > 0 ? d.sl.total().long_ops() / f.phong_px : 0.0;
    f.hw_long = f.hw_px > 0 ? d.hc.total().long_ops() / f.hw_px : 0.0;
    f.hw_other_long = f.hw_px > 0 ? d.hc_other.total().long_ops() / f.hw_px : 0.0;
    f.ratio = f.hw_long > 0 ? f.phong_long / f.hw_long : 0.0;
    f.ratio_scan = f.hw_long > 0 ? f.scan_long / f.hw_long : 0.0;
    for (std::size_t i = 0; i < d.hw.degree.size(); ++i)
        if (d.hw.covered[i] && d.hw.degree[i] < 4) ++f.n_deg[d.hw.degree[i]];
    return f;
}
}  // namespace

#define RENDER_ALIASES                                                                                     \
    const figures F = figures_of(d);                                                                       \
    const double phong_px = F.phong_px, hw_px = F.hw_px, phong_long = F.phong_long, hw_long = F.hw_long;  \
    const double ratio = F.ratio;                                                                          \
    const std::size_t* n_deg = F.n_deg;                                                                    \
    const plan_config& cfg = d.cfg;                                                                        \
    const scene::device_config& dev = d.dev;                                                               \
    const scene::world& s = d.s;                                                                           \
    const scene::rasterised& r = d.r;                                                                      \
    const frame_constants& k = d.k;                                                                        \
    const plan& p = d.p;                                                                                   \
    const scene::render_stats &sp = d.sp, &sd = d.sd;                                                      \
    const hardware_counts& hc = d.hc;                                                                      \
    const scene::op_counts hw_total = hc.total();                                                          \
    const scene::material& mat = s.objects.front().mat;                                                    \
    const auto& pairs = d.pairs;                                                                           \
    const json& sim_j = d.sim_j;                                                                           \
    (void)phong_long, (void)hw_long, (void)ratio, (void)n_deg, (void)cfg, (void)dev, (void)k, (void)sd, (void)sp, \
        (void)hw_total, (void)mat, (void)pairs, (void)sim_j, (void)phong_px, (void)hw_px, (void)r, (void)p

json report_json(const options& o, const render_data& d) {
    RENDER_ALIASES;
    const json& errors = d.errors;
    json rep;
    rep["program"] = "render_pipeline";
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
                     {"length", d.maker ? d.maker->length_name : std::string(length_policy_name(cfg.length))},
                     {"m", cfg.m},
                     {"m_min", cfg.m_min},
                     {"m_max", cfg.m_max},
                     {"length_tol", cfg.length_tol},
                     {"exact_fallback", cfg.exact_fallback},
                     {"split_at_check", cfg.split_at_check},
                     {"carry_samples", cfg.carry_samples},
                     {"above_slack", cfg.above_slack},
                     {"lit_guard", cfg.lit_guard},
                     {"surface_breaks", cfg.surface_breaks},
                     {"degree", degree_policy_name(cfg.degree)},
                     {"degree_tol", cfg.degree_tol},
                     {"eval", evaluator_name(cfg.eval)},
                     {"set", o.set},
                     {"div3", o.div3},
                     {"depth_step", cfg.depth_step},
                     {"geometry_unit", geometry_unit_name(cfg.unit)},
                     {"walk_edges", cfg.walk_edges},
                     {"runs_on_geometry_side",
                      (d.maker ? d.maker->runs_on_geometry_side : policy_runs_on_geometry_side(cfg.length)) &&
                          policy_runs_on_geometry_side(cfg.degree)},
                     {"sim", o.sim}};
    rep["frame_constants"] = {{"n", k.n}, {"ksi", k.ksi}, {"kdi", k.kdi}, {"ambient", k.ambient}};
    rep["plan"] = {{"intervals", p.jobs.size()},
                   {"pixels", p.pixels},
                   {"geometry_points", p.geometry_points},
                   {"stepping", {{"triangle_setups", p.stepping.triangle_setups}, {"run_starts", p.stepping.run_starts},
                                 {"walked_starts", p.stepping.walked_starts}, {"steps", p.stepping.steps}}},
                   {"check_samples", p.check_samples},
                   {"samples", hc.samples},
                   {"samples_carried", hc.carried},
                   {"mean_interval_pixels", p.jobs.empty() ? 0.0 : double(p.pixels) / p.jobs.size()},
                   {"exact_pixels", n_deg[1]},
                   {"quadratic_pixels", n_deg[2]},
                   {"cubic_pixels", n_deg[3]}};
    if (d.maker && d.maker->add_json) d.maker->add_json(d, rep);
    rep["scene_stats"] = {{"triangles", r.setups.size()}, {"covered_pixels", r.covered_pixels()}};
    rep["errors"] = errors;
    rep["ops_per_pixel"] = {
        {"phong", {{"geometry", ops_json(sp.geometry, phong_px)}, {"shading", ops_json(sp.shading, phong_px)},
                   {"total", ops_json(sp.total(), phong_px)}}},
        {"phong_scanline", {{"geometry", ops_json(d.sl.geometry, phong_px)}, {"shading", ops_json(d.sl.shading, phong_px)},
                            {"total", ops_json(d.sl.total(), phong_px)},
                            {"triangle_setups", d.sl_steps.triangle_setups}, {"run_starts", d.sl_steps.run_starts},
                            {"walked_starts", d.sl_steps.walked_starts}, {"steps", d.sl_steps.steps}}},
        {"device_reference", {{"total", ops_json(sd.total(), double(sd.pixels))}}},
        {"hardware", {{"geometry_unit", geometry_unit_name(cfg.unit)}, {"geometry", ops_json(hc.geometry, hw_px)},
                      {"sample_stage", ops_json(hc.sample_stage, hw_px)},
                      {"interpolation", ops_json(hc.interpolation, hw_px)}, {"total", ops_json(hw_total, hw_px)}}},
        {"hardware_other_geometry_unit",
         {{"geometry_unit", geometry_unit_name(cfg.unit == geometry_unit::stepped ? geometry_unit::scratch
                                                                                   : geometry_unit::stepped)},
          {"geometry", ops_json(d.hc_other.geometry, hw_px)}, {"total", ops_json(d.hc_other.total(), hw_px)}}},
        {"phong_long_over_hardware_long", ratio},
        {"scanline_phong_long_over_hardware_long", F.ratio_scan}};
    rep["clocks_per_pixel"] = {{"hardware_ops", hw_px > 0 ? hc.clocks / hw_px : 0.0},
                               {"sim", std::isfinite(d.sim_clocks_per_px) ? json(d.sim_clocks_per_px) : json(nullptr)}};
    rep["sim"] = sim_j;
    return rep;
}

namespace {

// The title, the configuration and the plan.
void md_configuration(std::ostream& md, const options& o, const render_data& d) {
    RENDER_ALIASES;
    md << "# Shading pipeline report: " << s.name << ", " << r.width << "x" << r.height << "\n\n";
    md << "Configuration: device " << scene::device_name(dev.device) << " (" << o.mode << "), n = " << mat.n
       << ", length " << (d.maker ? d.maker->length_name : std::string(length_policy_name(cfg.length)));
    if (cfg.length == length_policy::fixed)
        md << " (m = " << cfg.m << ", " << (1u << cfg.m) << " pixels)";
    else
        md << " (m " << cfg.m_min << ".." << cfg.m_max << ", tolerance " << cfg.length_tol << " levels, exact fallback "
           << (cfg.exact_fallback ? "on" : "off") << (cfg.split_at_check ? ", split at the check point" : "")
           << (cfg.above_slack >= 0 ? ", at most " + std::to_string(cfg.above_slack) + " levels over the line above" : "")
           << (cfg.lit_guard ? ", lit guard (no all-unlit interval over a triangle that may be lit)" : "")
           << (d.maker ? d.maker->length_note : "") << ")";
    md << ", degree " << degree_policy_name(cfg.degree);
    if (cfg.degree == degree_policy::adaptive) md << " (tolerance " << cfg.degree_tol << ")";
    md << ", evaluator " << evaluator_name(cfg.eval) << ", sample set " << o.set << ", /3 " << o.div3
       << ", depth step " << cfg.depth_step << (cfg.surface_breaks ? ", segments also end at folds" : "")
       << (cfg.carry_samples ? ", samples carried" : "") << ".\n\n";
    md << "Plan: " << p.jobs.size() << " intervals over " << p.pixels << " covered pixels (mean "
       << fmt("%.2f", p.jobs.empty() ? 0.0 : double(p.pixels) / p.jobs.size()) << " pixels), " << hc.samples
       << " samples through the sample stage; pixels exact " << n_deg[1] << ", quadratic " << n_deg[2] << ", cubic "
       << n_deg[3] << ".\n\n";
}

// The error tables: the whole frame, the displayed images, each zone.
void md_errors(std::ostream& md, const render_data& d) {
    RENDER_ALIASES;
    const auto& whole = d.whole;
    const auto& errors = d.errors;
    const auto& zone_px = d.zone_px;
    md << "## Errors (8-bit levels, covered pixels, three channels)\n\n";
    md << "| pair | what | NMSE | PSNR dB | max | pixels beyond " << over_levels_text() << " |\n|---|---|---|---|---|---|\n";
    for (const auto& pd : pairs) {
        const error_stats& w = whole.at(pd.key);
        md << "| " << pd.key << " | " << pd.what << " | " << fmt("%.3e", w.nmse) << " | " << fmt_psnr(w.psnr_db)
           << " | " << fmt("%.2f", w.max_abs) << " | " << over_counts_text(w) << " |\n";
    }
    md << "\nThe 8-bit displayed images (each value rounded to a level, as the PNGs): interpolation NMSE "
       << fmt("%.3e", d.interp_8bit.nmse) << " (max " << fmt("%.0f", d.interp_8bit.max_abs) << "), total NMSE "
       << fmt("%.3e", d.total_8bit.nmse) << " (max " << fmt("%.0f", d.total_8bit.max_abs)
       << "); the frame buffer's (Q8.8) above.\n";
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
}

// The operations per pixel and the ratios against Phong.
void md_operations(std::ostream& md, const render_data& d) {
    RENDER_ALIASES;
    const auto& errors = d.errors;
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
        ops_row("scan-line Phong: geometry", d.sl.geometry, phong_px);
        ops_row("scan-line Phong: shading", d.sl.shading, phong_px);
        ops_row("**scan-line Phong: total**", d.sl.total(), phong_px);
        ops_row("hardware: geometry side", hc.geometry, hw_px);
        ops_row("hardware: sample stage", hc.sample_stage, hw_px);
        ops_row("hardware: interpolation", hc.interpolation, hw_px);
        ops_row("**hardware: total**", hw_total, hw_px);
        ops_row(std::string("hardware, geometry ") +
                    (cfg.unit == geometry_unit::stepped ? "from scratch" : "stepped") + ": total",
                d.hc_other.total(), hw_px);
    }
    md << "\nThe hardware's geometry side: " << geometry_unit_name(cfg.unit)
       << " (scan-line stepping: per-triangle set-up, run starts, adds per step; or from scratch per point)"
       << (cfg.walk_edges ? "; edges walked: a triangle's later run starts, in the hardware and the scan-line Phong, "
                            "are reached by adds from its last point"
                          : "")
       << ". "
          "Long operations, Phong from scratch / the hardware path's: **"
       << fmt("%.2f", ratio) << "x**; scan-line Phong / the hardware path's: **" << fmt("%.2f", F.ratio_scan)
       << "x**. The scan-line Phong image against the per-pixel one: NMSE "
       << fmt("%.2e", errors["scanline_phong"]["image"]["nmse"].get<double>()) << ".\n\n";
}

// The clocks per pixel and the simulation's speed, the images' key, the wall times.
void md_clocks_and_images(std::ostream& md, const options& o, const render_data& d) {
    RENDER_ALIASES;
    const auto& wall = d.wall;
    const double sim_clocks_per_px = d.sim_clocks_per_px, sim_px_per_s = d.sim_px_per_s;
    const double sim_px_per_cpu_s = d.sim_px_per_cpu_s, sr_cpu = d.sr_cpu;
    md << "Clocks per pixel (evaluator, counted): " << fmt("%.3f", hw_px > 0 ? hc.clocks / hw_px : 0.0);
    if (sim_j["ran"].get<bool>())
        md << "; simulated: " << fmt("%.3f", sim_clocks_per_px) << " clocks per pixel, "
           << fmt("%.0f", sim_px_per_s) << " pixels per second (" << fmt("%.2f", wall.at("sim"))
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
}

}  // namespace

std::string report_md(const options& o, const render_data& d) {
    std::ostringstream md;
    md_configuration(md, o, d);
    if (d.maker && d.maker->md_after_plan) md << d.maker->md_after_plan(d);
    md_errors(md, d);
    md_operations(md, d);
    md_clocks_and_images(md, o, d);
    return md.str();
}

void print_summary(const options& o, const render_data& d) {
    RENDER_ALIASES;
    const auto& whole = d.whole;
    const auto& wall = d.wall;
    const auto& written = d.written;
    const double sim_clocks_per_px = d.sim_clocks_per_px, sim_px_per_s = d.sim_px_per_s;
    const double sim_px_per_cpu_s = d.sim_px_per_cpu_s, sr_cpu = d.sr_cpu;
    std::printf("%s %ux%u: %zu intervals, %zu pixels; device %s (%s), n = %u\n", s.name.c_str(), r.width, r.height,
                p.jobs.size(), p.pixels, scene::device_name(dev.device), o.mode.c_str(), mat.n);
    for (const auto& pd : pairs) {
        const error_stats& w = whole.at(pd.key);
        std::printf("  %-13s NMSE %.3e  PSNR %s dB  max %.2f  beyond %s: %s px  (%s)\n", pd.key, w.nmse,
                    fmt_psnr(w.psnr_db).c_str(), w.max_abs, over_levels_text().c_str(), over_counts_text(w).c_str(),
                    pd.what);
    }
    std::printf("  displayed 8-bit: interpolation NMSE %.3e, total NMSE %.3e\n", d.interp_8bit.nmse, d.total_8bit.nmse);
    std::printf("  long ops/pixel: Phong %.2f, scan-line Phong %.2f, hardware %.2f (geometry %s %.2f, sample stage "
                "%.2f, interpolation %.2f; geometry %s: total %.2f); ratio %.2f, against scan-line %.2f\n",
                phong_long, F.scan_long, hw_long, geometry_unit_name(cfg.unit),
                hw_px > 0 ? hc.geometry.long_ops() / hw_px : 0.0, hw_px > 0 ? hc.sample_stage.long_ops() / hw_px : 0.0,
                hw_px > 0 ? hc.interpolation.long_ops() / hw_px : 0.0,
                cfg.unit == geometry_unit::stepped ? "from scratch" : "stepped", F.hw_other_long, ratio, F.ratio_scan);
    if (sim_j["ran"].get<bool>())
        std::printf("  sim (%s): bit-exact, %.3f clocks/pixel, %.0f pixels/s (%.2f s), %.0f pixels per CPU second "
                    "(%.2f s)\n", o.abstraction.c_str(), sim_clocks_per_px, sim_px_per_s, wall.at("sim"), sim_px_per_cpu_s,
                    sr_cpu);
    std::string files = written.empty() ? "" : "*.png";
    for (const std::string& n : {o.md_name, o.json_name})
        if (!n.empty()) files += (files.empty() ? "" : ", ") + n;
    std::printf("  wall %.2f s; wrote %s/{%s}\n", wall.at("total"), o.out.c_str(), files.c_str());
}

}  // namespace shading::render_program
