// The head scan at --size (512) rendered through the scene library once per n, by exact Phong and
// through every study device (study_devices.h) and every variant of the squared-quadratic device's
// fit (squared_variants.h). Writes, into --out:
//   head_device_table.csv / .md  per device and n: the device reference's image against exact Phong
//                                (NMSE, largest error in 8-bit levels), the worst relative error
//                                above 0.56 and the NMSE over the head's N.H distribution; also for
//                                the real-valued laws (ours, and the trial law at n' in [2, 4))
//   squared_fit.csv              per variant: the worst relative error above 0.56 over n in
//                                [1, 1000] (where, how many n above 1 %) and the image NMSE and
//                                largest error against Phong at every --n
//   squared_fit_maxrel.csv       per n in [1, 1000]: each variant's worst relative error above 0.56
//   head_scan.csv                per n in [1, --scan-max]: the image NMSE and largest error against
//                                Phong of the square-and-multiply baseline and of every bend variant
//                                (the device is variant s2), replayed (shading_replay, bit-equal)
// and prints whether the devices meet the image targets (NMSE <= 1e-6 at n = 20, <= 1e-5 for every
// n of the exponents sweep 2..500).
//   build/bin/head_study --out out
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "testbenches/common/exit_status.h"
#include "testbenches/options/tool_options.h"
#include "head_surface.h"
#include "scene/image.h"
#include "scene/shade.h"
#include "squared_variants.h"
#include "study_devices.h"
#include "study_metrics.h"
#include "trial_law.h"
#include "reference/brdf_reference.h"

using namespace shading;
using namespace shading::study;

namespace {

struct variant_row {
    squared_variant v;
    const char* group;
    std::vector<double> maxrel;  // per n, 1..1000
    double worst = 0;
    unsigned worst_n = 0, above_1pct = 0;
    std::vector<scene::image_diff> image;  // per --n
    std::vector<scene::image_diff> scan;   // per n in [1, --scan-max] (index n - 1)
};

// The scan's summary over n in [lo, hi]: the worst image NMSE, where, and how many n exceed `limit`.
struct scan_summary {
    double worst = 0;
    unsigned at = 0, above = 0;
};
scan_summary summarise(const std::vector<scene::image_diff>& scan, unsigned lo, unsigned hi, double limit) {
    scan_summary s;
    for (unsigned n = lo; n <= hi && n <= scan.size(); ++n) {
        const double e = scan[n - 1].nmse;
        if (e > s.worst) s.worst = e, s.at = n;
        s.above += e > limit;
    }
    return s;
}

double worst_over(const std::vector<unsigned>& ns, const std::vector<scene::image_diff>& d, unsigned lo, unsigned hi) {
    double w = 0;
    for (std::size_t i = 0; i < ns.size(); ++i)
        if (ns[i] >= lo && ns[i] <= hi) w = std::max(w, d[i].nmse);
    return w;
}

// The study devices, then the real-valued laws for comparison: their BRDF at the code's cos, its out
// codes rounded to nearest on Q9.8 (1/256 of a level: far below every error measured). The trial
// law's fitted a is fitted on the head's distribution at each n of `ns`.
std::vector<study_device> devices_and_laws(const cos_distribution& dist, const std::vector<unsigned>& ns) {
    std::vector<study_device> devices = study_devices();
    std::vector<double> trial_a(1001, 0.0);
    for (unsigned n : ns) trial_a[n] = trial_a_fitted(dist, n);
    auto law = [](std::string id, std::string label, std::function<double(unsigned, double)> f) {
        const auto brdf = [f](unsigned n, uint64_t code) { return f(n, std::ldexp(static_cast<double>(code), -15)); };
        const auto out = [brdf](unsigned n, uint32_t code, const std::array<uint64_t, 3>& ksi) {
            std::array<uint64_t, 3> o{};
            for (std::size_t i = 0; i < 3; ++i) o[i] = static_cast<uint64_t>(std::llround(brdf(n, code) * ksi[i] * 256.0));
            return o;
        };
        return study_device{std::move(id), std::move(label), brdf, out};
    };
    devices.push_back(law("squared_law", "squared-quadratic law (ours), real-valued",
                          [](unsigned n, double c) { return ref::squared_law(c, n); }));
    devices.push_back(law("trial_inflection", "trial law, n' in [2,4), a at the inflection, real-valued",
                          [](unsigned n, double c) { return trial_law(c, trial_a_inflection(n), n); }));
    devices.push_back(law("trial_fitted", "trial law, n' in [2,4), a fitted on the head, real-valued",
                          [trial_a](unsigned n, double c) { return trial_law(c, trial_a[n], n); }));
    return devices;
}

// The fit's variants with their worst relative error above 0.56 for every n (cheap: no rendering).
std::vector<variant_row> variant_rows(const grid& g) {
    std::vector<variant_row> rows;
    for (const auto& v : bend_variants()) rows.push_back({v, "bend", {}, 0, 0, 0, {}, {}});
    for (const auto& v : fraction_variants()) rows.push_back({v, "fraction", {}, 0, 0, 0, {}, {}});
    for (auto& r : rows) {
        r.maxrel.assign(1001, 0.0);
        for (unsigned n = 1; n <= 1000; ++n) {
            r.maxrel[n] = g.max_rel_err_056(n, [&r, n](uint64_t c) { return variant_value(r.v, n, c); });
            r.above_1pct += r.maxrel[n] > 0.01;
            if (r.maxrel[n] > r.worst) r.worst = r.maxrel[n], r.worst_n = n;
        }
    }
    return rows;
}

// Per device, per n of --n: the image against Phong, the worst relative error above 0.56 and the
// NMSE over the head's N.H distribution.
struct device_measures {
    std::vector<std::vector<scene::image_diff>> img;
    std::vector<std::vector<double>> rel, hnmse;
};

// One Phong render per n; every device and variant against it (the variants' images into rows).
device_measures render_every_n(head_surface& head, const cos_distribution& dist, const grid& g,
                               const std::vector<unsigned>& ns, const std::vector<study_device>& devices,
                               std::vector<variant_row>& rows) {
    device_measures m;
    m.img.resize(devices.size());
    m.rel.resize(devices.size());
    m.hnmse.resize(devices.size());
    for (unsigned n : ns) {
        head.set_n(n);
        const scene::shaded_image phong = scene::render_phong(head.raster());
        const std::vector<double> exact = distribution_exact(dist, n);
        for (std::size_t d = 0; d < devices.size(); ++d) {
            const auto& dev = devices[d];
            m.img[d].push_back(scene::compare_images(scene::render_specular(head.raster(), dev.out), phong));
            const auto brdf = [&dev, n](uint64_t c) { return dev.brdf(n, c); };
            m.rel[d].push_back(g.max_rel_err_056(n, brdf));
            m.hnmse[d].push_back(distribution_nmse(dist, n, brdf, &exact));
        }
        for (auto& r : rows) {
            const auto unit = [&r](unsigned nn, uint32_t c, const std::array<uint64_t, 3>& ksi) {
                return variant_out(r.v, nn, c, ksi);
            };
            r.image.push_back(scene::compare_images(scene::render_specular(head.raster(), unit), phong));
        }
    }
    return m;
}

// Every n in [1, scan_max]: the images replayed from one pass over the geometry (shading_replay),
// for the squared device (= variant s2), the baseline and every bend variant (into rows); writes
// head_scan.csv. Returns the baseline's.
std::vector<scene::image_diff> scan_every_n(const head_surface& head, const std::vector<study_device>& devices,
                                            std::vector<variant_row>& rows, unsigned scan_max,
                                            const std::string& out_dir) {
    const auto t_scan = std::chrono::steady_clock::now();
    std::vector<scene::image_diff> scan_sqmul;
    const shading_replay replay(head.raster());
    const auto& sqmul = *std::find_if(devices.begin(), devices.end(), [](const study_device& d) { return d.id == "sqmul"; });
    for (unsigned n = 1; n <= scan_max; ++n) {
        const auto phong = replay.phong(n);
        scan_sqmul.push_back(shading_replay::compare(replay.specular(n, sqmul.out), phong));
        for (auto& r : rows) {
            if (std::string(r.group) != "bend") continue;  // the word length barely moves the image
            const auto unit = [&r](unsigned nn, uint32_t c, const std::array<uint64_t, 3>& ksi) {
                return variant_out(r.v, nn, c, ksi);
            };
            r.scan.push_back(shading_replay::compare(replay.specular(n, unit), phong));
        }
    }
    std::ofstream sc(out_dir + "/head_scan.csv");
    sc << "n,image_nmse_sqmul,image_max_sqmul";
    for (const auto& r : rows)
        if (!r.scan.empty()) sc << ",image_nmse_" << r.v.id << ",image_max_" << r.v.id;
    sc << '\n';
    sc.precision(6);
    for (unsigned n = 1; n <= scan_max; ++n) {
        sc << n << ',' << scan_sqmul[n - 1].nmse << ',' << scan_sqmul[n - 1].max_abs;
        for (const auto& r : rows)
            if (!r.scan.empty()) sc << ',' << r.scan[n - 1].nmse << ',' << r.scan[n - 1].max_abs;
        sc << '\n';
    }
    std::printf("scan of n = 1..%u: %.1f s wall\n", scan_max,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t_scan).count());
    return scan_sqmul;
}

// head_device_table.csv and its markdown twin (one table per measure, a row per device, a column per
// n); false if either could not be written.
bool write_device_tables(const std::string& out_dir, const std::vector<study_device>& devices,
                         const std::vector<unsigned>& ns, const device_measures& m) {
    std::ofstream tab(out_dir + "/head_device_table.csv");
    tab << "device,label,n,image_nmse,image_max_levels,maxrel056,head_nmse\n";
    tab.precision(6);
    for (std::size_t d = 0; d < devices.size(); ++d)
        for (std::size_t i = 0; i < ns.size(); ++i)
            tab << devices[d].id << ",\"" << devices[d].label << "\"," << ns[i] << ',' << m.img[d][i].nmse << ','
                << m.img[d][i].max_abs << ',' << m.rel[d][i] << ',' << m.hnmse[d][i] << '\n';

    std::ofstream md(out_dir + "/head_device_table.md");
    auto table = [&](const char* title, auto cell) {
        md << "\n" << title << "\n\n| device |";
        for (unsigned n : ns) md << " n = " << n << " |";
        md << "\n|---|";
        for (std::size_t i = 0; i < ns.size(); ++i) md << "---|";
        md << '\n';
        for (std::size_t d = 0; d < devices.size(); ++d) {
            md << "| " << devices[d].id << " |";
            for (std::size_t i = 0; i < ns.size(); ++i) {
                char buf[32];
                cell(buf, sizeof buf, d, i);
                md << ' ' << buf << " |";
            }
            md << '\n';
        }
    };
    table("Device reference against exact Phong, head, NMSE:", [&](char* b, std::size_t k, std::size_t d, std::size_t i) {
        std::snprintf(b, k, "%.2e", m.img[d][i].nmse);
    });
    table("Device reference against exact Phong, head, largest error (8-bit levels):",
          [&](char* b, std::size_t k, std::size_t d, std::size_t i) { std::snprintf(b, k, "%.2f", m.img[d][i].max_abs); });
    table("Worst relative error where cos^n >= 0.56 (%):", [&](char* b, std::size_t k, std::size_t d, std::size_t i) {
        std::snprintf(b, k, "%.3f", 100.0 * m.rel[d][i]);
    });
    table("NMSE of the BRDF over the head's N.H distribution:", [&](char* b, std::size_t k, std::size_t d, std::size_t i) {
        std::snprintf(b, k, "%.2e", m.hnmse[d][i]);
    });
    return tab && md;
}

// squared_fit.csv and squared_fit_maxrel.csv; false if either could not be written.
bool write_fit_tables(const std::string& out_dir, const std::vector<variant_row>& rows, const std::vector<unsigned>& ns) {
    std::ofstream fit(out_dir + "/squared_fit.csv");
    fit << "variant,label,group,bend_shifts,q_frac,worst_maxrel056_1_1000,at_n,n_above_1pct";
    for (unsigned n : ns) fit << ",image_nmse_n" << n << ",image_max_n" << n;
    fit << ",worst_image_nmse_2_500,scan_worst_image_nmse_2_500,scan_at_n,scan_n_above_1e-5_2_500,"
           "scan_worst_image_nmse_1_1000,scan_at_n\n";
    fit.precision(6);
    for (const auto& r : rows) {
        std::string shifts;
        for (unsigned s : r.v.bend_shifts) shifts += (shifts.empty() ? "" : "+") + std::to_string(s);
        fit << r.v.id << ",\"" << r.v.label << "\"," << r.group << ',' << (shifts.empty() ? "none" : shifts) << ','
            << r.v.q_frac << ',' << r.worst << ',' << r.worst_n << ',' << r.above_1pct;
        for (const auto& d : r.image) fit << ',' << d.nmse << ',' << d.max_abs;
        fit << ',' << worst_over(ns, r.image, 2, 500);
        if (r.scan.empty()) {
            fit << ",,,,,\n";  // not scanned (the word lengths)
        } else {
            const scan_summary s500 = summarise(r.scan, 2, 500, 1e-5), s1000 = summarise(r.scan, 1, 1000, 1e-5);
            fit << ',' << s500.worst << ',' << s500.at << ',' << s500.above << ',' << s1000.worst << ',' << s1000.at
                << '\n';
        }
    }
    std::ofstream mr(out_dir + "/squared_fit_maxrel.csv");
    mr << "n";
    for (const auto& r : rows) mr << ",maxrel056_" << r.v.id;
    mr << '\n';
    mr.precision(6);
    for (unsigned n = 1; n <= 1000; ++n) {
        mr << n;
        for (const auto& r : rows) mr << ',' << r.maxrel[n];
        mr << '\n';
    }
    return fit && mr;
}

// Per device: the worst relative error, the image NMSE at n = 20, the worst over 2..500 and whether
// the image targets are met; one summary row each to $SHADING_SUMMARY when it is set.
void print_devices(const std::vector<study_device>& devices, const std::vector<unsigned>& ns, const device_measures& m,
                   const cos_distribution& dist, unsigned size) {
    std::printf("head %ux%u, %zu samples; n =", size, size, dist.samples);
    for (unsigned n : ns) std::printf(" %u", n);
    std::printf("\nimage targets: NMSE <= 1e-6 at n = 20 and <= 1e-5 for every n in 2..500 (of the n above)\n");
    std::printf("%-12s %13s %11s %11s %8s\n", "device", "rel err (n)", "NMSE n=20", "worst 2-500", "targets");
    const char* summary_path = std::getenv("SHADING_SUMMARY");
    std::ofstream tsv;
    if (summary_path != nullptr && *summary_path != '\0') tsv.open(summary_path, std::ios::app);
    const auto it20 = std::find(ns.begin(), ns.end(), 20u);
    for (std::size_t d = 0; d < devices.size(); ++d) {
        const double at20 = it20 == ns.end() ? -1.0 : m.img[d][static_cast<std::size_t>(it20 - ns.begin())].nmse;
        const double w = worst_over(ns, m.img[d], 2, 500);
        const bool met = at20 >= 0 && at20 <= 1e-6 && w <= 1e-5;
        std::size_t worst_i = 0;
        for (std::size_t i = 0; i < ns.size(); ++i)
            if (m.rel[d][i] > m.rel[d][worst_i]) worst_i = i;
        std::printf("%-12s %7.3f%% (%u) %11.2e %11.2e %8s\n", devices[d].id.c_str(), 100 * m.rel[d][worst_i],
                    ns[worst_i], at20, w, met ? "met" : "not met");
        if (tsv.is_open())
            tsv << "head_study\t" << devices[d].id << '\t' << dist.samples << "\t-\t" << at20
                << "\t-\timage NMSE vs Phong at n=20 (head " << size << "); worst over n in 2..500: " << w
                << "; targets " << (met ? "met" : "not met") << '\n';
    }
}

// Per variant: its worst relative error, its image NMSE at n = 20 and over 2..500, and the scan's
// worst; then the squared device against the baseline over the scan.
void print_variants(const std::vector<variant_row>& rows, const std::vector<unsigned>& ns,
                    const std::vector<scene::image_diff>& scan_sqmul, unsigned scan_max) {
    const auto it20 = std::find(ns.begin(), ns.end(), 20u);
    std::printf("\n%-6s %-8s %-40s %9s %5s %5s %11s %11s %15s %5s\n", "group", "variant", "label", "worst rel", "at n",
                ">1%", "NMSE n=20", "worst 2-500", "scan: 2-500 (n)", ">1e-5");
    for (const auto& r : rows) {
        const double at20 = it20 == ns.end() ? -1.0 : r.image[static_cast<std::size_t>(it20 - ns.begin())].nmse;
        std::printf("%-6.6s %-8s %-40s %8.3f%% %5u %5u %11.2e %11.2e", r.group, r.v.id.c_str(), r.v.label.c_str(),
                    100 * r.worst, r.worst_n, r.above_1pct, at20, worst_over(ns, r.image, 2, 500));
        if (r.scan.empty()) {
            std::printf("\n");
        } else {
            const scan_summary s500 = summarise(r.scan, 2, 500, 1e-5);
            std::printf(" %9.2e (%3u) %5u\n", s500.worst, s500.at, s500.above);
        }
    }
    if (scan_max > 0) {
        const auto& device = *std::find_if(rows.begin(), rows.end(),
                                           [](const variant_row& r) { return r.v.id == squared_device_variant().id; });
        const scan_summary q = summarise(scan_sqmul, 2, 500, 1e-5), dv = summarise(device.scan, 2, 500, 1e-5);
        std::printf("\nevery n in 2..%u: squared device worst image NMSE %.2e (n = %u), %u n above 1e-5; "
                    "square-and-multiply %.2e (n = %u)\n",
                    std::min(scan_max, 500u), dv.worst, dv.at, dv.above, q.worst, q.at);
    }
}

}  // namespace

int main(int argc, char* argv[]) {
    shading::tb::head_study_options o;
    if (auto rc = shading::tb::parse_head_study(argc, argv, o)) return *rc;  // an n outside 1..1000 is bad usage (exit 2)
    const std::string &out_dir = o.out, &data_dir = o.data_dir;
    const unsigned size = o.size, scan_max = o.scan_max;
    const std::vector<unsigned>& ns = o.ns;

    try {
        const auto t0 = std::chrono::steady_clock::now();
        head_surface head(data_dir, size);
        const cos_distribution dist = nh_distribution(head.raster());
        const grid g;
        const std::vector<study_device> devices = devices_and_laws(dist, ns);
        std::vector<variant_row> rows = variant_rows(g);
        const device_measures m = render_every_n(head, dist, g, ns, devices, rows);
        std::vector<scene::image_diff> scan_sqmul;
        if (scan_max > 0) scan_sqmul = scan_every_n(head, devices, rows, scan_max, out_dir);
        const bool devices_written = write_device_tables(out_dir, devices, ns, m);
        const bool fit_written = write_fit_tables(out_dir, rows, ns);
        print_devices(devices, ns, m, dist, size);
        print_variants(rows, ns, scan_sqmul, scan_max);
        std::printf("head_study: wrote %s/{head_device_table.csv,head_device_table.md,squared_fit.csv,"
                    "squared_fit_maxrel.csv} in %.1f s\n",
                    out_dir.c_str(), std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        return devices_written && fit_written ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "head_study: %s\n", e.what());
        return 1;
    }
}
