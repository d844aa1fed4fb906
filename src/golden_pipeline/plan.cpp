// The geometry side of the interpolation paper's shading system (pipeline.h): each raster line is cut into segments
// at its discontinuities, each segment is tiled into intervals of 2^m pixels by a length policy, each
// interval gets its degree by a degree policy, and the geometry (N.H, N.L) is computed once per
// distinct pixel that any sample or decision needs, every operation counted.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "golden_pipeline/line_geometry.h"
#include "golden_pipeline/lit_planes.h"
#include "golden_pipeline/pipeline.h"

namespace shading::pipeline {

namespace {

using scene::cnum;
using scene::cvec3;
using scene::op_counts;

// The cubic's sample that the quadratic skips (the adaptive degree policy's check): case 1 t = 1/4,
// case 2 t = 3/4. The adaptive length policy's check: the middle of the widest gap between the cubic's
// points, case 1 t = 3/4, case 2 t = 1/4.
unsigned degree_check(interp::sample_set set) { return set == interp::sample_set::case1 ? 2 : 6; }
unsigned length_check(interp::sample_set set) { return set == interp::sample_set::case1 ? 6 : 2; }

// Lagrange weights of the polynomial through `nodes` (eighths) at `t` (eighths). Frame constants.
template <std::size_t K>
std::array<double, K> lagrange(const std::array<unsigned, K>& nodes, unsigned t) {
    std::array<double, K> w{};
    for (std::size_t i = 0; i < K; ++i) {
        double v = 1.0;
        for (std::size_t j = 0; j < K; ++j)
            if (j != i) v *= (double(t) - nodes[j]) / (double(nodes[i]) - nodes[j]);
        w[i] = v;
    }
    return w;
}

// Every weight above is a multiple of 1/8 (nodes and points on eighths of N): multiplying by one is
// a shift-and-add network, as in the coefficient units, costing (binary ones of |w| * 8) - 1 adds.
unsigned shift_add_cost(double w) {
    auto k = static_cast<unsigned>(std::lround(std::abs(w) * 8.0));
    unsigned ones = 0;
    for (; k; k >>= 1) ones += k & 1u;
    return ones > 0 ? ones - 1 : 0;
}

class planner {
public:
    planner(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
            const plan_config& c, plan& p, const std::vector<uint8_t>* taken, const length_decider& decide)
        : r_(r), k_(k), dev_(dev), c_(c), p_(p), taken_(taken), decide_(decide), stepper_(r, c.walk_edges), lit_(r),
          cubic_(cubic_points(c.set)),
          w_deg_(lagrange(quad_points, degree_check(c.set))),
          w_len_cubic_(lagrange(cubic_, length_check(c.set))),
          w_len_quad_(lagrange(quad_points, length_check(c.set))),
          // The degree tolerance in 8-bit levels against Q8.8 codes: scaled once per frame.
          degree_tol_(c.degree_tol * (1u << colour_fmt.frac)) {
        geometry_constants();
    }

    void line(unsigned y) {
        line_geometry lg(r_, y, k_, dev_, p_);
        const std::size_t first_job = p_.jobs.size();
        miss_pos_ = ~0u;  // the quadratic's miss is per line
        for (const auto& seg : line_segments(r_, y, c_, &p_.decision)) {
            // Pixels another unit delivers (taken_, the cells) end the segment's pieces too.
            unsigned xa = seg[0];
            for (unsigned x = seg[0]; x <= seg[1] + 1; ++x) {
                const bool end = x > seg[1] || (taken_ && (*taken_)[r_.index(x, y)]);
                if (!end) continue;
                if (x > xa) segment(lg, y, xa, x - 1);
                xa = x + 1;
            }
        }
        if (c_.above_slack >= 0) {
            // This line's levels (each pixel's job's m, exact pixels 0) are the next line's line above.
            above_.assign(r_.width, no_level);
            for (std::size_t j = first_job; j < p_.jobs.size(); ++j)
                for (unsigned i = 0; i < p_.jobs[j].len; ++i) above_[p_.jobs[j].x0 + i] = uint8_t(p_.jobs[j].m);
        }
        // Check samples: colours evaluated where no job of this line has a sample point.
        std::vector<uint8_t> sampled(r_.width, 0);
        for (std::size_t j = first_job; j < p_.jobs.size(); ++j) {
            const interval_job& job = p_.jobs[j];
            const unsigned n = 1u << job.m;
            if (job.m == 0)
                sampled[job.x0] = 1;
            else if (job.deg2)
                for (unsigned e : quad_points) sampled[job.x0 + e * n / 8] = 1;
            else
                for (unsigned e : cubic_) sampled[job.x0 + e * n / 8] = 1;
        }
        for (unsigned x = 0; x < r_.width; ++x)
            if (lg.has_colour(x) && !sampled[x]) ++p_.check_samples;
        lg.charge_stepped(stepper_, p_);
    }

private:
    // Pixels xa..xb (inclusive) with no discontinuity inside.
    void segment(line_geometry& lg, unsigned y, unsigned xa, unsigned xb) {
        // A fixed length with forward differences keeps one m per frame, tails exact: the SystemC
        // pipeline's fd channel is fd_eval<M> (one m) until fd_eval_var is wired in. Adaptive length
        // takes m_min..m_max for either evaluator (fd_eval_var), the same plan as for Horner.
        const unsigned lowest = c_.length != length_policy::fixed ? c_.m_min
                                : c_.eval == evaluator::fd     ? c_.m
                                                               : interp::m_min;
        unsigned pos = xa;
        // Adaptive length grows by at most one level per interval (the segment's first tries m_max):
        // after a short interval the next is likely short too, so the long candidates' checks (and
        // their geometry) are not paid again and again across a highlight; flat skin still reaches
        // m_max within a few intervals. On the head at 512 this gives the same NMSE for about 5 %
        // fewer long operations, and a lower largest error (test_pipeline_plan, the figures in the report).
        unsigned grow_to = c_.m_max;
        for (;;) {
            const unsigned room = xb - pos;  // the t = 1 sample, pixel pos + 2^m, must be <= xb
            if (room < (1u << lowest)) break;
            unsigned top = lowest;
            const unsigned highest = c_.length == length_policy::fixed ? c_.m : grow_to;
            while (top < highest && (1u << (top + 1)) <= room) ++top;
            if (const auto job = choose(lg, y, pos, lowest, top)) {
                pos += job->len;
                p_.pixels += job->len;
                if (splits(*job))
                    split_at_check(lg, *job);
                else
                    p_.jobs.push_back(*job);
                grow_to = std::min(job->m + 1, c_.m_max);
            } else {
                // Even the shortest interval misses its check: its pixels are exact.
                for (unsigned i = 0; i < (1u << lowest); ++i) exact(lg, y, pos++);
                grow_to = std::min(lowest + 1, c_.m_max);
            }
        }
        // The tail: exact pixels (the last one's geometry is the last interval's t = 1 sample).
        for (unsigned x = pos; x <= xb; ++x) exact(lg, y, x);
    }

    // An accepted, checked cubic above 2^m_min (without the fallback the shortest goes unchecked): its
    // check and samples lie on eighths 0, 2, 4, 6, 8 in either set, the halves' quadratics' points.
    bool splits(const interval_job& job) const {
        const bool checked = job.m > c_.m_min || c_.exact_fallback;
        return c_.split_at_check && c_.length != length_policy::fixed && checked && job.m > interp::m_min &&
               !job.deg2 && job.len == (1u << job.m);
    }
    std::array<interval_job, 2> halves(line_geometry& lg, const interval_job& whole) {
        const unsigned half = 1u << (whole.m - 1);
        std::array<interval_job, 2> out{whole, whole};
        for (unsigned h = 0; h < 2; ++h) {
            interval_job& job = out[h];
            job.x0 = whole.x0 + h * half;
            job.len = half;
            job.m = whole.m - 1;
            job.deg2 = true;
            for (unsigned i = 0; i < 3; ++i) job.s[i] = lg.sample(job.x0 + quad_points[i] * half / 8);
            job.s[3] = job.s[2];
        }
        return out;
    }
    void split_at_check(line_geometry& lg, const interval_job& whole) {
        for (interval_job job : halves(lg, whole)) {
            job.zone = static_cast<uint8_t>(head_zone(r_, lg.geometry(job.x0)));
            p_.jobs.push_back(job);
        }
    }

    void exact(line_geometry& lg, unsigned y, unsigned x) {
        interval_job job;
        job.y = y;
        job.x0 = x;
        job.len = 1;
        job.m = 0;
        const sample_geometry s = lg.sample(x);
        job.s = {s, s, s, s};
        job.zone = static_cast<uint8_t>(head_zone(r_, lg.geometry(x)));
        ++p_.pixels;
        p_.jobs.push_back(job);
    }

    // The interval at `pos`: the longest m in lowest..top that the length policy accepts; none when
    // the shortest one fails too and c.exact_fallback is set.
    std::optional<interval_job> choose(line_geometry& lg, unsigned y, unsigned pos, unsigned lowest, unsigned top) {
        // The zone map's decision depends on the first pixel only: taken once per position.
        const int zone_deg2 = c_.degree == degree_policy::zones ? int(degree(lg, pos, 0)) : -1;
        auto make = [&](unsigned m) {
            const unsigned n = 1u << m;
            interval_job job;
            job.y = y;
            job.x0 = pos;
            job.len = n;
            job.m = m;
            job.deg2 = zone_deg2 >= 0 ? zone_deg2 != 0 : degree(lg, pos, n);
            if (job.deg2) {
                for (unsigned i = 0; i < 3; ++i) job.s[i] = lg.sample(pos + quad_points[i] * n / 8);
                job.s[3] = job.s[2];
            } else {
                for (unsigned i = 0; i < 4; ++i) job.s[i] = lg.sample(pos + cubic_[i] * n / 8);
            }
            job.zone = static_cast<uint8_t>(head_zone(r_, lg.geometry(pos)));
            return job;
        };
        if (c_.length == length_policy::fixed) return make(top);
        for (unsigned m = top;; --m) {
            if (m > lowest && !within_above(pos, m)) continue;
            interval_job job = make(m);
            if (m == lowest && !c_.exact_fallback) return job;
            if ((c_.length == length_policy::geometry ? geometry_passes(lg, job) : adaptive_passes(lg, job)) &&
                (m == lowest || lit_guard_passes(lg, job)))
                return job;
            if (m == lowest) return std::nullopt;
        }
    }

    // Adaptive length: the decider's verdict on the candidate (estimate_decider: the policy's own).
    bool adaptive_passes(line_geometry& lg, const interval_job& job) {
        candidate cand(*this, lg, job);
        return decide_.accept(cand);
    }

    // A candidate as the decider sees it (pipeline.h): its estimates computed, and charged, on first use.
    class candidate final : public length_candidate {
    public:
        candidate(planner& pl, line_geometry& lg, const interval_job& job) : pl_(pl), lg_(lg), job_(job) {}
        const interval_job& job() const override { return job_; }
        std::vector<interval_job> sent() override {
            if (!pl_.splits(job_)) return {job_};
            const auto h = pl_.halves(lg_, job_);
            return {h.begin(), h.end()};
        }
        double quad_miss() override {
            if (job_.deg2) throw std::logic_error("length_candidate::quad_miss: a quadratic has no fourth sample");
            return pl_.quad_miss(lg_, job_.x0, 1u << job_.m);
        }
        double check_miss() override {
            if (!check_) {
                const unsigned n = 1u << job_.m, check = job_.x0 + length_check(pl_.c_.set) * n / 8;
                check_ = job_.deg2 ? pl_.estimate(lg_, job_.x0, n, quad_points, pl_.w_len_quad_, check)
                                   : pl_.estimate(lg_, job_.x0, n, pl_.cubic_, pl_.w_len_cubic_, check);
            }
            return *check_;
        }
        bool over(double v, double limit) override { return pl_.over(v, limit); }

    private:
        planner& pl_;
        line_geometry& lg_;
        const interval_job& job_;
        std::optional<double> check_;
    };

    // The line-above limit: 2^m pixels from pos, each at most above_slack levels above the line
    // above's level there (a compare a pixel against the line buffer).
    bool within_above(unsigned pos, unsigned m) {
        if (c_.above_slack < 0 || above_.empty()) return true;
        for (unsigned x = pos; x < pos + (1u << m); ++x) {
            ++p_.decision.cmp;
            if (above_[x] != no_level && unsigned(above_[x]) + unsigned(c_.above_slack) < m) return false;
        }
        return true;
    }
    // The lit guard (plan_config::lit_guard): false if every sample and check point of `job` is unlit
    // but one of its pixels is lit (lit_planes.h). Only points the policy has computed.
    bool lit_guard_passes(line_geometry& lg, const interval_job& job) {
        if (!c_.lit_guard) return true;
        const unsigned n = 1u << job.m;
        std::vector<unsigned> pts(cubic_.begin(), cubic_.end());
        if (job.deg2) pts.assign(quad_points.begin(), quad_points.end());
        pts.push_back(length_check(c_.set));
        for (unsigned e : pts) {
            ++p_.decision.cmp;
            if (lg.sample(job.x0 + e * n / 8).cos_nl > 0) return true;  // a lit point: the checks see the light
        }
        return !lit_.any_lit(job.x0, job.x0 + n - 1, job.y, p_.decision);
    }

    static constexpr uint8_t no_level = 0xFF;
    std::vector<uint8_t> above_;  // the line above's level at each pixel (no_level: no interval there)

    bool degree(line_geometry& lg, unsigned pos, unsigned n) {
        switch (c_.degree) {
            case degree_policy::cubic: return false;
            case degree_policy::quadratic: return true;
            case degree_policy::zones: {
                // The zone's box tests: three differences from the nose tip against thresholds
                // pre-scaled per frame (zones.cpp), at most ten comparisons.
                p_.decision.add += 3;
                p_.decision.cmp += 10;
                return zone_is_quadratic(head_zone(r_, lg.geometry(pos)));
            }
            case degree_policy::geometry: return geometry_quadratic(lg, pos, n);
            case degree_policy::adaptive: {
                // The quadratic through t = 0, 1/2, 1 at the cubic's other sample, which the cubic
                // computes anyway; no extra sample.
                const double e = quad_miss(lg, pos, n);
                return !(cnum(e, &p_.decision) > cnum(degree_tol_, &p_.decision));
            }
        }
        return false;
    }

    // The quadratic through t = 0, 1/2, 1 against the colour at the cubic's fourth sample (both
    // policies read it; evaluated, and charged, once per interval tried).
    double quad_miss(line_geometry& lg, unsigned pos, unsigned n) {
        if (miss_pos_ != pos || miss_n_ != n) {
            miss_ = estimate(lg, pos, n, quad_points, w_deg_, pos + degree_check(c_.set) * n / 8);
            miss_pos_ = pos;
            miss_n_ = n;
        }
        return miss_;
    }
    unsigned miss_pos_ = ~0u, miss_n_ = 0;
    double miss_ = 0.0;

    // The largest |polynomial - exact colour| over the channels at pixel `check`, in Q8.8 code units:
    // the polynomial through the colours at `nodes` evaluated by constant Lagrange weights (shift-and-
    // add, charged as adds), minus the exact colour (an add), the largest magnitude kept (compares).
    template <std::size_t K>
    double estimate(line_geometry& lg, unsigned pos, unsigned n, const std::array<unsigned, K>& nodes,
                    const std::array<double, K>& w, unsigned check) {
        std::array<const rgb_codes*, K> s{};
        for (std::size_t i = 0; i < K; ++i) s[i] = &lg.colour(pos + nodes[i] * n / 8);
        const rgb_codes& exact = lg.colour(check);
        double worst = 0.0;
        for (int ch = 0; ch < 3; ++ch) {
            double v = 0.0;
            for (std::size_t i = 0; i < K; ++i) {
                v += w[i] * double((*s[i])[ch]);
                p_.decision.add += shift_add_cost(w[i]);
            }
            p_.decision.add += K - 1;  // the weighted sum
            p_.decision.add += 1;      // minus the exact colour
            const double e = std::abs(v - double(exact[ch]));
            ++p_.decision.cmp;
            worst = std::max(worst, e);
        }
        return worst;
    }

    // ---- Geometry-only policies: N.H and N.L codes (Q1.15) and per-frame constants ----
    // Per frame (host set-up, like the device's a(n) generator; not counted per pixel), with the
    // specular amplitude A = max k_s I code (levels), the diffuse slope B = max k_d I (levels per unit
    // N.L) and the tolerance T (levels):
    //  - the highlight threshold c_n: A c^n = T / 2, below it the specular term is under half the
    //    tolerance: an interval whose N.H stays below c_n is lit diffusely only;
    //  - N.L's tolerance T / B (a miss of N.L by that moves the colour by T);
    //  - in the highlight, N.H's tolerance T / (2 A n) (the specular slope is at most A n), and the
    //    largest spread D of N.H over an interval: the colour there is about A exp(-n (1 - N.H)), and
    //    the polynomial through its samples misses it by about A K (n D)^(d+1) for degree d with
    //    K = max |prod (t - t_i)| / (d + 1)! over [0, 1], so D = lobe_tol (T / (2 A K))^(1/(d+1)) / n.
    void geometry_constants() {
        const geometry_limits g = geometry_limits_of(k_, c_);
        geo_cn_ = g.highlight;
        geo_nl_tol_ = g.nl_miss;
        geo_nl_deg_tol_ = g.nl_miss_degree;
        geo_nh_tol_ = g.nh_miss;
        geo_spread_cubic_ = g.spread_cubic;
        geo_spread_quad_ = g.spread_quad;
    }

    // |polynomial through the codes at `nodes` (Lagrange weights: shift-and-add) - the code at `check`|,
    // charged to the decision as estimate() charges its colour version.
    template <std::size_t K>
    double code_miss(const std::array<double, K>& v, const std::array<double, K>& w, double exact) {
        double e = 0.0;
        for (std::size_t i = 0; i < K; ++i) {
            e += w[i] * v[i];
            p_.decision.add += shift_add_cost(w[i]);
        }
        p_.decision.add += K - 1 + 1;
        return std::abs(e - exact);
    }
    bool over(double v, double limit) { return cnum(v, &p_.decision) > cnum(limit, &p_.decision); }

    // The N.H and N.L codes at pixels pos + e N / 8.
    struct codes {
        double nh, nl;
    };
    codes at(line_geometry& lg, unsigned pos, unsigned n, unsigned e) {
        const sample_geometry g = lg.sample(pos + e * n / 8);
        return {double(g.cos_nh), double(g.cos_nl)};
    }

    // Geometry-only length: the interval's samples and its check point (geometry only, no colour).
    bool geometry_passes(line_geometry& lg, const interval_job& job) {
        const unsigned n = 1u << job.m;
        std::vector<unsigned> pts(cubic_.begin(), cubic_.end());
        if (job.deg2) pts.assign(quad_points.begin(), quad_points.end());
        pts.push_back(length_check(c_.set));
        if (job.deg2) pts.push_back(degree_check(c_.set));  // N.L's curvature, as for a cubic
        double lo = 1e300, hi = -1.0;
        for (unsigned e : pts) {
            const double h = at(lg, job.x0, n, e).nh;
            lo = std::min(lo, h);
            hi = std::max(hi, h);
            p_.decision.cmp += 2;
        }
        const codes chk = at(lg, job.x0, n, length_check(c_.set));
        double nl_miss = 0.0, nh_miss = 0.0;
        if (job.deg2) {
            std::array<double, 3> nl{}, nh{};
            for (unsigned i = 0; i < 3; ++i) {
                const codes q = at(lg, job.x0, n, quad_points[i]);
                nl[i] = q.nl;
                nh[i] = q.nh;
            }
            nl_miss = code_miss(nl, w_len_quad_, chk.nl);
            nl_miss = std::max(nl_miss, code_miss(nl, w_deg_, at(lg, job.x0, n, degree_check(c_.set)).nl));
            nh_miss = code_miss(nh, w_len_quad_, chk.nh);
        } else {
            std::array<double, 4> nl{}, nh{};
            for (unsigned i = 0; i < 4; ++i) {
                const codes q = at(lg, job.x0, n, cubic_[i]);
                nl[i] = q.nl;
                nh[i] = q.nh;
            }
            nl_miss = code_miss(nl, w_len_cubic_, chk.nl);
            std::array<double, 3> nl3{nl[0], nl[2], nl[3]};  // t = 0, 1/2, 1 (case 1; case 2 below)
            if (c_.set == interp::sample_set::case2) nl3 = {nl[0], nl[1], nl[3]};
            nl_miss = std::max(nl_miss, code_miss(nl3, w_deg_, at(lg, job.x0, n, degree_check(c_.set)).nl));
            nh_miss = code_miss(nh, w_len_cubic_, chk.nh);
        }
        if (over(nl_miss, geo_nl_tol_)) return false;
        if (!over(hi, geo_cn_)) return true;  // no highlight in the interval
        ++p_.decision.add;                      // the spread hi - lo
        if (over(hi - lo, job.deg2 ? geo_spread_quad_ : geo_spread_cubic_)) return false;
        return !over(nh_miss, geo_nh_tol_);
    }

    // Geometry-only degree: the quadratic where no highlight reaches the interval and N.L's quadratic
    // through t = 0, 1/2, 1 misses the cubic's other sample by at most degree_tol (in levels).
    bool geometry_quadratic(line_geometry& lg, unsigned pos, unsigned n) {
        std::array<codes, 4> q{};
        double hi = -1.0;
        for (unsigned i = 0; i < 4; ++i) {
            q[i] = at(lg, pos, n, cubic_[i]);
            hi = std::max(hi, q[i].nh);
            ++p_.decision.cmp;
        }
        if (!over(geo_cn_, hi)) return false;  // a highlight: cubic
        const std::array<double, 3> nl3 = c_.set == interp::sample_set::case1
                                              ? std::array<double, 3>{q[0].nl, q[2].nl, q[3].nl}
                                              : std::array<double, 3>{q[0].nl, q[1].nl, q[3].nl};
        const unsigned other = c_.set == interp::sample_set::case1 ? 1 : 2;
        return !over(code_miss(nl3, w_deg_, q[other].nl), geo_nl_deg_tol_);
    }
    double geo_cn_ = 0.0, geo_nl_tol_ = 0.0, geo_nl_deg_tol_ = 0.0, geo_nh_tol_ = 0.0;
    double geo_spread_cubic_ = 0.0, geo_spread_quad_ = 0.0;

    const scene::rasterised& r_;
    const frame_constants& k_;
    const scene::device_config& dev_;
    const plan_config& c_;
    plan& p_;
    const std::vector<uint8_t>* taken_;  // pixels another unit delivers (make_plan with a map), or null
    const length_decider& decide_;       // the adaptive length policy's decisions
    scene::span_stepper stepper_;
    lit_planes lit_;  // the lit guard's planes, per triangle as consulted
    std::array<unsigned, 4> cubic_;
    std::array<double, 3> w_deg_;
    std::array<double, 4> w_len_cubic_;
    std::array<double, 3> w_len_quad_;
    double degree_tol_;
};

}  // namespace

geometry_limits geometry_limits_of(const frame_constants& k, const plan_config& c) {
    const double one = double(spec::cos_one);
    const double tol = c.length_tol;
    double a = 0.0, b = 0.0;
    for (int ch = 0; ch < 3; ++ch) {
        a = std::max(a, double(k.ksi[ch]));
        b = std::max(b, double(k.kdi[ch]) / double(1u << kdi_fmt.frac));
    }
    const double n = std::max(1u, k.n);
    const double big = 4.0 * one;  // a bound no code difference reaches
    geometry_limits g;
    g.highlight = a > 0.0 ? std::pow(std::min(1.0, 0.5 * tol / a), 1.0 / n) * one : big;
    g.nl_miss = b > 0.0 ? tol / b * one : big;
    g.nl_miss_degree = b > 0.0 ? c.degree_tol / b * one : big;
    g.nh_miss = a > 0.0 ? 0.5 * tol / (a * n) * one : big;
    // K = max over [0, 1] of |prod (t - t_i)| / (d + 1)!, on a grid of 1/1000 (frame constant).
    auto spread = [&](const std::vector<double>& nodes) {
        double worst = 0.0;
        for (int i = 0; i <= 1000; ++i) {
            double v = 1.0;
            for (double t : nodes) v *= (i / 1000.0 - t);
            worst = std::max(worst, std::abs(v));
        }
        double fact = 1.0;
        for (std::size_t i = 2; i <= nodes.size(); ++i) fact *= double(i);
        const double kk = worst / fact;
        return a > 0.0 ? c.lobe_tol * std::pow(0.5 * tol / (a * kk), 1.0 / double(nodes.size())) / n * one : big;
    };
    std::vector<double> cubic_t;
    for (unsigned e : cubic_points(c.set)) cubic_t.push_back(e / 8.0);
    g.spread_cubic = spread(cubic_t);
    g.spread_quad = spread({0.0, 0.5, 1.0});
    return g;
}

estimate_decider::estimate_decider(const plan_config& c)
    : tol_(c.length_tol * (1u << colour_fmt.frac)) {}  // levels against Q8.8 codes: scaled once per frame

// A cubic first: a large third-order term means a feature between the samples that the check point
// in the other half cannot see (head 512: the same NMSE for about 6 % fewer long operations, the
// largest error 15 levels instead of 18 .. 85); the cubic's own fourth sample costs no extra
// geometry. Then every interval's check point.
bool estimate_decider::accept(length_candidate& cand) const {
    if (!cand.job().deg2 && cand.over(cand.quad_miss(), 2.0 * tol_)) return false;
    return !cand.over(cand.check_miss(), tol_);
}

plan make_plan(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
               const plan_config& c) {
    validate(c);
    return make_plan(r, k, dev, c, std::vector<uint8_t>(r.tri.size(), 0), estimate_decider(c));
}

plan make_plan(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
               const plan_config& c, const std::vector<uint8_t>& taken) {
    validate(c);
    return make_plan(r, k, dev, c, taken, estimate_decider(c));
}

plan make_plan(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
               const plan_config& c, const length_decider& decide) {
    return make_plan(r, k, dev, c, std::vector<uint8_t>(r.tri.size(), 0), decide);
}

plan make_plan(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
               const plan_config& c, const std::vector<uint8_t>& taken, const length_decider& decide) {
    validate(c);
    if (taken.size() != r.tri.size())
        throw scene::scene_error("make_plan: the taken pixels' map has " + std::to_string(taken.size()) +
                                 " entries for a raster of " + std::to_string(r.tri.size()) + " pixels");
    plan p;
    p.width = r.width;
    p.height = r.height;
    planner pl(r, k, dev, c, p, &taken, decide);
    for (unsigned y = 0; y < r.height; ++y) pl.line(y);
    return p;
}

plan plan_of_jobs(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
                  const plan_config& c, const std::vector<interval_job>& shapes) {
    plan p;
    p.width = r.width;
    p.height = r.height;
    scene::span_stepper stepper(r, c.walk_edges);
    const std::array<unsigned, 4> cubic = cubic_points(c.set);
    std::size_t i = 0;
    for (unsigned y = 0; y < r.height; ++y) {
        line_geometry lg(r, y, k, dev, p);
        unsigned free_from = 0;  // the first pixel of the line no job has taken yet
        for (; i < shapes.size() && shapes[i].y == y; ++i) {
            interval_job job = shapes[i];
            job.len = 1u << job.m;
            job.deg2 = job.m > 0 && job.deg2;
            std::vector<unsigned> at;  // the sample pixels
            if (job.m == 0)
                at = {job.x0};
            else if (job.deg2)
                for (unsigned e : quad_points) at.push_back(job.x0 + e * job.len / 8);
            else
                for (unsigned e : cubic) at.push_back(job.x0 + e * job.len / 8);
            const std::string where = "plan_of_jobs: the job at line " + std::to_string(y) + ", x " + std::to_string(job.x0);
            if (job.x0 < free_from) throw std::invalid_argument(where + " overlaps the one before or is out of order");
            for (unsigned x : at)
                if (x >= r.width || !r.covered(x, y)) throw std::invalid_argument(where + " has a sample off the covered pixels");
            for (unsigned s = 0; s < 4; ++s) job.s[s] = lg.sample(at[std::min<std::size_t>(s, at.size() - 1)]);
            job.zone = static_cast<uint8_t>(head_zone(r, lg.geometry(job.x0)));
            free_from = job.x0 + job.len;
            p.pixels += job.len;
            p.jobs.push_back(job);
        }
        lg.charge_stepped(stepper, p);
    }
    if (i != shapes.size())
        throw std::invalid_argument("plan_of_jobs: job " + std::to_string(i) + " is out of raster order or below the frame");
    return p;
}

}  // namespace shading::pipeline
