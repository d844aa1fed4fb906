// The yardsticks of the geometry side's plans (studies/yardsticks), rendered as render_pipeline
// renders a policy's plan (testbenches/pipeline/render_program.h: golden frame, references, with --sim
// the SystemC pipeline bit for bit, the comparisons and counts, PNGs, report.md and report.json):
//  - --length optimal: the optimum plan (optimum.h) at --optimal-nmse against --optimal-reference,
//    its certificate in the report's plan.optimum (no plan of these segments reaches the NMSE with
//    fewer points; with the cheapest point and the sample stage's cost per sample, no fewer long
//    operations); with --optimal-greedy the policies' greedy structure with perfect estimates, with
//    --optimal-from-above W the plan chosen on the line above's errors;
//  - --length adaptive --perfect-decisions: the adaptive length policy with every decision taken on
//    the true error of what it sends (perfect_decisions.h), its check points still paid.
// Neither is a policy a geometry side can run: they know every colour. How far a policy is from them
// is what studies/scripts/pipeline_gap.py and studies/scripts/pipeline_targets.py tabulate.
//   build/bin/yardstick_study --scene head --size 512 --device squared --eval fd --carry-samples
//       --length optimal --optimal-nmse 1e-5 --no-sim --out out/yardsticks/optimum
//   build/bin/yardstick_study --scene head --size 512 --device squared --eval fd --carry-samples
//       --length adaptive --perfect-decisions --degree cubic --m-max 5 --split-at-check --length-tol 0.687
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "studies/yardsticks/optimum.h"
#include "studies/yardsticks/perfect_decisions.h"
#include "studies/yardsticks/yardstick_options.h"
#include "testbenches/common/exit_status.h"
#include "testbenches/pipeline/render_program.h"

#ifndef SHADING_PIPELINE_SIM
#define SHADING_PIPELINE_SIM 0
#endif
#if SHADING_PIPELINE_SIM
#include <systemc>

#include "testbenches/common/report_log.h"
#endif

using namespace shading;
using namespace shading::pipeline;
using namespace shading::render_program;
using namespace shading::yardsticks;

namespace {

yardstick_options g_options;  // handed from main() to sc_main() when the SystemC pipeline runs

const char* reference_name(optimum_config::reference r) {
    return r == optimum_config::reference::total ? "total" : "interpolation";
}

// The optimum in the render's place; its certificate into `cert` once planned.
plan_maker optimum_maker(const yardstick_options& yo, optimum_certificate& cert) {
    const optimum_config& o = yo.optimum;
    plan_maker m;
    m.length_name = "optimal";
    m.runs_on_geometry_side = false;
    m.make = [&o, &cert](const render_data& d) {
        optimum best = optimal_plan(d.r, d.k, d.dev, d.cfg, o);
        cert = best.certificate;
        return best.p;
    };
    // The certificate: no plan of these segments reaching the NMSE has fewer points, and (with the
    // cheapest point's long operations and the sample stage's per sample) no fewer long operations of
    // the geometry side and the sample stage than the bound.
    m.add_json = [&o, &cert](const render_data& d, json& rep) {
        rep["program"] = "yardstick_study";
        rep["config"]["perfect_decisions"] = false;
        const double hw_px = double(d.hc.pixels), phong_px = double(d.sp.pixels);
        const double per_sample = d.hc.samples ? double(d.hc.sample_stage.long_ops()) / double(d.hc.samples) : 0.0;
        const double bound_long = cert.points_bound * (cert.point_long_min + per_sample);
        rep["plan"]["optimum"] = {
            {"reference", reference_name(o.ref)},
            {"nmse_allowed", o.nmse},
            {"feasible", cert.feasible},
            {"nmse", cert.nmse},
            {"lambda", cert.lambda},
            {"points_bound", cert.points_bound},
            {"points_bound_per_pixel", hw_px > 0 ? cert.points_bound / hw_px : 0.0},
            {"point_long_min", cert.point_long_min},
            {"sample_long", per_sample},
            {"long_bound_per_pixel", hw_px > 0 ? bound_long / hw_px : 0.0},
            {"scanline_phong_ratio_bound",
             bound_long > 0 ? double(d.sl.total().long_ops()) / bound_long * (hw_px / phong_px) : 0.0},
            {"greedy", o.greedy}};
        if (o.greedy)
            rep["plan"]["optimum"]["greedy_plan"] = {{"tolerance_rms_levels", cert.greedy_tolerance},
                                                     {"nmse", cert.greedy_nmse}};
        if (o.from_above >= 0)
            rep["plan"]["optimum"]["from_above"] = {{"window", o.from_above},
                                                    {"nmse", cert.above_nmse},
                                                    {"met", cert.above_nmse <= o.nmse},
                                                    {"own_priced_share", cert.above_fallback}};
    };
    m.md_after_plan = [&o, &cert, &yo](const render_data& d) {
        const json rep = report_json(yo.render, d);
        const json& opt = rep["plan"]["optimum"];
        std::string md = std::string("The optimum (a yardstick, not a policy: it knows every colour and pays nothing to "
                                     "decide) for ") +
                         opt["reference"].get<std::string>() + " NMSE <= " + fmt("%.2e", o.nmse) + ": " +
                         (cert.feasible ? "reached, NMSE " : "out of reach; the lowest-error plan has NMSE ") +
                         fmt("%.3e", cert.nmse) + "; no plan of these segments meets the NMSE with fewer than " +
                         fmt("%.1f", cert.points_bound) + " (" + fmt("%.4f", opt["points_bound_per_pixel"].get<double>()) +
                         " per pixel).";
        const bool above = o.from_above >= 0;
        if (o.greedy)
            md += std::string(" The plan here is not the optimum's but the adaptive policies' greedy structure with ") +
                  (above ? "the line above's errors as its estimates" : "perfect estimates") + ": RMS tolerance " +
                  fmt("%.3f", cert.greedy_tolerance) + " levels per interval, NMSE " + fmt("%.3e", cert.greedy_nmse) +
                  ", " + std::to_string(d.p.geometry_points) + " geometry points.";
        else if (above)
            md += " The plan here is not the optimum's but one chosen the optimum's way on the line above's errors, "
                  "not each line's own: NMSE " +
                  fmt("%.3e", cert.above_nmse) + (cert.above_nmse <= o.nmse ? "" : ", above the NMSE allowed") + ", " +
                  std::to_string(d.p.geometry_points) + " geometry points.";
        if (above)
            md += " Each candidate is priced by the same candidate's largest error on the line above over starts "
                  "within " +
                  std::to_string(o.from_above) + " pixels; " + fmt("%.1f", 100.0 * cert.above_fallback) +
                  " % of the candidates, with none above, by their own.";
        return md + "\n\n";
    };
    return m;
}

// The adaptive length policy with perfect decisions in the render's place.
plan_maker perfect_maker() {
    plan_maker m;
    m.length_name = length_policy_name(length_policy::adaptive);
    m.runs_on_geometry_side = false;
    m.length_note = ", perfect decisions (a yardstick: true errors, checks still paid)";
    m.make = [](const render_data& d) { return perfect_decisions_plan(d.r, d.k, d.dev, d.cfg); };
    m.add_json = [](const render_data&, json& rep) {
        rep["program"] = "yardstick_study";
        rep["config"]["perfect_decisions"] = true;
    };
    return m;
}

// Bad usage found from the command line alone (exit 2): render_pipeline's, and a yardstick asked for
// what it is not.
std::string usage_problem(const yardstick_options& o) {
    if (o.length == "adaptive" && !o.perfect_decisions)
        return "--length adaptive without --perfect-decisions is the policy itself (render_pipeline), not a yardstick";
    if (o.length == "optimal" && o.perfect_decisions)
        return "plan: perfect decisions are the adaptive length policy's (the decision it takes on its estimates)";
    if (const std::string why = render_program::usage_problem(o.render); !why.empty()) return why;
    try {
        validate(o.optimum);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

int run(const yardstick_options& o) {
    try {
        optimum_certificate cert;
        const plan_maker m = o.length == "optimal" ? optimum_maker(o, cert) : perfect_maker();
        return render(o.render, &m);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%syardstick_study: %s\n", progress_open ? "\n" : "", e.what());
        return 1;
    }
}

}  // namespace

#if SHADING_PIPELINE_SIM
// SystemC's reports through the testbenches' log, as render_pipeline's.
int sc_main(int, char*[]) {
    shading::tb::report_log::install();
    return run(g_options);
}
#endif

int main(int argc, char* argv[]) {
    yardstick_options& o = g_options;
    if (auto rc = parse_yardstick_study(argc, argv, o)) return *rc;  // help 0, a bad option 2
    if (o.render.sim_available) return SHADING_PIPELINE_SIM ? 0 : 1;
    if (const std::string why = usage_problem(o); !why.empty()) {
        std::fprintf(stderr, "yardstick_study: %s\n", why.c_str());
        return tb::exit_usage;
    }
#if SHADING_PIPELINE_SIM
    if (o.render.sim) {
        ::setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
        return sc_core::sc_elab_and_sim(argc, argv);
    }
#endif
    return run(o);
}
