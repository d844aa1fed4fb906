// The interpolation paper's shading system as a bit-accurate golden model (plain C++, no SystemC): the geometry side
// plans each raster line into intervals and delivers N.H and N.L at their sample points; the
// hardware forms a colour sample per sample point (the specular device, a diffuse multiplier and an
// adder per channel), the coefficient unit turns the samples into a polynomial, and the Horner unit
// (or our forward-difference evaluator) gives every pixel of the interval, clamped to the pixel format.
// The SystemC pipeline (modules/pipeline/) is bit-exact against golden_interval() and golden_frame().
//
// This header is the contract between the parts:
//   frame_constants / sample_geometry / golden_sample   the sample stage      (floor: arith/pipeline_arith.*)
//   interval_job / interval_pixels                       one interval          (floor: arith/pipeline_arith.*)
//   frame_constants_of / sample_of / golden_interval     from a scene, checked (golden_pipeline.cpp)
//   plan_config / make_plan                              the geometry side     (plan.cpp)
//   length_decider / plan_of_jobs                        its seams for studies (plan.cpp)
//   head_zone / zone names                               the Fig. 5 zone map   (zones.cpp)
//   golden_frame / hardware_ops / metrics                a whole frame         (golden_pipeline.cpp, metrics.cpp)
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "arith/pipeline_arith.h"
#include "formats/fixed_point.h"
#include "formats/interp_formats.h"
#include "formats/pipeline_formats.h"
#include "formats/specular_formats.h"
#include "scene/counted.h"
#include "scene/raster.h"
#include "scene/scanline.h"
#include "scene/shade.h"
#include "scene/world.h"

namespace shading::pipeline {

// ---- Formats of the sample stage: src/floor/formats/pipeline_formats.h; the sample stage's and an
// interval's arithmetic (rgb_codes, frame_constants, sample_geometry, golden_sample, evaluator,
// interval_job, golden_output_clamp, interval_pixels): src/floor/arith/pipeline_arith.h. Both are
// shared with the SystemC modules, which may not include this header (it pulls in the rasteriser).

// ---- Sample stage ----
// The frame constants of a scene. The hardware path shades one material under one light: throws
// scene::scene_error naming the scene if it has more than one light or its objects' materials differ.
frame_constants frame_constants_of(const scene::world& s);
// 255 k_d I as a Q8.8 code (pipeline_formats.h: kdi_fmt): rounded to nearest, k_d I clamped to [0, 1].
uint64_t kdi_code(double kd_times_i);

// Single light (light index 0). Pure format conversion: not counted.
sample_geometry sample_of(const scene::pixel_geometry& g);

// ---- One interval ----
// Every pixel of one interval (interval_pixels, pipeline_arith.h); throws scene::scene_error naming
// the interval if the hardware cannot take it (interval_problem).
std::vector<rgb_codes> golden_interval(const interval_job& job, const frame_constants& k,
                                       const scene::device_config& dev, evaluator e, interp::sample_set set,
                                       interp::div3_mode div);

// ---- The geometry side: planning a frame into intervals ----
// How the geometry side computes N, V, L, H at the points it needs: `stepped` (the default) steps the
// interpolated attributes along the line from point to point as a scan-line renderer does
// (scene::span_stepper: per-triangle set-up, run starts, adds per step); `scratch` computes each point
// from scratch (scene::geometry_at: barycentrics, one division, three interpolations). The plan and
// its images are the same; only the counts differ (plan.geometry_stepped or plan.geometry).
enum class geometry_unit { stepped, scratch };
const char* geometry_unit_name(geometry_unit u);  // "stepped", "scratch"

// Length and degree policies. `geometry` (ours) decides from the geometry side's own values only:
// N.H and N.L at the interval's sample points and check point and per-frame constants (from n,
// k_s I, k_d I and the tolerance, computed once per frame like the device's a(n)); see plan.cpp.
// `adaptive` reads exact colours (the sample stage's output) at a check point, which no modelled
// hardware returns to the geometry side: policy_runs_on_geometry_side() says which can run there.
enum class length_policy { fixed, adaptive, geometry };
enum class degree_policy { cubic, quadratic, zones, adaptive, geometry };
const char* length_policy_name(length_policy p);  // "fixed", "adaptive", "geometry"
const char* degree_policy_name(degree_policy p);  // "cubic", "quadratic", "zones", "adaptive", "geometry"
// True where a hardware geometry side can run the policy as it stands (its inputs are N.H, N.L,
// positions and per-frame constants); false for the adaptive ones (they need the colour samples back).
bool policy_runs_on_geometry_side(length_policy p);
bool policy_runs_on_geometry_side(degree_policy p);

// Sample points of an interval as fractions of N in eighths (t = k/8), for either sample set:
// cubic case 1: 0, 1/4, 1/2, 1; case 2: 0, 1/2, 3/4, 1. Quadratic: 0, 1/2, 1.
inline std::array<unsigned, 4> cubic_points(interp::sample_set set) {
    return set == interp::sample_set::case1 ? std::array<unsigned, 4>{0, 2, 4, 8} : std::array<unsigned, 4>{0, 4, 6, 8};
}
inline constexpr std::array<unsigned, 3> quad_points{0, 4, 8};

struct plan_config {
    interp::sample_set set = interp::sample_set::case1;
    interp::div3_mode div = interp::div3_mode::shift_add;
    length_policy length = length_policy::fixed;
    unsigned m = 4;                        // fixed: N = 2^m
    unsigned m_min = interp::m_min;        // adaptive: range of m tried, longest first
    unsigned m_max = 5;
    double length_tol = 1.0;               // adaptive length: largest accepted error estimate, 8-bit levels
    bool exact_fallback = true;            // adaptive length: where even 2^m_min fails, 2^m_min exact pixels
    // Adaptive and geometry length: an accepted cubic interval of 2^m > 2^m_min pixels goes out as two
    // quadratic intervals of 2^(m-1) through its four samples and its check point (t = 0, 1/4, 1/2 and
    // 1/2, 3/4, 1): the point the decision paid for becomes a sample instead of being thrown away.
    bool split_at_check = false;
    // Adaptive and geometry length (ours): an interval may be at most `above_slack` levels longer than
    // the shortest interval the line above has over the same pixels (a line buffer of each pixel's
    // level, exact pixels 0; pixels the line above does not cover set no limit; 2^m_min is always
    // allowed, as the shortest interval must be). A feature the line above's checks found is not
    // jumped over by a long interval whose check misses it between its samples. Negative: no limit
    // (the default).
    int above_slack = -1;
    // Adaptive and geometry length (ours): an interval above 2^m_min whose sample and check points are
    // all unlit (N.L <= 0: only the ambient term) is rejected if one of its pixels is lit, so a lit
    // patch between unlit points is not jumped over. The geometry side knows it without shading a
    // pixel: inside a triangle N is a positive combination of its vertex normals with the rasteriser's
    // plane values as weights, so N.L > 0 exactly where the plane sum_i (N_i.L) g_i is > 0, which is
    // linear along the line (tested at each run's two ends; a triangle whose vertex normals all face
    // away needs no test). Exact for a directional light; with a point light the vertices' own L stand
    // in. Its arithmetic is charged to the decision (lit_planes.h).
    bool lit_guard = false;
    degree_policy degree = degree_policy::cubic;
    double degree_tol = 0.5;               // adaptive degree: largest accepted quadratic error estimate
    // Geometry length policy: 0 < lobe_tol; the spread of N.H an interval may span in the highlight,
    // as a multiple of the bound derived from length_tol (plan.cpp); 1 is the bound itself.
    double lobe_tol = 1.0;
    double depth_step = 0.02;              // world units: a depth jump that ends a segment (raster.h)
    bool surface_breaks = true;            // also end segments where neighbours' triangles share no vertex (a fold)
    evaluator eval = evaluator::horner;    // fd: fixed length keeps one m (tails exact); adaptive as Horner
    geometry_unit unit = geometry_unit::stepped;  // which geometry count hardware_ops charges
    bool walk_edges = false;  // the stepped unit (and the scan-line Phong) walk edges between lines (scanline.h)
    // The sample stage's carry (modules/pipeline/sample_ctrl.h): a job whose first sample's codes are
    // the last formed sample's takes that colour from the last-sample registers, not from the device.
    bool carry_samples = false;
};
// Throws scene::scene_error with a clear message for an invalid config (m out of range, m_min > m_max,
// a negative tolerance). Either evaluator takes either length policy (fd: fd_eval_var).
void validate(const plan_config& c);

// The geometry-only policies' per-frame constants, in Q1.15 code units of N.H / N.L (plan.cpp says how
// each follows from n, k_s I, k_d I, length_tol, degree_tol and lobe_tol).
struct geometry_limits {
    double highlight = 0.0;     // c_n: N.H at or above it is in a highlight
    double nl_miss = 0.0;       // largest accepted miss of N.L's polynomial (length)
    double nl_miss_degree = 0.0;  // the same for the quadratic degree
    double nh_miss = 0.0;       // largest accepted miss of N.H's polynomial in a highlight
    double spread_cubic = 0.0, spread_quad = 0.0;  // largest N.H spread of an interval in a highlight
};
geometry_limits geometry_limits_of(const frame_constants& k, const plan_config& c);

// A frame's intervals, line by line, left to right, and what the geometry side spent on them:
// `geometry` counts geometry_at plus the two dot products at every distinct pixel whose geometry was
// computed (sample points, and the extra check points the adaptive policies look at); `decision`
// counts the policies' own arithmetic (the error estimates, the fold test's compares). Lines are split into segments at every
// discontinuity (raster.h: coverage edges, object changes, depth steps), and no interval's samples
// straddle one; pieces too short for an interval of 2^m_min are exact pixels. With surface_breaks,
// segments also end where the visible surface jumps to a part of the mesh not connected to the pixel
// before (neighbouring pixels' triangles share no vertex: an eyelid or ear fold in front of skin at
// nearly the same depth). Adaptive length tries m from min(m_max, the previous interval's m + 1) down
// to m_min and takes the first whose polynomial misses the exact colour at the middle of its widest
// gap (case 1 t = 3/4, case 2 t = 1/4: a check point) by at most length_tol and, for a cubic, whose
// quadratic through t = 0, 1/2, 1 misses the cubic's fourth sample by at most 2 x length_tol; with
// exact_fallback, where even m_min fails, its 2^m_min pixels are exact. With split_at_check the
// decisions are the same; only each accepted cubic above 2^m_min is delivered as its two halves.
struct plan {
    unsigned width = 0, height = 0;
    std::vector<interval_job> jobs;
    scene::op_counts geometry, decision;
    // The same points' geometry (and dot products) stepped along each line in increasing x by one
    // scene::span_stepper over the frame (its set-ups, run starts and steps in `stepping`).
    scene::op_counts geometry_stepped;
    scene::stepping_stats stepping;
    std::size_t geometry_points = 0;   // distinct pixels whose geometry was computed
    std::vector<std::array<unsigned, 2>> points;  // those pixels {x, y}, line by line, left to right
    // Colour samples the adaptive policies evaluated (golden_sample) at pixels that are no job's
    // sample point: their check points. The sample stage's cost for these is the decision's too.
    std::size_t check_samples = 0;
    std::size_t pixels = 0;            // covered pixels (= sum of len)
};
// Pixels xa..xb (inclusive, as {xa, xb}) of line y with no discontinuity inside, left to right: the
// spans cut at every discontinuity (raster.h: coverage edges, object changes, depth steps of
// c.depth_step) and, with c.surface_breaks, at folds; the fold test's compares charged to `decision`
// (null: uncounted). Every length policy plans segment by segment.
std::vector<std::array<unsigned, 2>> line_segments(const scene::rasterised& r, unsigned y, const plan_config& c,
                                                   scene::op_counts* decision);

// The adaptive length policy's decision, a seam for studies: make_plan shows each candidate interval
// to a decider, which accepts it or not. The candidate's estimates are computed on first use, their
// colour samples, geometry and arithmetic charged to the plan then, so a decider pays for what it
// reads; the hardware's decider (estimate_decider) reads them as the policy above describes.
class length_candidate {
public:
    virtual ~length_candidate() = default;
    virtual const interval_job& job() const = 0;
    // What the policy sends for it: the job, or with split_at_check its two quadratic halves.
    virtual std::vector<interval_job> sent() = 0;
    // Largest over the channels, in Q8.8 code units: for a cubic, the quadratic through t = 0, 1/2, 1
    // against the cubic's fourth sample (std::logic_error for a quadratic); the interval's polynomial
    // against the exact colour at its check point.
    virtual double quad_miss() = 0;
    virtual double check_miss() = 0;
    // v > limit on the decision's comparator (charged to the plan's decision).
    virtual bool over(double v, double limit) = 0;
};
class length_decider {
public:
    virtual ~length_decider() = default;
    virtual bool accept(length_candidate& candidate) const = 0;
};
// The adaptive length policy's own decision: a cubic's quadratic miss within 2 x length_tol, then the
// check point's miss within length_tol (both in levels, scaled to Q8.8 once per frame).
class estimate_decider : public length_decider {
public:
    explicit estimate_decider(const plan_config& c);
    bool accept(length_candidate& candidate) const override;

private:
    double tol_;
};

plan make_plan(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
               const plan_config& c);
// The same over the pixels `taken` (one entry per raster pixel) leaves out: they end segments, as a
// discontinuity does, and no job covers them (the cells deliver them, cells.h).
plan make_plan(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
               const plan_config& c, const std::vector<uint8_t>& taken);
// Either of the above with the adaptive length policy's decisions taken by `decide` (the others read
// no decider): the rest of the plan, and what each candidate's estimates cost, are make_plan's.
plan make_plan(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
               const plan_config& c, const length_decider& decide);
plan make_plan(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
               const plan_config& c, const std::vector<uint8_t>& taken, const length_decider& decide);
// A plan of intervals chosen elsewhere (a study's), counted as make_plan counts its own: `shapes` in
// raster order (line by line, left to right), each with y, x0, m (0: an exact pixel) and deg2; the
// jobs get len, their samples and zone, and the plan its pixels and the geometry of every sample
// point (both units, stepped along each line as make_plan steps). No decision is charged. Throws
// std::invalid_argument for shapes out of order or overlapping.
plan plan_of_jobs(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
                  const plan_config& c, const std::vector<interval_job>& shapes);

// ---- Zones of the head (the interpolation paper, Fig. 5, reconstructed: the figure is not in the text) ----
// 0 other (ears, skull, neck), 1 brows, 2 forehead, 3 eyes, 4 cheeks, 5 nose, 6 mouth, 7 chin:
// numbered so that the interpolation paper's quadratic zones 2, 4, 7 are the flat ones (zones.cpp, zone_is_quadratic).
inline constexpr unsigned zone_count = 8;
const char* zone_name(unsigned zone);
bool zone_is_quadratic(unsigned zone);
// The zone of a surface point of the head scan, from its position (g.p) relative to its mesh's nose
// tip (the most forward vertex, +z) and top, in units of their height difference; boxes calibrated on
// the scan (zones.cpp). 0 where geometry_at gives no position (orthographic camera, directional light).
unsigned head_zone(const scene::rasterised& r, const scene::pixel_geometry& g);

// ---- A whole frame ----
struct frame {
    unsigned width = 0, height = 0;
    std::vector<rgb_codes> px;          // pixel_fmt codes; 0 where not covered
    std::vector<uint8_t> covered;
    std::vector<uint8_t> degree;        // 0 empty, 1 exact pixel, 2 quadratic, 3 cubic
    std::vector<uint8_t> log2_len;      // m of the pixel's interval (0 exact)
    std::vector<uint8_t> zone;
};
// A w x h frame with nothing covered (every code 0).
frame empty_frame(unsigned w, unsigned h);
// Runs golden_interval over every job of the plan into a frame (the frame buffer's content).
frame golden_frame(const plan& p, const frame_constants& k, const scene::device_config& dev, const plan_config& c);
// The same frame with every covered pixel an exact sample (golden_sample at every pixel, clamped to
// pixel_fmt): per-pixel shading through the same device, the interpolation's reference.
frame per_pixel_frame(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev);

// Operations of the hardware path for a planned frame, counted per block as the hardware performs
// them: the geometry side (plan.geometry_stepped, or plan.geometry with c.unit = scratch, + plan.decision), per sample evaluated by the sample stage
// the device's multipliers and adders and the diffuse multiplier and adders, per interval the
// coefficient unit's adders, per pixel the evaluator's multiplications and additions. `interpolation`
// is everything after the geometry side. With c.carry_samples a job whose first sample's codes equal
// the previous job's last sample's (t = 1 of an interval; an exact pixel's own) forms one sample less.
struct hardware_counts {
    scene::op_counts geometry, sample_stage, interpolation;
    std::size_t pixels = 0, samples = 0, intervals = 0;
    std::size_t carried = 0;  // with carry_samples: samples taken from the last-sample registers (not in `samples`)
    uint64_t clocks = 0;  // clock cycles of the evaluator for the frame (Horner: 6 per cubic pixel, 4 per quadratic)
    scene::op_counts total() const {
        scene::op_counts t = geometry;
        t += sample_stage;
        t += interpolation;
        return t;
    }
};
// A device's operations per colour sample: scene::device_sample_ops (shade.h), the scene layer's, as
// every scheme that calls a device is charged them.
using scene::device_sample_ops;
// The sample stage's operations for one colour: the device's (device_sample_ops), then per channel
// the diffuse multiplier k_d*I x N.L and the two adders of ambient + diffuse + specular.
scene::op_counts colour_sample_ops(const scene::device_config& dev, unsigned n);
// The counts with the frame's device (dev, n); without them, a Fig. 1 device's.
hardware_counts hardware_ops(const plan& p, const plan_config& c, const scene::device_config& dev, unsigned n);
hardware_counts hardware_ops(const plan& p, const plan_config& c);

// The stepping geometry unit's count for any geometry points, (x, y) in the order the unit reaches
// them: one scene::span_stepper over the frame, each point's geometry and its dot products, as
// make_plan charges a plan's points (plan.geometry_stepped, plan.stepping). For plans made elsewhere,
// such as a study's emulated policy; the points must be covered pixels.
struct stepped_count {
    scene::op_counts ops;
    scene::stepping_stats stats;
};
// down: empty, or one flag a point, set where the point is read down a column (span_stepper::at).
stepped_count stepped_geometry(const scene::rasterised& r, const std::vector<std::array<unsigned, 2>>& points,
                               bool walk_edges, const std::vector<uint8_t>& down = {});
// What an edge walker must store for these points in this order: the most triangles whose stepped
// values it holds at once, each from its first point to its last (the points must be covered pixels).
std::size_t walker_live_triangles(const scene::rasterised& r, const std::vector<std::array<unsigned, 2>>& points);

// ---- Error measures over covered pixels and the three channels, in 8-bit units ----
// Levels beyond which error_stats counts pixels: the NMSE and the largest error alone cannot say
// whether a large error is one pixel (a glint narrower than a pixel between two samples) or a region.
inline constexpr std::array<double, 3> error_levels{4.0, 16.0, 64.0};
struct error_stats {
    double nmse = 0.0;     // sum (a - ref)^2 / sum ref^2
    double psnr_db = 0.0;  // 10 log10(255^2 / MSE); +inf when equal
    double max_abs = 0.0;  // largest |a - ref|
    std::size_t pixels = 0;
    // Pixels whose largest channel error |a - ref| exceeds error_levels[i] (strictly).
    std::array<std::size_t, error_levels.size()> pixels_over{};
};
// The values of a frame's pixels in 8-bit units (code / 256).
scene::shaded_image to_image(const frame& f);
// `zone` < 0: the whole image; otherwise only pixels of that zone (zones from `zones`, per pixel).
error_stats compare(const scene::shaded_image& a, const scene::shaded_image& ref, const std::vector<uint8_t>* zones = nullptr,
                    int zone = -1);

}  // namespace shading::pipeline
