// One render of render_pipeline (render_program.h): scene -> rasterise -> plan -> golden frame, the
// per-pixel references (Phong from scratch, scan-line Phong, the device reference, per-pixel shading
// through the golden sample stage), with --sim the SystemC pipeline (bit for bit against the golden
// frame), the comparisons and the operation counts; then the report and the images.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "render_program.h"

#if SHADING_PIPELINE_SIM
#include <systemc>

#include "testbenches/common/report_log.h"
#include "pipeline_sim.h"
#endif

namespace shading::render_program {

bool progress_open = false;

namespace fs = std::filesystem;

namespace {

// The SystemC pipeline: the same plan through the hardware, which must give the golden frame.
// Returns the exit status (1: a mismatch or a SystemC warning or error).
int run_sim(const options& o, render_data& d) {
#if SHADING_PIPELINE_SIM
    const plan& p = d.p;
    const frame_constants& k = d.k;
    const scene::device_config& dev = d.dev;
    const plan_config& cfg = d.cfg;
    const frame& hw = d.hw;
    const hardware_counts& hc = d.hc;
    auto& wall = d.wall;
    double& sr_cpu = d.sr_cpu;
    double& sim_clocks_per_px = d.sim_clocks_per_px;
    double& sim_px_per_s = d.sim_px_per_s;
    double& sim_px_per_cpu_s = d.sim_px_per_cpu_s;
    json& sim_j = d.sim_j;
    (void)cfg;
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
    // The counts behind the sample stage's operations: the samples the simulated device formed (and
    // those carried) must be hardware_ops' figures, derived from the plan on their own.
    if (sr.samples_formed != hc.samples || sr.samples_carried != hc.carried) {
        std::fprintf(stderr,
                     "render_pipeline: the SystemC sample stage formed %zu samples and carried %zu; the counted "
                     "hardware path says %zu and %zu\n",
                     sr.samples_formed, sr.samples_carried, hc.samples, hc.carried);
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
             {"samples_formed", sr.samples_formed}, {"samples_carried", sr.samples_carried},
             {"bit_exact_vs_golden", true}, {"vcd", o.vcd.empty() ? json(nullptr) : json(o.vcd)}};
    return 0;
#else
    (void)o;
    (void)d;
    throw scene::scene_error("--sim: this build has no SystemC pipeline (target shading_pipeline_sim); use --no-sim");
#endif
}

}  // namespace

void compare_all(render_data& d) {
    const auto t = std::chrono::steady_clock::now();
    d.hw_img = to_image(d.hw);
    d.pp_img = to_image(d.pp);
    d.pairs = {
        {"interpolation", &d.hw_img, &d.pp_img, "hardware vs per-pixel shading through the same device (golden)"},
        {"total", &d.hw_img, &d.phong, "hardware vs Phong with exact cos^n"},
        {"brdf", &d.devref, &d.phong, "device reference (double) vs Phong: the device BRDF's own error"},
        {"sample_stage", &d.pp_img, &d.devref,
         "per-pixel golden vs device reference (double): the fixed-point sample stage's own error"},
    };
    d.zone_px.assign(zone_count, 0);
    for (std::size_t i = 0; i < d.hw.zone.size(); ++i)
        if (d.hw.covered[i] && d.hw.zone[i] < zone_count) ++d.zone_px[d.hw.zone[i]];
    for (const auto& pd : d.pairs) {
        json e;
        e["what"] = pd.what;
        const error_stats w = compare(*pd.a, *pd.ref);
        d.whole[pd.key] = w;
        e["image"] = stats_json(w);
        json zones = json::object();
        for (unsigned z = 0; z < zone_count; ++z)
            if (d.zone_px[z]) zones[zone_name(z)] = stats_json(compare(*pd.a, *pd.ref, &d.hw.zone, static_cast<int>(z)));
        e["zones"] = zones;
        d.errors[pd.key] = e;
    }
    // What the display shows: both images rounded to 8-bit levels (the PNGs), the same pairs.
    const scene::shaded_image hw8 = displayed(d.hw_img);
    d.interp_8bit = compare(hw8, displayed(d.pp_img));
    d.total_8bit = compare(hw8, displayed(d.phong));
    d.errors["interpolation"]["displayed_8bit"] = stats_json(d.interp_8bit);
    d.errors["total"]["displayed_8bit"] = stats_json(d.total_8bit);
    d.wall["metrics"] = seconds_since(t);
}

int render(const options& o, const plan_maker* maker) {
    const auto t_start = std::chrono::steady_clock::now();
    render_data d;
    d.maker = maker;
    auto& wall = d.wall;
    d.cfg = plan_config_of(o);
    validate(d.cfg);
    d.dev = {scene::parse_device(o.device), o.mode == "wrap" ? overflow_mode::wrap : overflow_mode::saturate};
    auto t = std::chrono::steady_clock::now();
    d.s = load_world(o);
    wall["load"] = seconds_since(t);
    d.k = frame_constants_of(d.s);

    t = std::chrono::steady_clock::now();
    d.r = scene::rasterise(d.s);
    wall["rasterise"] = seconds_since(t);
    t = std::chrono::steady_clock::now();
    d.p = maker ? maker->make(d) : make_plan(d.r, d.k, d.dev, d.cfg);
    wall["plan"] = seconds_since(t);
    t = std::chrono::steady_clock::now();
    d.hw = golden_frame(d.p, d.k, d.dev, d.cfg);
    wall["golden_frame"] = seconds_since(t);
    t = std::chrono::steady_clock::now();
    d.pp = per_pixel_frame(d.r, d.k, d.dev);
    wall["per_pixel_frame"] = seconds_since(t);
    t = std::chrono::steady_clock::now();
    d.phong = scene::render_phong(d.r, &d.sp);
    wall["phong"] = seconds_since(t);
    t = std::chrono::steady_clock::now();
    // The scan-line Phong: the same image to rounding (its difference from the per-pixel one is in
    // the report), counted with stepped geometry.
    const scene::shaded_image scan = scene::render_phong_scanline(d.r, &d.sl, &d.sl_steps, d.cfg.walk_edges);
    d.errors["scanline_phong"]["image"] = stats_json(compare(scan, d.phong));
    d.errors["scanline_phong"]["what"] = "scan-line Phong vs per-pixel Phong (the two baselines' images)";
    wall["phong_scanline"] = seconds_since(t);
    t = std::chrono::steady_clock::now();
    d.devref = scene::render_device(d.r, d.dev, &d.sd);
    wall["device_reference"] = seconds_since(t);
    d.hc = hardware_ops(d.p, d.cfg, d.dev, d.k.n);
    plan_config other = d.cfg;
    other.unit = d.cfg.unit == geometry_unit::stepped ? geometry_unit::scratch : geometry_unit::stepped;
    d.hc_other = hardware_ops(d.p, other, d.dev, d.k.n);

    d.sim_clocks_per_px = d.sim_px_per_s = d.sim_px_per_cpu_s = std::numeric_limits<double>::quiet_NaN();
    if (o.sim)
        if (const int rc = run_sim(o, d)) return rc;

    compare_all(d);
    json rep = report_json(o, d);

    staged_output out(o.out);
    if (o.images) write_images(o, d, out);
    wall["total"] = seconds_since(t_start);
    rep["wall_seconds"] = wall;
    rep["files"] = d.written;
    if (!o.md_name.empty()) write_text(out.path(o.md_name), report_md(o, d));
    if (!o.json_name.empty()) write_text(out.path(o.json_name), rep.dump(2) + "\n");
    out.commit();
    print_summary(o, d);
    return 0;
}

}  // namespace shading::render_program
