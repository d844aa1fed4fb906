// The square-and-multiply designs (ours, for comparison; sqmul_words.h): left to right with one
// multiplier and right to left with two, each at P words Q1.15 .. Q1.20. Per design: the worst
// relative error where cos^n >= 0.56 (the quadratic-BRDF paper's measure) and where cos^n >= 0.1,
// over every Q1.15 code and n in [1, --n-max]; the head at --size rendered through it at every --n
// against exact Phong (the device reference's image NMSE, as head_study measures the devices:
// replayed by shading_replay, bit-equal to the scene library's renders). Per walk: the clocks per
// sample from the golden models' steps, checked against the hand-derived formula for every n.
// Writes, into --out:
//   sqmul_words.csv / .md   one row per design
//   sqmul_clocks.csv        per n in [1, 1023]: the clocks per sample of each walk
//   build/bin/sqmul_study --out out
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "testbenches/common/exit_status.h"
#include "testbenches/options/tool_options.h"
#include "head_surface.h"
#include "scene/image.h"
#include "sqmul_words.h"

using namespace shading;
using namespace shading::study;

namespace {

struct design_row {
    sqmul_design d;
    rel_error rel056, rel010;
    std::vector<scene::image_diff> image;  // per --n
};

// Every design's relative errors, then its head renders at every --n (one Phong replay per n).
std::vector<design_row> measure(const shading_replay& replay, const std::vector<unsigned>& ns, unsigned n_max) {
    std::vector<design_row> rows;
    for (const auto& d : sqmul_designs()) {
        const auto f = [&d](unsigned n, uint64_t c) { return sqmul_design_value(d, n, c); };
        rows.push_back({d, worst_rel_error(f, 0.56, n_max), worst_rel_error(f, 0.1, n_max), {}});
    }
    for (unsigned n : ns) {
        const auto phong = replay.phong(n);
        for (auto& r : rows) {
            const auto unit = [&r](unsigned nn, uint32_t c, const std::array<uint64_t, 3>& ksi) {
                return sqmul_design_out(r.d, nn, c, ksi);
            };
            r.image.push_back(shading_replay::compare(replay.specular(n, unit), phong));
        }
    }
    return rows;
}

// The worst image NMSE over the --n in [2, 500] (the squared device's image goal's range), and where.
std::pair<double, unsigned> worst_image(const design_row& r, const std::vector<unsigned>& ns) {
    std::pair<double, unsigned> w{0, 0};
    for (std::size_t i = 0; i < ns.size(); ++i)
        if (ns[i] >= 2 && ns[i] <= 500 && r.image[i].nmse > w.first) w = {r.image[i].nmse, ns[i]};
    return w;
}

bool write_rows(const std::string& out_dir, const std::vector<design_row>& rows, const std::vector<unsigned>& ns) {
    std::ofstream csv(out_dir + "/sqmul_words.csv"), md(out_dir + "/sqmul_words.md");
    csv << "design,label,p_frac,maxrel056,maxrel056_n,n_above_1pct_056,maxrel010,maxrel010_n,n_above_1pct_010";
    for (unsigned n : ns) csv << ",image_nmse_n" << n << ",image_max_levels_n" << n;
    csv << ",image_nmse_worst_2_500,image_nmse_worst_at\n";
    md << "| design | worst rel. error, cos^n >= 0.56 (n) | worst rel. error, cos^n >= 0.1 (n) | image NMSE";
    for (unsigned n : ns) md << " n = " << n << " |";
    md << " worst image NMSE, n in 2..500 (n) |\n|---|---|---|";
    for (std::size_t i = 0; i <= ns.size(); ++i) md << "---|";
    md << '\n';
    csv.precision(6);
    for (const auto& r : rows) {
        const auto w = worst_image(r, ns);
        csv << r.d.id << ",\"" << r.d.label << "\"," << r.d.p_frac << ',' << r.rel056.worst << ',' << r.rel056.at_n
            << ',' << r.rel056.n_above_1pct << ',' << r.rel010.worst << ',' << r.rel010.at_n << ','
            << r.rel010.n_above_1pct;
        char buf[160];
        std::snprintf(buf, sizeof buf, "| %s | %.4f %% (%u) | %.4f %% (%u) |", r.d.label.c_str(), 100 * r.rel056.worst,
                      r.rel056.at_n, 100 * r.rel010.worst, r.rel010.at_n);
        md << buf;
        for (const auto& im : r.image) {
            csv << ',' << im.nmse << ',' << im.max_abs;
            std::snprintf(buf, sizeof buf, " %.3g |", im.nmse);
            md << buf;
        }
        csv << ',' << w.first << ',' << w.second << '\n';
        std::snprintf(buf, sizeof buf, " %.3g (%u) |\n", w.first, w.second);
        md << buf;
    }
    return static_cast<bool>(csv) && static_cast<bool>(md);
}

// Clocks per sample of each walk for n in [1, 1023], from the golden models; false (and a message)
// where they differ from the formula.
bool write_clocks(const std::string& out_dir, unsigned n_max) {
    std::ofstream csv(out_dir + "/sqmul_clocks.csv");
    csv << "n,clocks_l2r,clocks_r2l\n";
    bool agree = true;
    for (unsigned n = 1; n < 1024; ++n) {
        const unsigned l = sqmul_clocks(sqmul_walk::left_to_right, n), r = sqmul_clocks(sqmul_walk::right_to_left, n);
        csv << n << ',' << l << ',' << r << '\n';
        if (l != sqmul_clocks_formula(sqmul_walk::left_to_right, n) ||
            r != sqmul_clocks_formula(sqmul_walk::right_to_left, n)) {
            std::fprintf(stderr, "sqmul_study: n = %u: the golden models' clocks %u, %u differ from the formula\n", n, l,
                         r);
            agree = false;
        }
    }
    for (const auto w : {sqmul_walk::left_to_right, sqmul_walk::right_to_left}) {
        unsigned worst = 0, sum = 0;
        for (unsigned n = 1; n <= n_max; ++n) {
            worst = std::max(worst, sqmul_clocks(w, n));
            sum += sqmul_clocks(w, n);
        }
        std::printf("clocks per sample, %s: n = 5: %u, 20: %u, 100: %u, 1000: %u; over n in [1, %u]: worst %u, mean %.3f\n",
                    w == sqmul_walk::left_to_right ? "left to right" : "right to left", sqmul_clocks(w, 5),
                    sqmul_clocks(w, 20), sqmul_clocks(w, 100), sqmul_clocks(w, 1000), n_max, worst,
                    static_cast<double>(sum) / n_max);
    }
    return agree && static_cast<bool>(csv);
}

}  // namespace

int main(int argc, char* argv[]) {
    shading::tb::sqmul_study_options o;
    if (auto rc = shading::tb::parse_sqmul_study(argc, argv, o)) return *rc;  // an n outside 1..1000 is bad usage
    try {
        const auto t0 = std::chrono::steady_clock::now();
        head_surface head(o.data_dir, o.size);
        const shading_replay replay(head.raster());
        const std::vector<design_row> rows = measure(replay, o.ns, o.n_max);
        const bool rows_written = write_rows(o.out, rows, o.ns);
        const bool clocks_agree = write_clocks(o.out, o.n_max);
        std::ifstream md(o.out + "/sqmul_words.md");
        std::printf("head %ux%u; relative errors over n in [1, %u]\n%s", o.size, o.size, o.n_max,
                    std::string(std::istreambuf_iterator<char>(md), {}).c_str());
        std::printf("sqmul_study: wrote %s/{sqmul_words.csv,sqmul_words.md,sqmul_clocks.csv} in %.1f s\n", o.out.c_str(),
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        return rows_written && clocks_agree ? tb::exit_success : tb::exit_failure;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sqmul_study: %s\n", e.what());
        return tb::exit_failure;
    }
}
