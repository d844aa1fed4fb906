// The geometry side's per-line machinery shared by the length policies and plan_of_jobs (plan.cpp) and
// the cells (cells.cpp): a raster line's segments, and its geometry computed once per pixel and counted
// once. Internal to src/golden_pipeline: the contract is pipeline.h.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "golden_pipeline/pipeline.h"
#include "scene/scanline.h"

namespace shading::pipeline {

// Whether the visible surface jumps to another part of the mesh between the covered pixels of
// raster indices a and b: their triangles share no vertex or lie on different objects (a fold; the
// segments' surface_breaks). Its compares are charged to `decision` (null: uncounted).
bool surface_break(const scene::rasterised& r, std::size_t a, std::size_t b, scene::op_counts* decision);

// One raster line's geometry, computed once per pixel and counted once.
class line_geometry {
    using cnum = scene::cnum;
    using cvec3 = scene::cvec3;

public:
    line_geometry(const scene::rasterised& r, unsigned y, const frame_constants& k, const scene::device_config& dev,
                  plan& p)
        : r_(r), y_(y), k_(k), dev_(dev), p_(p), geo_(r.width), have_geo_(r.width, 0), smp_(r.width),
          col_(r.width), have_col_(r.width, 0) {}

    const scene::pixel_geometry& geometry(unsigned x) {
        if (!have_geo_[x]) {
            // geometry_at charges a scratch count, added at once; sample_of may do arithmetic on the
            // counted values, which then lands in the scratch and is ignored: the dot products are
            // charged below, exactly as the references' shade_common computes them.
            scene::op_counts scratch;
            geo_[x] = scene::geometry_at(r_, x, y_, &scratch);
            p_.geometry += scratch;
            smp_[x] = sample_of(geo_[x]);
            charge_dots(geo_[x], &p_.geometry);
            uncount(geo_[x]);  // the scratch count dies here: the kept values charge nothing
            ++p_.geometry_points;
            have_geo_[x] = 1;
        }
        return geo_[x];
    }
    sample_geometry sample(unsigned x) {
        geometry(x);
        return smp_[x];
    }
    bool has_geometry(unsigned x) const { return have_geo_[x] != 0; }
    // N.L, the N.L > 0 gate, and N.H clamped at 0 where the light reaches (sample_of, shade.cpp).
    static void charge_dots(const scene::pixel_geometry& g, scene::op_counts* ops) {
        auto recount = [ops](const cvec3& v) {
            return cvec3{cnum(v.x.value(), ops), cnum(v.y.value(), ops), cnum(v.z.value(), ops)};
        };
        const cvec3 n = recount(g.n);
        const cnum zero(0.0, ops);
        if (dot(n, recount(g.l[0])) > zero) max(dot(n, recount(g.h[0])), zero);
    }
    // The colour sample at pixel x (the sample stage's output), for the policies' estimates.
    bool has_colour(unsigned x) const { return have_col_[x] != 0; }
    const rgb_codes& colour(unsigned x) {
        if (!have_col_[x]) {
            col_[x] = golden_sample(dev_, k_, sample(x));
            have_col_[x] = 1;
        }
        return col_[x];
    }

    // The stepping geometry unit's count: the same points, left to right, stepped along the line by
    // one span_stepper over the frame (plan.geometry_stepped, plan.stepping); the points are listed
    // in plan.points.
    void charge_stepped(scene::span_stepper& stepper, plan& p) const {
        for (unsigned x = 0; x < r_.width; ++x)
            if (has_geometry(x)) {
                charge_dots(stepper.at(x, y_, &p.geometry_stepped), &p.geometry_stepped);
                p.points.push_back({x, y_});
            }
        p.stepping = stepper.stats();
    }

private:
    static void uncount(scene::pixel_geometry& g) {
        auto plain = [](cvec3& v) { v = {cnum(v.x.value(), nullptr), cnum(v.y.value(), nullptr), cnum(v.z.value(), nullptr)}; };
        plain(g.p);
        plain(g.n);
        plain(g.v);
        for (auto& v : g.l) plain(v);
        for (auto& v : g.h) plain(v);
    }
    const scene::rasterised& r_;
    unsigned y_;
    const frame_constants& k_;
    const scene::device_config& dev_;
    plan& p_;
    std::vector<scene::pixel_geometry> geo_;
    std::vector<uint8_t> have_geo_;
    std::vector<sample_geometry> smp_;
    std::vector<rgb_codes> col_;
    std::vector<uint8_t> have_col_;
};


}  // namespace shading::pipeline
