// Perfect decisions: the adaptive length policy (src/golden_pipeline/pipeline.h, make_plan) with every
// decision right, a yardstick (host only), not a policy: what the policy's structure (its growth, its
// split, its check points) reaches when no estimate misleads it.
#pragma once

#include "golden_pipeline/pipeline.h"

namespace shading::yardsticks {

// Decides each candidate on the true RMS error (8-bit levels per channel) of what the policy sends for
// it (the candidate, or its halves split at the check point) against per-pixel shading through the
// device (pipeline::per_pixel_frame, uncounted), at most c.length_tol. Every estimate is still computed
// and paid (a cubic's quadratic miss and the check point, even where the policy's own test would have
// stopped at the first), so the plan's costs are those of the policy's structure.
class perfect_decider : public pipeline::length_decider {
public:
    perfect_decider(const scene::rasterised& r, const pipeline::frame_constants& k, const scene::device_config& dev,
                    const pipeline::plan_config& c);
    bool accept(pipeline::length_candidate& candidate) const override;
    // The RMS error (levels per channel) of `sent` over its `pixels` pixels against per-pixel shading.
    double true_rms(const std::vector<pipeline::interval_job>& sent, unsigned pixels) const;

private:
    const scene::rasterised& r_;
    const pipeline::frame_constants& k_;
    const scene::device_config& dev_;
    pipeline::plan_config c_;
    pipeline::frame per_pixel_;
};

// make_plan of c with a perfect_decider. Throws scene::scene_error unless c.length is adaptive (the
// decision replaced is the one it takes on its estimates), or for an invalid c.
pipeline::plan perfect_decisions_plan(const scene::rasterised& r, const pipeline::frame_constants& k,
                                      const scene::device_config& dev, const pipeline::plan_config& c);

}  // namespace shading::yardsticks
