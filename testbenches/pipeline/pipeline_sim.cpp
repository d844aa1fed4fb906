// simulate_frame(): elaborates the bench for the device and evaluator asked for, runs it, and reads
// the frame buffer back (pipeline_sim.h; the runs in pipeline_sim_run.h).
#include "pipeline_sim.h"

#include <string>

#include "core/report_ids.h"
#include "pipeline_sim_run.h"

namespace shading::pipeline {

double sim_period_ns() { return pipeline_period().to_seconds() * 1e9; }

sim_result simulate_frame(const plan& p, const frame_constants& k, const scene::device_config& dev,
                          const plan_config& c, const sim_options& o) {
    std::string bad;
    if (sc_core::sc_get_status() != sc_core::SC_ELABORATION || sc_core::sc_get_curr_simcontext()->elaboration_done())
        bad = "simulate_frame: SystemC elaborates once per process; this process has simulated already";
    else if (c.eval == evaluator::fd && c.length == length_policy::fixed && (c.m < interp::m_min || c.m > interp::m_max))
        bad = "simulate_frame: the forward-difference evaluator is built for m = " + std::to_string(c.m) +
              ", outside " + std::to_string(interp::m_min) + ".." + std::to_string(interp::m_max);
    if (!bad.empty()) {
        sim_result r;
        r.f = empty_frame(p.width, p.height);
        r.mismatches = p.pixels;
        SC_REPORT_ERROR(msg::config, bad.c_str());
        return r;
    }
    return c.eval == evaluator::horner ? sim_detail::run_device<evaluator::horner>(p, k, dev, c, o)
                                       : sim_detail::run_device<evaluator::fd>(p, k, dev, c, o);
}

}  // namespace shading::pipeline
