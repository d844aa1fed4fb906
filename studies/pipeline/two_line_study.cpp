// Every other line predicted from the lines either side (two_line.h): is the interpolation target
// (NMSE <= 1e-5 against per-pixel shading, >= 3x fewer long operations than the scan-line Phong) in
// reach of a two-line scheme? Golden model only. On one scene (default the head at 512, the squared
// device, n = 20):
//  - the planner (adaptive, cubic, split at the check, carry, forward differences, the line-above
//    limit K = --above-slack, default 2 as in the race's targets) at each --tol-one beside its
//    emulation (emulate_adaptive) on the same lines: the points and NMSE agree, so the emulation's
//    figures stand for the planner's;
//  - the emulation one line at a time, and the two-line scheme at each --tol-even x --tol-odd: the
//    points per pixel of each line parity and their parts of the NMSE; the odd lines with the even
//    ones exact (what the prediction gives at best);
//  - every emulated frame's long operations counted as the planner counts a plan's
//    (emulated_long_ops: its points stepped in the order the scheme renders the lines, a colour at
//    each), against the scan-line Phong; with --walk-edges both walk edges;
//  - with --tol-mid, every fourth line first: the lines two apart predicted from the lines two above
//    and below at each --tol-mid, then the odd lines as in the two-line scheme (emulate_lines);
//  - the cheapest of each meeting --nmse by those counts;
//  - with --perfect-decisions, each as a yardstick: every decision, the planner's and the emulation's,
//    taken on the true error of what the interval sends, the check points still paid.
//   build/bin/two_line_study                  (under 1 s at 512)
//   build/bin/two_line_study --size 64 --tol-one 1 --tol-even 1 --tol-odd 2
#include <algorithm>
#include <cstdio>
#include <exception>
#include <optional>
#include <vector>

#include "scene/shade.h"
#include "studies/yardsticks/perfect_decisions.h"
#include "testbenches/common/exit_status.h"
#include "testbenches/options/tool_options.h"
#include "line_kinks.h"
#include "study_frame.h"
#include "two_line.h"

using namespace shading;
using namespace shading::pipeline;
using namespace shading::study;

int main(int argc, char* argv[]) {
    tb::two_line_study_options o;
    if (auto rc = tb::parse_two_line_study(argc, argv, o)) return *rc;
    try {
        const study_frame sf(o.scene, o.data_dir, o.size, o.device, o.walk_edges);
        const scene::rasterised& r = sf.r;
        const frame_constants& k = sf.k;
        const scene::device_config& dev = sf.dev;
        const std::vector<rgb_levels>& colour = sf.colour;
        const scene::shaded_image ref = to_image(sf.per_pixel);
        if (sf.pixels == 0) {
            std::fprintf(stderr, "two_line_study: the scene covers no pixel at %ux%u\n", o.size, o.size);
            return tb::exit_failure;
        }
        const double pixels = double(sf.pixels), scanline = sf.scanline;

        plan_config base;
        base.length = length_policy::adaptive;
        base.degree = degree_policy::cubic;
        base.split_at_check = true;
        base.carry_samples = true;
        base.eval = evaluator::fd;
        base.m_max = o.m_max;
        base.above_slack = o.above_slack;
        base.walk_edges = o.walk_edges;
        // With --perfect-decisions the planner's (studies/yardsticks) and, through emulate_lines, the emulation's.
        const bool perfect = o.perfect_decisions;

        std::printf("# Two lines: every other line predicted from the lines either side. %s %ux%u, device %s, n = %u, "
                    "m <= %u, line-above limit K = %d, edges %s, NMSE limit %.3g%s\n\n",
                    o.scene.c_str(), o.size, o.size, o.device.c_str(), k.n, o.m_max, o.above_slack,
                    o.walk_edges ? "walked" : "not walked", o.nmse,
                    o.perfect_decisions ? ", perfect decisions (a yardstick)" : "");
        std::printf("Scan-line Phong: %.2f long operations per pixel (%zu pixels).\n\n", scanline, sf.pixels);
        // The emulation's points counted as the planner counts a plan's (emulated_long_ops).
        auto counted = [&](const emulated_frame& f) {
            return emulated_long_ops(r, f, dev, k.n, o.walk_edges).long_ops() / pixels;
        };
        auto per_px = [](std::size_t a, std::size_t b) { return double(a) / double(std::max<std::size_t>(1, b)); };
        std::printf("One line at a time, the planner and its emulation on the same lines:\n\n"
                    "| T | planner points / px | planner NMSE | planner long ops / px (x scan-line) | its long ops a point "
                    "| emulation points / px | emulation NMSE | emulation long ops / px, counted (x scan-line) |\n"
                    "|---|---|---|---|---|---|---|---|\n");
        std::optional<double> one_points, one_T, per_point, one_long, one_counted;
        for (double t : o.tol_one) {
            plan_config c = base;
            c.length_tol = t;
            const plan p = perfect ? yardsticks::perfect_decisions_plan(r, k, dev, c) : make_plan(r, k, dev, c);
            const double e = compare(to_image(golden_frame(p, k, dev, c)), ref).nmse;
            const double cost = double(hardware_ops(p, c, dev, k.n).total().long_ops()) / pixels;
            const emulated_frame f = emulate_lines(r, colour, c, {t}, false, perfect);
            const double pts = double(f.points()) / double(f.pixels()), ec = counted(f);
            std::printf("| %.2f | %.4f | %.3e | %.2f (%.2fx) | %.1f | %.4f | %.3e | %.2f (%.2fx) |\n", t,
                        p.geometry_points / pixels, e, cost, scanline / cost, cost * pixels / double(p.geometry_points),
                        pts, f.nmse(), ec, scanline / ec);
            if (f.nmse() <= o.nmse && (!one_points || pts < *one_points)) {
                one_points = pts;
                one_T = t;
                per_point = cost * pixels / double(p.geometry_points);
                one_long = cost;
                one_counted = ec;
            }
        }
        std::printf("\nThe two-line scheme (emulated): even lines at T_even, then each odd line's residual against the "
                    "mean of the delivered lines above and below at T_odd:\n\n"
                    "| T_even | T_odd | points / px | even lines | odd lines | odd pixels predicted | NMSE | even lines' "
                    "part | odd lines' part | long ops / px, counted (x scan-line) |\n"
                    "|---|---|---|---|---|---|---|---|---|---|\n");
        std::optional<double> two_points, two_counted;
        double two_even = 0.0, two_odd = 0.0, two_nmse = 0.0;
        for (double te : o.tol_even)
            for (double to : o.tol_odd) {
                const emulated_frame f = emulate_lines(r, colour, base, {te, to}, false, perfect);
                const double pts = double(f.points()) / double(f.pixels()), ec = counted(f);
                std::printf("| %.2f | %.2f | %.4f | %.4f | %.4f | %.3f | %.3e | %.2e | %.2e | %.2f (%.2fx) |\n", te, to,
                            pts, per_px(f.points_first, f.pixels_first), per_px(f.points_rest, f.pixels_rest),
                            per_px(f.pixels_predicted, f.pixels_rest), f.nmse(), f.se_first / f.ref2,
                            f.se_rest / f.ref2, ec, scanline / ec);
                if (f.nmse() <= o.nmse && (!two_counted || ec < *two_counted)) {
                    two_counted = ec;
                    two_points = pts;
                    two_even = te;
                    two_odd = to;
                    two_nmse = f.nmse();
                }
            }
        std::printf("\nThe odd lines at best: the even lines exact (every pixel a point), the odd lines as above:\n\n"
                    "| T_odd | odd lines' points / px | odd lines' part of the NMSE |\n|---|---|---|\n");
        for (double to : o.tol_odd) {
            const emulated_frame f = emulate_lines(r, colour, base, {to, to}, true, perfect);
            std::printf("| %.2f | %.4f | %.2e |\n", to, per_px(f.points_rest, f.pixels_rest), f.se_rest / f.ref2);
        }
        // Every fourth line first (--tol-mid given): the lines two apart predicted from the lines two
        // above and below at T_mid, then the odd ones at T_odd.
        std::optional<double> four_counted, four_points;
        double four_first = 0.0, four_mid = 0.0, four_odd = 0.0, four_nmse = 0.0;
        if (!o.tol_mid.empty()) {
            std::printf("\nEvery fourth line first (emulated): those at T_even, then the lines between them two apart "
                        "predicted from the lines two above and below at T_mid, then the odd lines from their "
                        "neighbours at T_odd:\n\n| T_even | T_mid | T_odd | points / px | NMSE | long ops / px, counted "
                        "(x scan-line) |\n|---|---|---|---|---|---|\n");
            for (double te : o.tol_even)
                for (double tm : o.tol_mid)
                    for (double to : o.tol_odd) {
                        const emulated_frame f = emulate_lines(r, colour, base, {te, tm, to}, false, perfect);
                        const double pts = double(f.points()) / double(f.pixels()), ec = counted(f);
                        std::printf("| %.2f | %.2f | %.2f | %.4f | %.3e | %.2f (%.2fx) |\n", te, tm, to, pts, f.nmse(), ec,
                                    scanline / ec);
                        if (f.nmse() <= o.nmse && (!four_counted || ec < *four_counted)) {
                            four_counted = ec;
                            four_points = pts;
                            four_first = te;
                            four_mid = tm;
                            four_odd = to;
                            four_nmse = f.nmse();
                        }
                    }
        }
        std::printf("\nThe cheapest meeting NMSE <= %.3g:\n", o.nmse);
        if (!one_points) {
            std::printf("- one line at a time: none of --tol-one\n");
        } else {
            std::printf("- one line at a time: T = %.2f, %.4f points / px; the planner there %.2f long ops / px "
                        "(%.2fx the scan-line Phong), %.1f a point; its emulation counted %.2f (%.2fx)\n",
                        *one_T, *one_points, *one_long, scanline / *one_long, *per_point, *one_counted,
                        scanline / *one_counted);
        }
        if (!two_points) {
            std::printf("- two lines: none of --tol-even x --tol-odd\n");
        } else {
            std::printf("- two lines: T_even = %.2f, T_odd = %.2f, %.4f points / px (NMSE %.3e), counted %.2f long ops / "
                        "px: %.2fx the scan-line Phong (3x needs %.2f)",
                        two_even, two_odd, *two_points, two_nmse, *two_counted, scanline / *two_counted,
                        scanline / 3.0);
            if (one_points)
                std::printf("; %.2fx fewer points and %.2fx fewer long ops than one line at a time", *one_points / *two_points,
                            *one_counted / *two_counted);
            std::printf("\n");
        }
        if (!o.tol_mid.empty()) {
            if (!four_counted)
                std::printf("- every fourth line first: none of --tol-even x --tol-mid x --tol-odd\n");
            else
                std::printf("- every fourth line first: T_even = %.2f, T_mid = %.2f, T_odd = %.2f, %.4f points / px (NMSE "
                            "%.3e), counted %.2f long ops / px: %.2fx the scan-line Phong\n",
                            four_first, four_mid, four_odd, *four_points, four_nmse, *four_counted,
                            scanline / *four_counted);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "two_line_study: %s\n", e.what());
        return tb::exit_failure;
    }
    return tb::exit_success;
}
