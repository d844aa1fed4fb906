#include "scene/scanline.h"

#include <glm/glm.hpp>

namespace shading::scene {

namespace {
unsigned popcount(unsigned v) {
    unsigned ones = 0;
    for (; v; v >>= 1) ones += v & 1u;
    return ones;
}
}  // namespace

span_stepper::span_stepper(const rasterised& r, bool walk_edges) : r_(r), walk_(walk_edges), grad_(r.setups.size()) {
    const world& s = *r.src;
    perspective_ = !s.cam.orthographic();
    need_p_ = perspective_;
    for (const auto& l : s.lights) need_p_ = need_p_ || l.type == light::kind::point;
}

void span_stepper::setup(int32_t t, op_counts* ops) {
    gradients& g = grad_[static_cast<std::size_t>(t)];
    const triangle_setup& ts = r_.setups[static_cast<std::size_t>(t)];
    const mesh& m = r_.src->objects[ts.object].geometry;
    const auto& tri = m.triangles[ts.triangle];
    auto c = [ops](double v) { return cnum(v, ops); };
    // One plane coefficient of sum_i g_i A_i: 3 mul, 2 add.
    auto coef = [&](int k, const std::array<double, 3>& a) {
        return (c(ts.plane[0][k]) * c(a[0]) + c(ts.plane[1][k]) * c(a[1]) + c(ts.plane[2][k]) * c(a[2])).value();
    };
    auto plane_of = [&](const std::array<double, 3>& a) { return plane3{coef(0, a), coef(1, a), coef(2, a)}; };
    for (int comp = 0; comp < 3; ++comp) {
        g.n[comp] = plane_of({m.normals[tri[0]][comp], m.normals[tri[1]][comp], m.normals[tri[2]][comp]});
        if (need_p_)
            g.p[comp] = plane_of({m.positions[tri[0]][comp], m.positions[tri[1]][comp], m.positions[tri[2]][comp]});
    }
    if (perspective_) {
        // Q = sum_i g_i: the vertices' weights are 1, so only the sums (2 adds per coefficient).
        auto sum = [&](int k) { return (c(ts.plane[0][k]) + c(ts.plane[1][k]) + c(ts.plane[2][k])).value(); };
        g.q = {sum(0), sum(1), sum(2)};
    }
    g.ready = true;
    ++stats_.triangle_setups;
}

pixel_geometry span_stepper::at(unsigned x, unsigned y, op_counts* ops, bool down) {
    const int32_t t = r_.tri[r_.index(x, y)];
    if (stats_.points > 0 && !(y > y_ || (y == y_ && x > x_))) raster_ = false;
    if (!grad_[static_cast<std::size_t>(t)].ready) setup(t, ops);
    gradients& g = grad_[static_cast<std::size_t>(t)];
    auto c = [ops](double v) { return cnum(v, ops); };
    // Counted values start from the stored ones, charging `ops` from here on.
    auto rebind = [&c](cnum v) { return c(v.value()); };
    const bool across = t == tri_ && y == y_ && x > x_, below = down && t == tri_ && x == x_ && y > y_;
    if (across || below) {
        // Step d pixels right (+ d a per component) or d lines down (+ d b): a shift, or
        // shift-and-add, popcount(d) adds.
        const unsigned d = across ? x - x_ : y - y_;
        const unsigned ones = popcount(d);
        auto step = [&](cnum v, const plane3& pl) {
            if (ops) ops->add += ones - 1;
            return rebind(v) + c(d * (across ? pl.a : pl.b));
        };
        for (int k = 0; k < 3; ++k) {
            cnum* un = k == 0 ? &un_.x : k == 1 ? &un_.y : &un_.z;
            *un = step(*un, g.n[k]);
            if (need_p_) {
                cnum* up = k == 0 ? &up_.x : k == 1 ? &up_.y : &up_.z;
                *up = step(*up, g.p[k]);
            }
        }
        if (perspective_) q_ = step(q_, g.q);
        ++stats_.steps;
    } else if (walk_ && g.visited) {
        // Edge walking from the triangle's last point. In raster order a walker steps its live
        // triangles line by line: + (y - y') b is an add a line, + (x - x') a popcount(|x - x'|) adds
        // (a subtraction leftwards or upwards). Once the points leave raster order (the cells' bands
        // and levels) the walker jumps: each of (y - y') b and (x - x') a is a multiplication by a
        // small integer and an add.
        const int dy = int(y) - int(g.last_y);
        const unsigned lines = unsigned(dy < 0 ? -dy : dy);
        const int dx = int(x) - int(g.last_x);
        const unsigned ones = popcount(unsigned(dx < 0 ? -dx : dx));
        auto walk = [&](double v, const plane3& pl) {
            cnum out = c(v);
            if (dy != 0) {
                if (raster_) {
                    out = out + c(dy * pl.b);
                    if (ops) ops->add += lines - 1;
                } else {
                    out = out + c(double(dy)) * c(pl.b);
                }
            }
            if (dx != 0) {
                if (raster_) {
                    out = out + c(dx * pl.a);
                    if (ops) ops->add += ones - 1;
                } else {
                    out = out + c(double(dx)) * c(pl.a);
                }
            }
            return out;
        };
        un_ = {walk(g.last_un[0], g.n[0]), walk(g.last_un[1], g.n[1]), walk(g.last_un[2], g.n[2])};
        if (need_p_) up_ = {walk(g.last_up[0], g.p[0]), walk(g.last_up[1], g.p[1]), walk(g.last_up[2], g.p[2])};
        if (perspective_) q_ = walk(g.last_q, g.q);
        tri_ = t;
        ++stats_.run_starts;
        ++stats_.walked_starts;
    } else {
        // Run start: a x + b y + c at the pixel centre (2 mul, 2 add per component).
        const cnum px = c(x + 0.5), py = c(y + 0.5);
        auto eval = [&](const plane3& pl) { return c(pl.a) * px + c(pl.b) * py + c(pl.c); };
        un_ = {eval(g.n[0]), eval(g.n[1]), eval(g.n[2])};
        if (need_p_) up_ = {eval(g.p[0]), eval(g.p[1]), eval(g.p[2])};
        if (perspective_) q_ = eval(g.q);
        tri_ = t;
        ++stats_.run_starts;
    }
    x_ = x;
    y_ = y;
    ++stats_.points;
    if (walk_) {
        g.visited = true;
        g.last_x = x;
        g.last_y = y;
        g.last_q = q_.value();
        g.last_un = {un_.x.value(), un_.y.value(), un_.z.value()};
        g.last_up = {up_.x.value(), up_.y.value(), up_.z.value()};
    }

    auto rb = [&rebind](const cvec3& v) { return cvec3{rebind(v.x), rebind(v.y), rebind(v.z)}; };
    pixel_geometry out;
    out.object = r_.setups[static_cast<std::size_t>(t)].object;
    // U_N is Q times the perspective-correct normal: normalising removes Q, so no division here.
    out.n = normalize(rb(un_));
    if (perspective_) {
        // V and a point light's L from Q E - U_P = Q (E - P), Q > 0: the direction of E - P without
        // forming P = U_P / Q (3 mul, 3 add instead of a division and 3 mul). P's value is kept,
        // uncounted: no shading path reads it.
        const double inv_q = 1.0 / q_.value();
        out.p = {c(up_.x.value() * inv_q), c(up_.y.value() * inv_q), c(up_.z.value() * inv_q)};
        const cnum q = rebind(q_);
        const cvec3 up = rb(up_);
        auto towards = [&](const glm::dvec3& e) { return normalize(q * cvec3{c(e.x), c(e.y), c(e.z)} - up); };
        add_view_and_lights(r_, out, ops, towards);
    } else {
        if (need_p_) out.p = rb(up_);
        add_view_and_lights(r_, out, ops);  // V, L, H as the per-pixel geometry derives them
    }
    return out;
}

}  // namespace shading::scene
