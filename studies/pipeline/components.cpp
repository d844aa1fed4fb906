#include "components.h"

#include <algorithm>

namespace shading::study {

using namespace shading::pipeline;

frame_constants diffuse_part(const frame_constants& k) {
    frame_constants out = k;
    out.ksi = {0, 0, 0};
    return out;
}

frame_constants specular_part(const frame_constants& k) {
    frame_constants out = k;
    out.kdi = {0, 0, 0};
    out.ambient = {0, 0, 0};
    return out;
}

frame add_saturated(const frame& a, const frame& b) {
    frame out = a;
    for (std::size_t i = 0; i < out.px.size(); ++i)
        for (std::size_t ch = 0; ch < 3; ++ch) out.px[i][ch] = std::min<uint64_t>(a.px[i][ch] + b.px[i][ch], pixel_fmt.mask());
    return out;
}

std::vector<uint8_t> sample_pixels(const plan& p, interp::sample_set set) {
    std::vector<uint8_t> out(std::size_t(p.width) * p.height, 0);
    for (const interval_job& j : p.jobs) {
        std::vector<unsigned> eighths{0};
        if (j.m > 0)
            eighths = j.deg2 ? std::vector<unsigned>{0, 4, 8}
                      : set == interp::sample_set::case1 ? std::vector<unsigned>{0, 2, 4, 8}
                                                         : std::vector<unsigned>{0, 4, 6, 8};
        // A job shorter than 2^m (a fixed length near a segment's end) may name a t = 1 point past the
        // line; it marks no pixel of this frame.
        for (unsigned e : eighths)
            if (const unsigned x = j.x0 + e * (1u << j.m) / 8; x < p.width) out[std::size_t(j.y) * p.width + x] = 1;
    }
    return out;
}

std::size_t diffuse_only_points_bound(const plan& d, const std::vector<uint8_t>& sd, const plan& e,
                                      const std::vector<uint8_t>& se) {
    std::size_t nd = 0, ne = 0, both = 0;
    for (std::size_t i = 0; i < sd.size(); ++i) {
        nd += sd[i];
        ne += se[i];
        both += sd[i] && se[i];
    }
    const std::size_t xd = d.geometry_points - nd, xe = e.geometry_points - ne;
    const std::size_t taken = both + xd + xe;
    return d.geometry_points > taken ? d.geometry_points - taken : 0;
}

apart_cost apart_cost_bound(const plan& d, const plan_config& cd, const plan& e, const plan_config& ce,
                            const scene::device_config& dev, unsigned n) {
    const hardware_counts hd = hardware_ops(d, cd, dev, n), he = hardware_ops(e, ce, dev, n);
    apart_cost c;
    c.specular = double(he.total().long_ops()) - double(diffuse_colour_long) * double(he.samples + e.check_samples);
    c.diffuse_only = diffuse_only_points_bound(d, sample_pixels(d, cd.set), e, sample_pixels(e, ce.set));
    c.diffuse = double(diffuse_point_long_min) * double(c.diffuse_only) +
                double(diffuse_colour_long) * double(hd.samples + d.check_samples) + double(hd.interpolation.long_ops());
    return c;
}

}  // namespace shading::study
