// The plan's configuration (pipeline.h): the policies' names, which of them a hardware geometry side
// can run, and the check of a plan_config before any planning, apart from the planner (plan.cpp).
#include <string>

#include "golden_pipeline/pipeline.h"

namespace shading::pipeline {
const char* geometry_unit_name(geometry_unit u) { return u == geometry_unit::stepped ? "stepped" : "scratch"; }

const char* length_policy_name(length_policy p) {
    switch (p) {
        case length_policy::fixed: return "fixed";
        case length_policy::adaptive: return "adaptive";
        case length_policy::geometry: return "geometry";
    }
    return "?";
}

const char* degree_policy_name(degree_policy p) {
    switch (p) {
        case degree_policy::cubic: return "cubic";
        case degree_policy::quadratic: return "quadratic";
        case degree_policy::zones: return "zones";
        case degree_policy::adaptive: return "adaptive";
        case degree_policy::geometry: return "geometry";
    }
    return "?";
}

bool policy_runs_on_geometry_side(length_policy p) { return p != length_policy::adaptive; }
// zones: the zone's box tests on the position the geometry side interpolates, against per-frame
// thresholds from the mesh (host set-up, as the scene's other frame constants).
bool policy_runs_on_geometry_side(degree_policy p) { return p != degree_policy::adaptive; }

void validate(const plan_config& c) {
    const std::string range = std::to_string(interp::m_min) + ".." + std::to_string(interp::m_max);
    auto fail = [](const std::string& what) { throw scene::scene_error("plan: " + what); };
    if (c.length == length_policy::fixed && (c.m < interp::m_min || c.m > interp::m_max))
        fail("interval length 2^m with m = " + std::to_string(c.m) + " is outside the units' range m = " + range);
    if (c.m_min < interp::m_min || c.m_min > interp::m_max || c.m_max < interp::m_min || c.m_max > interp::m_max)
        fail("adaptive interval lengths m = " + std::to_string(c.m_min) + ".." + std::to_string(c.m_max) +
             " are outside the units' range m = " + range);
    if (c.m_min > c.m_max)
        fail("m_min = " + std::to_string(c.m_min) + " exceeds m_max = " + std::to_string(c.m_max));
    if (!(c.length_tol >= 0.0)) fail("the length tolerance must be >= 0 (8-bit levels)");
    if (!(c.degree_tol >= 0.0)) fail("the degree tolerance must be >= 0 (8-bit levels)");
    if (!(c.depth_step > 0.0)) fail("the depth step must be > 0 (world units)");
    if (!(c.lobe_tol > 0.0)) fail("the lobe tolerance must be > 0");
    if (c.above_slack > int(interp::m_max))
        fail("the slack over the line above, " + std::to_string(c.above_slack) + ", exceeds m_max of the units (" +
             std::to_string(interp::m_max) + "); negative for no limit");
    // Any evaluator takes either length policy: fd_eval_var sets the forward differences up per
    // interval for every m in m_min..m_max, as the Horner unit takes any t.
}

}  // namespace shading::pipeline
