// The interpolation paper's accuracy claim measured: NMSE of the interpolated raster line against the exact
// intensity, per unit variant and interval length N = 2^m (m = 2..6), through the bit-accurate
// golden models (the benches prove them bit-exact to the SystemC units). Plus the adaptive degree
// the paper proposes: per interval, the quadratic where the cubic term is small (|A| <= tau
// intensity levels, a stand-in for the paper's curvature zones, whose figure is not available),
// the cubic elsewhere; with its mean Horner cycles per pixel (4 quadratic, 6 cubic).
// NMSE = sum (I_hw - I_exact)^2 / sum I_exact^2 over the line's pixels.
// The /3 grouping (interp_div3_grouping.csv, beside --csv): today's /3 on the whole weighted sum
// against the interpolation paper's /3 on a partial sum, with either divider: the error of A and C against the
// real coefficients of the same Q8.8 samples (the line's intervals, and uniform random samples)
// and the line's NMSE.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "testbenches/options/tool_options.h"
#include "formats/fixed_point.h"
#include "testbenches/interp/interp_line.h"

using namespace shading;
using namespace shading::tb;

namespace {

struct line_error {
    double nmse = 0, max_abs = 0, cycles_per_pixel = 0;
    unsigned quad_intervals = 0;
};

// Interpolates the whole line; `coefs(interval, quad)` gives each interval's coefficients and sets
// `quad` when it picks the degree-2 polynomial.
template <typename Coefs>
line_error interpolate_with(const line_scenario& line, Coefs coefs) {
    double num = 0, den = 0, cycles = 0;
    line_error r;
    for (const auto& iv : line.intervals) {
        bool quad = false;
        const auto k = coefs(iv, quad);
        r.quad_intervals += quad ? 1u : 0u;
        for (unsigned j = 0; j < iv.len; ++j) {
            const uint64_t t = uint64_t{j} << (interp::t_fmt.frac - line.m);
            const double hw = to_real(interp::golden_horner(k, t, quad), interp::coef_fmt);
            const double exact = line.exact[iv.first_pixel + j];
            num += (hw - exact) * (hw - exact);
            den += exact * exact;
            r.max_abs = std::max(r.max_abs, std::abs(hw - exact));
            cycles += quad ? 4.0 : 6.0;
        }
    }
    r.nmse = num / den;
    r.cycles_per_pixel = cycles / line.width;
    return r;
}
// The same with one variant per interval picked by `pick(interval)`.
template <typename Pick>
line_error interpolate(const line_scenario& line, Pick pick) {
    return interpolate_with(line, [&pick](const line_interval& iv, bool& quad) {
        const variant v = pick(iv);
        quad = is_quad(v);
        return variant_coefs(v, iv);
    });
}

// One cubic coefficient unit by sample set, divider and grouping of the /3.
struct cubic_unit {
    interp::sample_set set;
    interp::div3_mode div;
    interp::div3_grouping grouping;
    std::string name() const {
        return std::string(set == interp::sample_set::case1 ? "cubic1_" : "cubic2_") +
               (div == interp::div3_mode::shift_add ? "shiftadd" : "exactdiv") +
               (grouping == interp::div3_grouping::whole_sum ? "" : "_partialsum");
    }
    interp::cubic_coefs coefs(const std::array<uint64_t, 4>& i) const {
        return interp::golden_cubic_coefs(i, set, div, grouping);
    }
    const std::array<uint64_t, 4>& samples(const line_interval& iv) const {
        return set == interp::sample_set::case1 ? iv.c1 : iv.c2;
    }
};
std::vector<cubic_unit> all_cubic_units() {
    std::vector<cubic_unit> v;
    for (auto g : {interp::div3_grouping::whole_sum, interp::div3_grouping::partial_sum})
        for (auto set : {interp::sample_set::case1, interp::sample_set::case2})
            for (auto div : {interp::div3_mode::shift_add, interp::div3_mode::exact}) v.push_back({set, div, g});
    return v;
}

// Error of A and C (intensity levels) against the real coefficients of the same samples.
struct coef_error {
    double a_max = 0, a_sq = 0, c_max = 0, c_sq = 0;
    std::size_t n = 0;
    void add(const cubic_unit& u, const std::array<uint64_t, 4>& i) {
        const auto k = u.coefs(i);
        const auto r = ref::cubic_coefs({to_real(i[0], interp::sample_fmt), to_real(i[1], interp::sample_fmt),
                                         to_real(i[2], interp::sample_fmt), to_real(i[3], interp::sample_fmt)},
                                        u.set);
        const double ea = static_cast<double>(k.a) * interp::coef_fmt.lsb() - r.a;
        const double ec = static_cast<double>(k.c) * interp::coef_fmt.lsb() - r.c;
        a_max = std::max(a_max, std::abs(ea));
        c_max = std::max(c_max, std::abs(ec));
        a_sq += ea * ea;
        c_sq += ec * ec;
        ++n;
    }
    double a_rms() const { return std::sqrt(a_sq / static_cast<double>(n)); }
    double c_rms() const { return std::sqrt(c_sq / static_cast<double>(n)); }
};

}  // namespace

int main(int argc, char* argv[]) {
    interp_study_options o;
    if (auto rc = parse_interp_study(argc, argv, o)) return *rc;
    const std::string& csv_path = o.csv;
    const std::string& grouping_path = o.grouping_csv;
    const unsigned width = o.width;

    std::ofstream csv(csv_path);
    csv << "m,N,variant,tau,nmse,max_abs_err,quad_intervals,intervals,horner_cycles_per_pixel\n";
    std::ofstream summary;
    if (const char* p = std::getenv("SHADING_SUMMARY"); p != nullptr && *p != '\0') summary.open(p, std::ios::app);

    std::printf("%3s %4s %-26s %8s %11s %9s %7s\n", "m", "N", "variant", "tau", "NMSE", "max|err|", "cyc/px");
    const double inf = std::numeric_limits<double>::infinity();
    for (unsigned m = interp::m_min; m <= interp::m_max; ++m) {
        const auto line = make_line(width, m);
        auto emit = [&](const std::string& name, double tau, const line_error& e) {
            csv << m << ',' << line.n() << ',' << name << ',' << tau << ',' << e.nmse << ',' << e.max_abs << ','
                << e.quad_intervals << ',' << line.intervals.size() << ',' << e.cycles_per_pixel << '\n';
            std::printf("%3u %4u %-26s %8g %11.3e %9.3f %7.2f\n", m, line.n(), name.c_str(), tau, e.nmse, e.max_abs,
                        e.cycles_per_pixel);
            if (summary && (m == 3 || m == 5) && (name != "adaptive" || tau == 2.0) &&
                name.find("_partialsum") == std::string::npos)
                summary << "interp_nmse\t" << name << (name == "adaptive" ? "_tau2" : "") << "_N" << line.n() << '\t'
                        << width << "\t-\t" << std::scientific << std::setprecision(2) << e.nmse << std::defaultfloat
                        << "\t" << e.cycles_per_pixel << "\tNMSE vs exact intensity (Horner golden); the interpolation paper: <= 1e-4 "
                        << (e.nmse <= 1e-4 ? "holds" : "fails") << "\n";
        };
        for (auto v : all_variants) emit(variant_name(v), 0, interpolate(line, [v](const line_interval&) { return v; }));
        for (const auto& u : all_cubic_units())  // the interpolation paper's /3 grouping beside them
            if (u.grouping == interp::div3_grouping::partial_sum)
                emit(u.name(), 0, interpolate_with(line, [&u](const line_interval& iv, bool& quad) {
                         quad = false;
                         return u.coefs(u.samples(iv));
                     }));
        // Adaptive degree: the quadratic where the case-1 cubic's A is small.
        for (double tau : {0.5, 2.0, 8.0, 32.0, inf}) {
            auto pick = [tau](const line_interval& iv) {
                const auto k = variant_coefs(variant::cubic1_exact, iv);
                const double a = std::abs(to_real(static_cast<uint64_t>(k.a), interp::coef_fmt));
                return a <= tau ? variant::quad : variant::cubic1_exact;
            };
            emit("adaptive", tau, interpolate(line, pick));
        }
    }

    // The /3 grouping: whole weighted sum vs the interpolation paper's partial sum, both dividers, both sets.
    std::ofstream gcsv(grouping_path);
    gcsv << "samples,m,N,unit,set,divider,grouping,coef_sets,a_max_err,a_rms_err,c_max_err,c_rms_err,nmse\n";
    std::printf("\n/3 grouping: error of A and C against the real coefficients (levels), NMSE of the line\n");
    std::printf("%-7s %4s %-26s %10s %10s %10s %10s %11s\n", "samples", "N", "unit", "max|eA|", "rms eA", "max|eC|",
                "rms eC", "NMSE");
    auto row = [&](const char* samples, unsigned m, const cubic_unit& u, const coef_error& e, double nmse) {
        const bool line = m != 0;
        gcsv << samples << ',' << m << ',' << (line ? (1u << m) : 0u) << ',' << u.name() << ','
             << (u.set == interp::sample_set::case1 ? 1 : 2) << ','
             << (u.div == interp::div3_mode::shift_add ? "shift_add" : "exact") << ','
             << (u.grouping == interp::div3_grouping::whole_sum ? "whole_sum" : "partial_sum") << ',' << e.n << ','
             << e.a_max << ',' << e.a_rms() << ',' << e.c_max << ',' << e.c_rms() << ',';
        if (line) gcsv << nmse;
        gcsv << '\n';
        std::printf("%-7s %4s %-26s %10.4g %10.4g %10.4g %10.4g %11s\n", samples,
                    line ? std::to_string(1u << m).c_str() : "-", u.name().c_str(), e.a_max, e.a_rms(), e.c_max,
                    e.c_rms(), line ? [&] { char b[32]; std::snprintf(b, sizeof b, "%.3e", nmse); return std::string(b); }().c_str() : "-");
    };
    for (unsigned m = interp::m_min; m <= interp::m_max; ++m) {
        const auto line = make_line(width, m);
        for (const auto& u : all_cubic_units()) {
            coef_error e;
            for (const auto& iv : line.intervals) e.add(u, u.samples(iv));
            const auto err = interpolate_with(line, [&u](const line_interval& iv, bool& quad) {
                quad = false;
                return u.coefs(u.samples(iv));
            });
            row("line", m, u, e, err.nmse);
        }
    }
    // Uniform random samples over the whole Q8.8 range (worst cases the line never reaches).
    for (const auto& u : all_cubic_units()) {
        std::mt19937 rng(4);
        std::uniform_int_distribution<uint64_t> code(0, interp::sample_fmt.mask());
        coef_error e;
        for (int n = 0; n < 100000; ++n) e.add(u, {code(rng), code(rng), code(rng), code(rng)});
        row("random", 0, u, e, 0);
    }
    return csv && gcsv ? 0 : 1;
}
