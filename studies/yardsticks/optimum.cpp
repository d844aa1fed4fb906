// The optimum plan (optimum.h, optimal_plan): a yardstick for the length and degree policies. It
// knows what no policy knows (every pixel's colour and its reference) and pays nothing to decide, so
// no policy can need fewer geometry points at its NMSE; its certificate says how far each policy is
// from the best the pipeline's intervals allow, and so what ratio against Phong is in reach at all.
//
// Per segment (pipeline::line_segments: the same segments as make_plan), a piece at pixel i is an exact pixel
// or an interval of 2^m pixels (m_min..m_max, whose t = 1 sample is pixel i + 2^m of the segment),
// quadratic or cubic. Points are counted as the geometry side computes them: a piece's first pixel
// costs one unless an interval ended there (its t = 1 sample), an interval adds its inner samples and
// its t = 1 sample. The squared error of each candidate piece is computed once (interval_pixels, the
// hardware's arithmetic, against the reference image); a backward dynamic programme over the segment
// then minimises points + lambda x error exactly, for each lambda of a bisection.
//
// Planned from the line above (o.from_above >= 0), each candidate is priced with the line
// above's errors instead of its own: what a planner could reach that knew every colour of the line
// above (more than any hardware keeps) but nothing of its own line. The plan is chosen on those prices
// and its true error counted; the certificate stays the optimum's.
#include "studies/yardsticks/optimum.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace shading::yardsticks {

using namespace shading::pipeline;

void validate(const optimum_config& o) {
    if (!(o.nmse >= 0.0) || !std::isfinite(o.nmse)) throw scene::scene_error("optimum: the NMSE must be finite and >= 0");
    if (o.from_above > int(window_max))
        throw scene::scene_error("optimum: the window over the line above, " + std::to_string(o.from_above) + ", exceeds " +
                                 std::to_string(window_max) + " pixels; negative for the optimum's own prices");
}

namespace {

// A segment's candidate pieces: the squared error (8-bit levels^2, three channels) of the exact pixel
// and of every interval (m, degree) at each of its pixels; +inf where the interval does not fit.
struct segment_costs {
    unsigned y = 0, xa = 0, len = 0;
    std::vector<double> exact;      // [i]
    std::vector<double> intervals;  // [(i * lengths + (m - m_min)) * 2 + cubic]
};

// A piece of the chosen plan: m = 0 an exact pixel.
struct piece {
    unsigned i = 0, m = 0;
    bool cubic = false;
};

class optimum_search {
public:
    optimum_search(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
                   const plan_config& c, const optimum_config& o, optimum_certificate& cert)
        : r_(r), k_(k), dev_(dev), c_(c), o_(o), cert_(cert), lengths_(c.m_max - c.m_min + 1) {}

    // The reference image and every segment's candidate errors.
    void prepare() {
        const frame exact = per_pixel_frame(r_, k_, dev_);
        const scene::shaded_image ref = o_.ref == optimum_config::reference::interpolation
                                            ? to_image(exact)
                                            : scene::render_phong(r_);
        const double lsb = pixel_fmt.lsb();
        auto err = [&](std::size_t at, const rgb_codes& v) {
            double e = 0.0;
            for (int ch = 0; ch < 3; ++ch) {
                const double d = double(v[ch]) * lsb - ref.value[at][ch];
                e += d * d;
            }
            return e;
        };
        for (std::size_t at = 0; at < ref.value.size(); ++at)
            if (ref.covered[at])
                for (int ch = 0; ch < 3; ++ch) ref_energy_ += ref.value[at][ch] * ref.value[at][ch];
        const double inf = std::numeric_limits<double>::infinity();
        const std::array<unsigned, 4> cubic = cubic_points(c_.set);
        std::vector<sample_geometry> sg(r_.width);
        for (unsigned y = 0; y < r_.height; ++y) {
            for (unsigned x = 0; x < r_.width; ++x)
                if (r_.covered(x, y)) sg[x] = sample_of(scene::geometry_at(r_, x, y, nullptr));
            for (const auto& seg : line_segments(r_, y, c_, &decision_)) {
                segment_costs s;
                s.y = y;
                s.xa = seg[0];
                s.len = seg[1] - seg[0] + 1;
                s.exact.resize(s.len);
                s.intervals.assign(std::size_t(s.len) * lengths_ * 2, inf);
                for (unsigned i = 0; i < s.len; ++i) {
                    const unsigned x = s.xa + i;
                    s.exact[i] = err(r_.index(x, y), exact.px[r_.index(x, y)]);
                    for (unsigned m = c_.m_min; m <= c_.m_max; ++m) {
                        const unsigned n = 1u << m;
                        if (i + n >= s.len) break;  // the t = 1 sample must lie in the segment
                        for (unsigned cub = 0; cub < 2; ++cub) {
                            interval_job job;
                            job.y = y;
                            job.x0 = x;
                            job.len = n;
                            job.m = m;
                            job.deg2 = cub == 0;
                            if (job.deg2) {
                                for (unsigned j = 0; j < 3; ++j) job.s[j] = sg[x + quad_points[j] * n / 8];
                                job.s[3] = job.s[2];
                            } else {
                                for (unsigned j = 0; j < 4; ++j) job.s[j] = sg[x + cubic[j] * n / 8];
                            }
                            const std::vector<rgb_codes> px = interval_pixels(job, k_, dev_, c_.eval, c_.set, c_.div);
                            double e = 0.0;
                            for (unsigned j = 0; j < n; ++j) e += err(r_.index(x + j, y), px[j]);
                            s.intervals[index(i, m, cub)] = e;
                        }
                    }
                }
                segs_.push_back(std::move(s));
            }
        }
    }

    // The prices from the line above: each candidate (exact pixel, or interval of one length and
    // degree) at pixel x of line y costs the largest error of the same candidate on line y - 1 at
    // x - window .. x + window where it fits a segment there; where none does (a segment's first line,
    // a coverage edge), its own error (counted in above_fallback).
    void price_from_above(unsigned window) {
        priced_ = segs_;
        std::size_t fallback = 0, candidates = 0;
        std::vector<int> above(r_.width, -1), here(r_.width, -1);  // pixel -> its segment on the line
        std::size_t k = 0;
        for (unsigned y = 0; y < r_.height; ++y) {
            std::swap(above, here);
            std::fill(here.begin(), here.end(), -1);
            const std::size_t first = k;
            for (; k < segs_.size() && segs_[k].y == y; ++k)
                for (unsigned i = 0; i < segs_[k].len; ++i) here[segs_[k].xa + i] = int(k);
            for (std::size_t j = first; j < k; ++j) {
                segment_costs& pr = priced_[j];
                // The largest of get(q, i') over the line above's segments q covering x + d, |d| <= window.
                auto from_above = [&](unsigned x, auto get) {
                    double e = -1.0;
                    for (int d = -int(window); d <= int(window); ++d) {
                        const int xd = int(x) + d;
                        if (xd < 0 || xd >= int(r_.width) || above[std::size_t(xd)] < 0) continue;
                        const segment_costs& q = segs_[std::size_t(above[std::size_t(xd)])];
                        e = std::max(e, get(q, unsigned(xd) - q.xa));
                    }
                    return e;
                };
                for (unsigned i = 0; i < pr.len; ++i) {
                    const unsigned x = pr.xa + i;
                    auto price = [&](double& own, auto get) {
                        ++candidates;
                        const double e = from_above(x, get);
                        if (e >= 0.0) own = e;
                        else ++fallback;
                    };
                    price(pr.exact[i], [](const segment_costs& q, unsigned iq) { return q.exact[iq]; });
                    for (unsigned m = c_.m_min; m <= c_.m_max; ++m) {
                        const unsigned n = 1u << m;
                        if (i + n >= pr.len) break;
                        for (unsigned cub = 0; cub < 2; ++cub)
                            price(pr.intervals[index(i, m, cub)], [&](const segment_costs& q, unsigned iq) {
                                return iq + n < q.len ? q.intervals[index(iq, m, cub)] : -1.0;
                            });
                    }
                }
            }
        }
        cert_.above_fallback = candidates > 0 ? double(fallback) / double(candidates) : 0.0;
    }
    const std::vector<segment_costs>& prices() const { return o_.from_above >= 0 ? priced_ : segs_; }

    // Points and squared error of the plan minimising points + lambda x error over every segment, the
    // errors priced by `by` (segs_ for the optimum); with `out`, its pieces per segment.
    std::pair<double, double> solve(double lambda, std::vector<std::vector<piece>>* out,
                                    const std::vector<segment_costs>& by) {
        double points = 0.0, error = 0.0;
        if (out) out->assign(segs_.size(), {});
        for (std::size_t k = 0; k < segs_.size(); ++k) {
            const segment_costs& s = by[k];
            const segment_costs& truth = segs_[k];
            // g[have][i]: the least cost of pixels i.. of the segment, `have` when pixel i's geometry
            // is already computed (an interval's t = 1 sample).
            std::vector<double> g0(s.len + 1, 0.0), g1(s.len + 1, 0.0);
            std::vector<piece> best0(s.len), best1(s.len);
            for (unsigned i = s.len; i-- > 0;) {
                for (unsigned have = 0; have < 2; ++have) {
                    const double first = have ? 0.0 : 1.0;
                    double cost = first + lambda * s.exact[i] + g0[i + 1];
                    piece choice{i, 0, false};
                    for (unsigned m = c_.m_min; m <= c_.m_max; ++m) {
                        const unsigned n = 1u << m;
                        if (i + n >= s.len) break;
                        for (unsigned cub = 0; cub < 2; ++cub) {
                            const double v = first + (cub ? 3.0 : 2.0) + lambda * s.intervals[index(i, m, cub)] + g1[i + n];
                            if (v < cost) {
                                cost = v;
                                choice = {i, m, cub != 0};
                            }
                        }
                    }
                    (have ? g1 : g0)[i] = cost;
                    (have ? best1 : best0)[i] = choice;
                }
            }
            bool have = false;
            for (unsigned i = 0; i < s.len;) {
                const piece pc = (have ? best1 : best0)[i];
                points += have ? 0.0 : 1.0;
                if (pc.m == 0) {
                    error += truth.exact[i];
                    have = false;
                    i += 1;
                } else {
                    points += pc.cubic ? 3.0 : 2.0;
                    error += truth.intervals[index(i, pc.m, pc.cubic)];
                    have = true;
                    i += 1u << pc.m;
                }
                if (out) (*out)[k].push_back(pc);
            }
        }
        return {points, error};
    }

    // The length policies' own structure with perfect estimates: per segment left to right, the
    // longest m (growing by at most one level, as make_plan's adaptive length) whose quadratic, else
    // cubic, has a mean squared error per channel of at most tau2; where even 2^m_min misses, 2^m_min
    // exact pixels. Points and squared error as solve(), the acceptance priced by prices().
    std::pair<double, double> greedy(double tau2, std::vector<std::vector<piece>>* out) {
        double points = 0.0, error = 0.0;
        if (out) out->assign(segs_.size(), {});
        for (std::size_t k = 0; k < segs_.size(); ++k) {
            const segment_costs& s = segs_[k];
            const segment_costs& by = prices()[k];
            bool have = false;
            unsigned i = 0, grow = c_.m_max;
            auto take = [&](const piece& pc) {
                points += have ? 0.0 : 1.0;
                if (pc.m == 0) {
                    error += s.exact[pc.i];
                    have = false;
                } else {
                    points += pc.cubic ? 3.0 : 2.0;
                    error += s.intervals[index(pc.i, pc.m, pc.cubic)];
                    have = true;
                }
                if (out) (*out)[k].push_back(pc);
            };
            while (s.len - 1 - i >= (1u << c_.m_min)) {
                const unsigned room = s.len - 1 - i;  // the t = 1 sample must lie in the segment
                unsigned top = c_.m_min;
                while (top < grow && (1u << (top + 1)) <= room) ++top;
                bool done = false;
                for (unsigned m = top + 1; m-- > c_.m_min && !done;)
                    for (unsigned cub = 0; cub < 2 && !done; ++cub)
                        if (by.intervals[index(i, m, cub)] <= tau2 * 3.0 * double(1u << m)) {
                            take({i, m, cub != 0});
                            i += 1u << m;
                            grow = std::min(m + 1, c_.m_max);
                            done = true;
                        }
                if (!done) {
                    for (unsigned j = 0; j < (1u << c_.m_min); ++j) take({i++, 0, false});
                    grow = std::min(c_.m_min + 1, c_.m_max);
                }
            }
            while (i < s.len) take({i++, 0, false});
        }
        return {points, error};
    }

    // The greedy's tolerance: the largest (bisected) whose plan meets the NMSE.
    std::vector<std::vector<piece>> search_greedy() {
        const double allowed = o_.nmse * ref_energy_;
        auto meets = [&](double tau) { return greedy(tau * tau, nullptr).second <= allowed; };
        double lo = 0.0, hi = 256.0;  // levels: tau = 0 takes only intervals without error
        if (meets(hi)) lo = hi;
        for (int it = 0; it < 40 && lo != hi; ++it) {
            const double mid = lo > 0.0 ? std::sqrt(lo * hi) : hi / 16.0;
            (meets(mid) ? lo : hi) = mid;
            if (hi < 1e-6) break;
        }
        std::vector<std::vector<piece>> pieces;
        const double error = greedy(lo * lo, &pieces).second;
        cert_.greedy_tolerance = lo;
        cert_.greedy_nmse = ref_energy_ > 0.0 ? error / ref_energy_ : 0.0;
        if (o_.from_above >= 0) cert_.above_nmse = cert_.greedy_nmse;
        return pieces;
    }

    // Bisects lambda to the smallest that meets the NMSE; returns the chosen pieces. With `certify`
    // (the optimum, priced by its own errors) its certificate; else, priced from the line above, the
    // plan's NMSE only (there the dual bound does not hold).
    std::vector<std::vector<piece>> search(bool certify) {
        const std::vector<segment_costs>& by = certify ? segs_ : priced_;
        const double allowed = o_.nmse * ref_energy_;
        double bound = 0.0;
        auto trial = [&](double lambda) {
            const auto [points, error] = solve(lambda, nullptr, by);
            bound = std::max(bound, points + lambda * (error - allowed));  // Lagrangian dual: a lower bound
            return error <= allowed;
        };
        double lo = 0.0, hi = 1.0;
        bool feasible = trial(0.0);
        if (feasible) {
            hi = 0.0;
        } else {
            // Squared levels against points: grow until the error fits (or no plan's does).
            while (!(feasible = trial(hi)) && hi < 1e15) {
                lo = hi;
                hi *= 4.0;
            }
            for (int it = 0; feasible && it < 48 && hi > lo * (1.0 + 1e-6); ++it) {
                const double mid = lo > 0.0 ? std::sqrt(lo * hi) : hi / 4.0;
                (trial(mid) ? hi : lo) = mid;
            }
        }
        std::vector<std::vector<piece>> pieces;
        const auto [points, error] = solve(hi, &pieces, by);
        if (!certify) {
            cert_.above_nmse = ref_energy_ > 0.0 ? error / ref_energy_ : 0.0;
            cert_.above_lambda = hi;
            return pieces;
        }
        cert_.points_bound = feasible ? bound : 0.0;  // <= points: at lambda = hi the error is within
        cert_.nmse = ref_energy_ > 0.0 ? error / ref_energy_ : 0.0;
        cert_.lambda = hi;
        cert_.feasible = feasible;
        return pieces;
    }

    // The chosen pieces as a plan, its geometry counted as make_plan counts it (plan_of_jobs) and the
    // segments' fold tests as its decision.
    plan emit(const std::vector<std::vector<piece>>& pieces) {
        std::vector<interval_job> shapes;
        for (std::size_t k = 0; k < segs_.size(); ++k)
            for (const piece& pc : pieces[k]) {
                interval_job job;
                job.y = segs_[k].y;
                job.x0 = segs_[k].xa + pc.i;
                job.m = pc.m;
                job.deg2 = pc.m > 0 && !pc.cubic;
                shapes.push_back(job);
            }
        plan p = plan_of_jobs(r_, k_, dev_, c_, shapes);
        p.decision += decision_;
        cert_.point_long_min = cheapest_point();
        return p;
    }

private:
    std::size_t index(unsigned i, unsigned m, unsigned cub) const {
        return (std::size_t(i) * lengths_ + (m - c_.m_min)) * 2 + cub;
    }

    // The long operations of a point the stepping unit reaches by a step (no triangle set-up, no run
    // start) with its dot products: no point of any plan costs less. The stepping unit's count of the
    // pair (x, x + 1) less that of x alone. 0 if no two neighbouring pixels of a line share a
    // triangle (then nothing is claimed).
    double cheapest_point() const {
        for (unsigned y = 0; y < r_.height; ++y)
            for (unsigned x = 0; x + 1 < r_.width; ++x)
                if (r_.covered(x, y) && r_.covered(x + 1, y) && r_.tri[r_.index(x, y)] == r_.tri[r_.index(x + 1, y)]) {
                    const uint64_t pair = stepped_geometry(r_, {{x, y}, {x + 1, y}}, false).ops.long_ops();
                    const uint64_t first = stepped_geometry(r_, {{x, y}}, false).ops.long_ops();
                    return double(pair - first);
                }
        return 0.0;
    }

    const scene::rasterised& r_;
    const frame_constants& k_;
    const scene::device_config& dev_;
    const plan_config& c_;
    const optimum_config& o_;
    optimum_certificate& cert_;
    scene::op_counts decision_;  // the segments' fold tests (line_segments), as make_plan charges them
    unsigned lengths_;
    double ref_energy_ = 0.0;
    std::vector<segment_costs> segs_;
    std::vector<segment_costs> priced_;  // with o.from_above >= 0: segs_ priced from the line above
};

}  // namespace

optimum optimal_plan(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
                     const plan_config& c, const optimum_config& o) {
    pipeline::validate(c);
    validate(o);
    optimum out;
    optimum_search s(r, k, dev, c, o, out.certificate);
    s.prepare();
    auto pieces = s.search(true);
    if (o.from_above >= 0) {
        s.price_from_above(unsigned(o.from_above));
        if (!o.greedy) pieces = s.search(false);
    }
    if (o.greedy) pieces = s.search_greedy();
    out.p = s.emit(pieces);
    return out;
}

}  // namespace shading::yardsticks
