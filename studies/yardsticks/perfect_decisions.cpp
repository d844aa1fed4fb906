// Perfect decisions (perfect_decisions.h): the adaptive length policy deciding on the truth.
#include "studies/yardsticks/perfect_decisions.h"

#include <cmath>

namespace shading::yardsticks {

using namespace shading::pipeline;

perfect_decider::perfect_decider(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
                                 const plan_config& c)
    : r_(r), k_(k), dev_(dev), c_(c), per_pixel_(per_pixel_frame(r, k, dev)) {}

double perfect_decider::true_rms(const std::vector<interval_job>& sent, unsigned pixels) const {
    double e = 0.0;
    for (const interval_job& q : sent) {
        const std::vector<rgb_codes> px = interval_pixels(q, k_, dev_, c_.eval, c_.set, c_.div);
        for (unsigned i = 0; i < q.len; ++i)
            for (int ch = 0; ch < 3; ++ch) {
                const double d =
                    (double(px[i][ch]) - double(per_pixel_.px[r_.index(q.x0 + i, q.y)][ch])) * pixel_fmt.lsb();
                e += d * d;
            }
    }
    return std::sqrt(e / (3.0 * pixels));
}

bool perfect_decider::accept(length_candidate& cand) const {
    // Every estimate paid (the check point too, even where the cubic's own test would have stopped
    // first), then the decision taken on the truth.
    if (!cand.job().deg2) cand.quad_miss();
    cand.check_miss();
    return true_rms(cand.sent(), cand.job().len) <= c_.length_tol;
}

plan perfect_decisions_plan(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
                            const plan_config& c) {
    validate(c);
    if (c.length != length_policy::adaptive)
        throw scene::scene_error("plan: perfect decisions are the adaptive length policy's (the decision it takes on "
                                 "its estimates)");
    return make_plan(r, k, dev, c, perfect_decider(r, k, dev, c));
}

}  // namespace shading::yardsticks
