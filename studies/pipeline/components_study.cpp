// The shading components interpolated apart, as the interpolation paper does, against the model's
// one polynomial per channel for their sum (docs/deviations.md, row 22). Golden model only. On one
// scene (default the head at 512, the squared device, n = 20) and the same adaptive policy as the
// race's targets (cubic, split at the check, carry, the line above K = 2, forward differences):
//  - the sum: one plan per --tol-sum, its long operations as counted (render_pipeline's figure);
//  - apart: one plan per --tol-diffuse for ambient + diffuse and one per --tol-specular for specular,
//    every pair's summed frame (saturated) and a lower bound on its long operations (components.h);
//  - the specular plan alone with an exact diffuse given for nothing: what apart could reach at best.
// Each against per-pixel shading of the sum through the device (the interpolation NMSE), ratios
// against the scan-line Phong. Prints Markdown tables and, per design, the cheapest meeting --nmse.
//   build/bin/components_study                  (about 1 s)
//   build/bin/components_study --size 64 --tol-sum 1 --tol-diffuse 1 --tol-specular 1
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "components.h"
#include "scene/shade.h"
#include "testbenches/common/exit_status.h"
#include "testbenches/options/tool_options.h"

using namespace shading;
using namespace shading::pipeline;
using namespace shading::study;

namespace {

struct part {
    double tol = 0.0;
    plan_config c;
    plan p;
    frame g;
};

part plan_part(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
               plan_config c, double tol, unsigned m_max) {
    c.length_tol = tol;
    c.m_max = m_max;
    part out{tol, c, make_plan(r, k, dev, c), {}};
    out.g = golden_frame(out.p, k, dev, c);
    return out;
}

std::string fixed2(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.2f", v);
    return b;
}

struct best {
    std::optional<double> cost;
    std::string what;
    void offer(double c, double nmse, double limit, const std::string& w) {
        if (nmse <= limit && (!cost || c < *cost)) {
            cost = c;
            what = w;
        }
    }
};

}  // namespace

int main(int argc, char* argv[]) {
    tb::components_study_options o;
    if (auto rc = tb::parse_components_study(argc, argv, o)) return *rc;
    try {
        const scene::world w = scene::builtin_scene(o.scene, o.data_dir, o.size, o.size);
        const scene::rasterised r = scene::rasterise(w);
        const frame_constants k = frame_constants_of(w), kd = diffuse_part(k), ks = specular_part(k);
        scene::device_config dev;
        dev.device = scene::parse_device(o.device);

        plan_config base;
        base.length = length_policy::adaptive;
        base.degree = degree_policy::cubic;
        base.split_at_check = true;
        base.carry_samples = true;
        base.above_slack = 2;
        base.eval = evaluator::fd;

        // The reference: per-pixel shading of the sum; its parts must add up to it exactly.
        const frame pp = per_pixel_frame(r, k, dev), pp_d = per_pixel_frame(r, kd, dev),
                    pp_s = per_pixel_frame(r, ks, dev);
        if (add_saturated(pp_d, pp_s).px != pp.px) {
            std::fprintf(stderr, "components_study: the components' per-pixel colours do not add up to the sum's\n");
            return tb::exit_failure;
        }
        const scene::shaded_image ref = to_image(pp);
        auto nmse = [&ref](const frame& f) { return compare(to_image(f), ref).nmse; };
        scene::render_stats sl;
        scene::render_phong_scanline(r, &sl);
        const double pixels = double(sl.pixels), scanline = double(sl.total().long_ops()) / pixels;

        std::printf("# Components apart against their sum: %s %ux%u, device %s, n = %u, NMSE limit %.3g\n\n",
                    o.scene.c_str(), o.size, o.size, o.device.c_str(), k.n, o.nmse);
        std::printf("Scan-line Phong: %.2f long operations per pixel (%zu pixels).\n\n", scanline, sl.pixels);

        best b_sum, b_apart, b_spec;
        std::printf("## The sum (one plan, m <= %u): long operations as counted\n\n", o.m_max_sum);
        std::printf("| T | geometry points / px | NMSE | long ops / px | x scan-line |\n|---|---|---|---|---|\n");
        for (double t : o.tol_sum) {
            const part s = plan_part(r, k, dev, base, t, o.m_max_sum);
            const double cost = double(hardware_ops(s.p, s.c, dev, k.n).total().long_ops()) / pixels, e = nmse(s.g);
            std::printf("| %.2f | %.4f | %.3g | %.2f | %.2f |\n", t, s.p.geometry_points / pixels, e, cost, scanline / cost);
            b_sum.offer(cost, e, o.nmse, "T = " + fixed2(t));
        }

        std::vector<part> dif, spec;
        for (double t : o.tol_diffuse) dif.push_back(plan_part(r, kd, dev, base, t, o.m_max_diffuse));
        for (double t : o.tol_specular) spec.push_back(plan_part(r, ks, dev, base, t, o.m_max_specular));

        std::printf("\n## Apart (ambient + diffuse m <= %u, specular m <= %u): long operations at least\n\n",
                    o.m_max_diffuse, o.m_max_specular);
        std::printf("| T diffuse | T specular | diffuse-only points / px (at least) | NMSE | long ops / px (at least) | x scan-line (at most) |\n");
        std::printf("|---|---|---|---|---|---|\n");
        for (const part& d : dif)
            for (const part& s : spec) {
                const apart_cost c = apart_cost_bound(d.p, d.c, s.p, s.c, dev, k.n);
                const double cost = c.total() / pixels, e = nmse(add_saturated(d.g, s.g));
                std::printf("| %.2f | %.2f | %.4f | %.3g | %.2f | %.2f |\n", d.tol, s.tol, c.diffuse_only / pixels, e, cost,
                            scanline / cost);
                b_apart.offer(cost, e, o.nmse, "T diffuse = " + fixed2(d.tol) + ", T specular = " + fixed2(s.tol));
            }

        std::printf("\n## The specular plan alone, the diffuse exact for nothing: long operations at least\n\n");
        std::printf("| T specular | NMSE | long ops / px (at least) | x scan-line (at most) |\n|---|---|---|---|\n");
        for (const part& s : spec) {
            const double cost = apart_cost_bound(s.p, s.c, s.p, s.c, dev, k.n).specular / pixels,
                         e = nmse(add_saturated(pp_d, s.g));
            std::printf("| %.2f | %.3g | %.2f | %.2f |\n", s.tol, e, cost, scanline / cost);
            b_spec.offer(cost, e, o.nmse, "T specular = " + fixed2(s.tol));
        }

        std::printf("\n## The cheapest with NMSE <= %.3g\n\n", o.nmse);
        auto line = [scanline](const char* name, const best& b) {
            if (b.cost)
                std::printf("- %s: %.2f long ops / px, %.2fx the scan-line Phong (%s)\n", name, *b.cost, scanline / *b.cost,
                            b.what.c_str());
            else
                std::printf("- %s: none of the tolerances given meets the limit\n", name);
        };
        line("the sum (counted)", b_sum);
        line("apart (at least; ratio at most)", b_apart);
        line("the specular alone, diffuse free (at least; ratio at most)", b_spec);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "components_study: %s\n", e.what());
        return tb::exit_failure;
    }
    return tb::exit_success;
}
