#include "scene/fast_phong.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <string>

#include "scene/scene.h"

namespace shading::scene {

namespace {
constexpr double full_scale = 255.0;  // 8-bit image units

// A scaling by a power of two is a shift and |v| drops a sign: free in hardware, not counted.
cnum scaled(cnum v, double power_of_two) { return {v.value() * power_of_two, v.counts()}; }
cnum magnitude(cnum v) { return {std::abs(v.value()), v.counts()}; }
cnum smaller(cnum a, cnum b) { return b > a ? a : b; }  // one comparison

// A triangle's U_N screen gradients and their products, shared by all its parts.
struct gradient_terms {
    cvec3 ux, uy;
    cnum xx, xy, yy;  // u_x.u_x, u_x.u_y, u_y.u_y
};
gradient_terms products(const cvec3& ux, const cvec3& uy) { return {ux, uy, dot(ux, ux), dot(ux, uy), dot(uy, uy)}; }

// 1/|U| about the expansion point: r (1 - alpha x - beta y + g11 x^2 + g12 x y + g22 y^2 + g3(x, y)),
// r = 1/sqrt(q0). With U.U = q0 (1 + eps), eps = 2 alpha x + 2 beta y + c x^2 + 2 delta x y + e y^2
// (alpha = U0.u_x / q0, beta = U0.u_y / q0, c, delta, e the products over q0), and
// (1 + eps)^(-1/2) = 1 - eps/2 + 3 eps^2/8 - 5 eps^3/16 - ...
struct inverse_length {
    bool zero = false;
    cnum r, alpha, beta, g11, g12, g22;
    std::array<cnum, 4> g3;  // x^3, x^2 y, x y^2, y^3
};

inverse_length expand_inverse_length(const cvec3& u0, const gradient_terms& t, bool third) {
    inverse_length s;
    const cnum q0 = dot(u0, u0), s1 = dot(u0, t.ux), s2 = dot(u0, t.uy);
    if (!(q0.value() > 0.0)) {
        s.zero = true;  // the normals cancel at the expansion point: no direction to shade
        return s;
    }
    s.r = cnum(1.0, q0.counts()) / sqrt(q0);
    const cnum rr = s.r * s.r;  // 1/q0
    s.alpha = s1 * rr;
    s.beta = s2 * rr;
    const cnum c = t.xx * rr, delta = t.xy * rr, e = t.yy * rr;
    const cnum a2 = s.alpha * s.alpha, ab = s.alpha * s.beta, b2 = s.beta * s.beta;
    // -eps/2 + 3 eps^2/8 to second order: x^2: -c/2 + 3/2 alpha^2, x y: -delta + 3 alpha beta,
    // y^2: -e/2 + 3/2 beta^2 (3/2 v = v + v/2 and 3 v = v + 2 v: one add each).
    s.g11 = (a2 + scaled(a2, 0.5)) - scaled(c, 0.5);
    s.g12 = (ab + scaled(ab, 2.0)) - delta;
    s.g22 = (b2 + scaled(b2, 0.5)) - scaled(e, 0.5);
    if (third) {
        // Third order: 3/2 A - 5/2 B with A = (alpha x + beta y)(c x^2 + 2 delta x y + e y^2) (from
        // 3 eps^2/8) and B = (alpha x + beta y)^3 (from -5 eps^3/16).
        const std::array<cnum, 4> a{s.alpha * c, scaled(s.alpha * delta, 2.0) + s.beta * c,
                                    s.alpha * e + scaled(s.beta * delta, 2.0), s.beta * e};
        const cnum a2b = a2 * s.beta, ab2 = s.alpha * b2;
        const std::array<cnum, 4> b{a2 * s.alpha, a2b + scaled(a2b, 2.0), ab2 + scaled(ab2, 2.0), b2 * s.beta};
        for (int k = 0; k < 4; ++k) s.g3[k] = (a[k] + scaled(a[k], 0.5)) - (scaled(b[k], 2.0) + scaled(b[k], 0.5));
    }
    return s;
}

// A.U / |U| = (p0 + p1 x + p2 y) / |U|, with P = r p (so r is multiplied in once per p, not per term).
expansion expand_one(const inverse_length& s, const cvec3& a, const cvec3& u0, const gradient_terms& t, bool third) {
    const cnum p0 = dot(a, u0), p1 = dot(a, t.ux), p2 = dot(a, t.uy);
    expansion out;
    if (s.zero) return out;
    const cnum P0 = s.r * p0, P1 = s.r * p1, P2 = s.r * p2;
    out.q.t0 = P0.value();
    out.q.t2 = (P1 - P0 * s.alpha).value();
    out.q.t1 = (P2 - P0 * s.beta).value();
    out.q.t5 = (P0 * s.g11 - P1 * s.alpha).value();
    out.q.t4 = (P0 * s.g12 - P1 * s.beta - P2 * s.alpha).value();
    out.q.t3 = (P0 * s.g22 - P2 * s.beta).value();
    if (third) {
        // p0 g3 + (p1 x + p2 y)(g11 x^2 + g12 x y + g22 y^2), times r.
        out.third = {(P0 * s.g3[0] + P1 * s.g11).value(), (P0 * s.g3[1] + P1 * s.g12 + P2 * s.g11).value(),
                     (P0 * s.g3[2] + P1 * s.g22 + P2 * s.g12).value(), (P0 * s.g3[3] + P2 * s.g22).value()};
    }
    return out;
}

// One expression stepped along a run: the value F and its first difference D (D2 = 2 T5 a shift).
struct runner {
    cnum f, d, d2;
};
// Horner's rule and the first difference F(x + 1) - F(x) = 2 T5 x + T5 + T4 y + T2 = t + T5 x + T5,
// t = T5 x + T4 y + T2 shared with F: 5 mul, 7 add.
runner start_run(const quadratic& q, cnum dx, cnum dy) {
    op_counts* ops = dx.counts();
    auto c = [ops](double v) { return cnum(v, ops); };
    const cnum t5dx = c(q.t5) * dx;
    const cnum t = t5dx + c(q.t4) * dy + c(q.t2);
    const cnum f = t * dx + (c(q.t3) * dy + c(q.t1)) * dy + c(q.t0);
    return {f, t + t5dx + c(q.t5), scaled(c(q.t5), 2.0)};
}
void step_run(runner& s, op_counts* ops) {
    const cnum d(s.d.value(), ops);
    s.f = cnum(s.f.value(), ops) + d;
    s.d = d + cnum(s.d2.value(), ops);
}

struct cpoint {
    cnum x, y;
};
// A part's vertex: screen x, y and, where the set-up needs positions, its world position and 1/w.
struct cvertex {
    cnum x, y;
    cvec3 p;
    cnum q;
};
// What the set-up derives at a part's centroid: P, per light L then H, and the inverse lengths it
// normalised by (1/|eye - P|, per light 1/|light - P| and 1/|L + V|), which the estimate reuses.
struct centroid_frame {
    cvec3 p;
    std::vector<cvec3> dirs;
    cnum inv_eye;
    std::vector<cnum> inv_light, inv_half;
};
}  // namespace

std::vector<expansion> expand_normalised(const cvec3& u0, const cvec3& ux, const cvec3& uy,
                                         const std::vector<cvec3>& dirs, bool third_order) {
    const gradient_terms t = products(ux, uy);
    const inverse_length s = expand_inverse_length(u0, t, third_order);
    std::vector<expansion> out;
    for (const cvec3& a : dirs) out.push_back(expand_one(s, a, u0, t, third_order));
    return out;
}

std::vector<double> forward_differences(const quadratic& q, double dx0, double dy, unsigned count, op_counts* ops) {
    std::vector<double> out;
    if (count == 0) return out;
    runner s = start_run(q, cnum(dx0, ops), cnum(dy, ops));
    out.push_back(s.f.value());
    for (unsigned i = 1; i < count; ++i) {
        step_run(s, ops);
        out.push_back(s.f.value());
    }
    return out;
}

std::size_t power_table::index(double s) const {
    const std::size_t last = entry.size() - 1;
    if (!(s > 0.0)) return 0;
    if (s >= 1.0) return last;
    return std::min(last, static_cast<std::size_t>(s * static_cast<double>(entry.size())));  // the top bits
}

power_table make_power_table(unsigned n, unsigned bits, op_counts* ops) {
    if (bits < 1 || bits > 16)
        throw scene_error("fast Phong: table_bits must be 1..16 (a table of 2..65536 entries), not " +
                          std::to_string(bits));
    power_table t;
    t.n = n;
    t.bits = bits;
    const std::size_t size = std::size_t{1} << bits;
    t.entry.resize(size);
    for (std::size_t i = 0; i < size; ++i) {
        const double mid = (static_cast<double>(i) + 0.5) / static_cast<double>(size);  // the bin's middle
        const double v = pow_int(cnum(mid, ops), n).value();
        t.entry[i] = static_cast<uint16_t>(std::lround(std::clamp(v, 0.0, 1.0) * 65535.0));
    }
    return t;
}

namespace {

// A triangle or one of its sub-triangles: screen vertices, expansion point, one quadratic per
// expression (per light: the diffuse L.N/|N|, then the specular argument H.N/|N|), children if split.
struct part {
    std::array<glm::dvec2, 3> v;
    double xc = 0.0, yc = 0.0;
    std::vector<quadratic> expr;
    std::array<int, 4> child{-1, -1, -1, -1};  // corners 0, 1, 2, middle
};

class fast_phong_renderer {
public:
    fast_phong_renderer(const rasterised& r, const device_config& dev, const fast_phong_config& c,
                        fast_phong_stats& fs)
        : r_(r), dev_(dev), cfg_(c), fs_(fs), parts_(r.setups.size()) {
        const world& s = *r.src;
        perspective_ = !s.cam.orthographic();
        need_p_ = perspective_;
        for (const auto& l : s.lights) need_p_ = need_p_ || l.type == light::kind::point;
    }
    void build_tables(op_counts* ops);
    shaded_image render(render_stats& st);

private:
    void setup_triangle(int32_t t);
    int build_part(const triangle_setup& ts, const gradient_terms& grads, const std::array<cvertex, 3>& v,
                   unsigned depth, std::vector<part>& nodes);
    cvertex midpoint(const cvertex& a, const cvertex& b);
    centroid_frame directions(const triangle_setup& ts, const std::array<cnum, 3>& g);
    cnum error_estimate(const part& p, const material& m, const std::vector<expansion>& e, const centroid_frame& f,
                        const std::array<cvertex, 3>& v);
    cnum held_directions(const centroid_frame& f, const std::array<cvertex, 3>& v, std::vector<cnum>& dl,
                         std::vector<cnum>& dh);
    rgb shade(const material& m, const std::vector<runner>& run, op_counts* ops);

    const rasterised& r_;
    const device_config& dev_;
    const fast_phong_config& cfg_;
    fast_phong_stats& fs_;
    bool perspective_ = false, need_p_ = false;
    std::vector<std::vector<part>> parts_;  // per set-up triangle; empty until it is set up
    std::map<unsigned, power_table> tables_;
};

void fast_phong_renderer::build_tables(op_counts* ops) {
    if (cfg_.power != specular_path::table) return;
    for (const auto& o : r_.src->objects)
        if (!tables_.count(o.mat.n)) tables_.emplace(o.mat.n, make_power_table(o.mat.n, cfg_.table_bits, ops));
}

// Per light: L, then H = normalize(L + V), at the part's centroid (g: the planes g_i there).
centroid_frame fast_phong_renderer::directions(const triangle_setup& ts, const std::array<cnum, 3>& g) {
    op_counts* ops = &fs_.setup;
    auto c = [ops](double v) { return cnum(v, ops); };
    auto cv = [&c](const glm::dvec3& v) { return cvec3{c(v.x), c(v.y), c(v.z)}; };
    // normalize(a) (counted as counted.h's: 3 mul, 2 add, sqrt, div, 3 mul), keeping 1/|a|.
    auto unit = [](const cvec3& a, cnum& inv) {
        inv = cnum(1.0, a.x.counts()) / sqrt(dot(a, a));
        return inv * a;
    };
    const world& s = *r_.src;
    const mesh& m = s.objects[ts.object].geometry;
    const auto& tri = m.triangles[ts.triangle];
    centroid_frame f;
    if (need_p_) {
        // The perspective-correct position at the centroid: b_i = g_i / sum g, P = sum b_i P_i.
        const cnum inv = c(1.0) / (g[0] + g[1] + g[2]);
        f.p = (g[0] * inv) * cv(m.positions[tri[0]]) + (g[1] * inv) * cv(m.positions[tri[1]]) +
              (g[2] * inv) * cv(m.positions[tri[2]]);
    }
    // An orthographic V and a directional L are frame constants (uncounted), and so is H when both are;
    // H is counted when either carries counts.
    auto frame = [](const glm::dvec3& v) { return cvec3{cnum(v.x, nullptr), cnum(v.y, nullptr), cnum(v.z, nullptr)}; };
    const cvec3 v = perspective_ ? unit(cv(r_.eye) - f.p, f.inv_eye) : frame(r_.view_dir);
    for (const auto& l : s.lights) {
        cnum inv_l, inv_h;
        const cvec3 lv =
            l.type == light::kind::point ? unit(cv(l.vector) - f.p, inv_l) : frame(glm::normalize(l.vector));
        f.dirs.push_back(lv);
        f.dirs.push_back(unit(lv + v, inv_h));
        f.inv_light.push_back(inv_l);
        f.inv_half.push_back(inv_h);
    }
    return f;
}

// How far the held L and H stray at the part's vertices, to first order: a direction to a point
// at distance D turns by at most |P_v - P_c| / D, so |dV| <= d / |eye - P_c|, |dL| <= d / |light - P_c|
// (d = max_v |P_v - P_c|), and H = (L + V)/|L + V| by at most (|dV| + |dL|) / |L + V|. Per light in
// dl and dh; zero where V and L are constant.
cnum fast_phong_renderer::held_directions(const centroid_frame& f, const std::array<cvertex, 3>& v,
                                          std::vector<cnum>& dl, std::vector<cnum>& dh) {
    op_counts* ops = &fs_.setup;
    const cnum zero(0.0, ops);
    const auto& lights = r_.src->lights;
    dl.assign(lights.size(), zero);
    dh.assign(lights.size(), zero);
    if (!need_p_) return zero;
    cnum d2 = zero;
    for (int i = 0; i < 3; ++i) {
        const cvec3 dp = v[i].p - f.p;
        d2 = i == 0 ? dot(dp, dp) : max(d2, dot(dp, dp));
    }
    const cnum d = sqrt(d2);
    const cnum dv = perspective_ ? d * f.inv_eye : zero;
    for (std::size_t li = 0; li < lights.size(); ++li) {
        const bool point = lights[li].type == light::kind::point;
        if (point) dl[li] = d * f.inv_light[li];
        dh[li] = (point ? dv + dl[li] : dv) * f.inv_half[li];
    }
    return d;
}

// The error estimate, in 8-bit levels after lighting, per light: 255 max_c(k_d I) (D + |dL|) +
// 255 max_c(k_s I) n s^(n-1) (S + |dH|), with D and S the largest |third-order term| of the diffuse
// and specular expressions at the part's vertices and edge midpoints (its farthest points from the
// centroid: a homogeneous cubic grows as the cube of the distance along each ray), dL and dH the
// held directions' stray (held_directions), s the largest expanded N.H at those points and the
// centroid (clamped to [0, 1]): the slope of s^n there.
cnum fast_phong_renderer::error_estimate(const part& p, const material& m, const std::vector<expansion>& e,
                                         const centroid_frame& f, const std::array<cvertex, 3>& v) {
    op_counts* ops = &fs_.setup;
    auto c = [ops](double v) { return cnum(v, ops); };
    // Offsets from the centroid: the vertices' (2 add each), the midpoints' (2 add each and a shift).
    std::array<cpoint, 6> at;
    for (int i = 0; i < 3; ++i) at[static_cast<std::size_t>(i)] = {c(p.v[i].x) - c(p.xc), c(p.v[i].y) - c(p.yc)};
    for (int i = 0; i < 3; ++i) {
        const cpoint& a = at[static_cast<std::size_t>(i)];
        const cpoint& b = at[static_cast<std::size_t>((i + 1) % 3)];
        at[static_cast<std::size_t>(3 + i)] = {scaled(a.x + b.x, 0.5), scaled(a.y + b.y, 0.5)};
    }
    std::array<cnum, 6> y2, y3;
    for (std::size_t k = 0; k < 6; ++k) {
        y2[k] = at[k].y * at[k].y;
        y3[k] = y2[k] * at[k].y;
    }
    // The largest |c0 x^3 + c1 x^2 y + c2 x y^2 + c3 y^3| = |((c0 x + c1 y) x + c2 y^2) x + c3 y^3|
    // over the six points: 6 mul, 3 add a point.
    auto cubic = [&](const std::array<double, 4>& k) {
        cnum worst = c(0.0);
        for (std::size_t i = 0; i < 6; ++i) {
            const cpoint& pt = at[i];
            const cnum v = ((c(k[0]) * pt.x + c(k[1]) * pt.y) * pt.x + c(k[2]) * y2[i]) * pt.x + c(k[3]) * y3[i];
            worst = i == 0 ? magnitude(v) : max(worst, magnitude(v));
        }
        return worst;
    };
    std::vector<cnum> dl, dh;
    held_directions(f, v, dl, dh);
    const auto& lights = r_.src->lights;
    cnum total = c(0.0);
    for (std::size_t li = 0; li < lights.size(); ++li) {
        // Frame constants: the largest channel's 255 k_d I and 255 k_s I.
        const rgb kdi = full_scale * m.k_d * lights[li].intensity, ksi = full_scale * m.k_s * lights[li].intensity;
        const quadratic& q = e[2 * li + 1].q;
        cnum s = c(q.t0);
        for (const cpoint& pt : at)  // Horner's rule: 5 mul, 5 add a point
            s = max(s, (c(q.t5) * pt.x + c(q.t4) * pt.y + c(q.t2)) * pt.x + (c(q.t3) * pt.y + c(q.t1)) * pt.y +
                           c(q.t0));
        s = smaller(max(s, c(0.0)), c(1.0));
        const cnum slope = m.n > 1 ? c(double(m.n)) * pow_int(s, m.n - 1) : c(1.0);
        total = total + c(std::max({kdi.x, kdi.y, kdi.z})) * (cubic(e[2 * li].third) + dl[li]) +
                c(std::max({ksi.x, ksi.y, ksi.z})) * slope * (cubic(e[2 * li + 1].third) + dh[li]);
    }
    return total;
}

// An edge's screen midpoint: an add per coordinate and a shift. Where positions are needed, its world
// point, perspective-correct: P = (q_a P_a + q_b P_b) / (q_a + q_b) (6 mul, 4 add, div, 3 mul) and
// 1/w there, (q_a + q_b) / 2.
cvertex fast_phong_renderer::midpoint(const cvertex& a, const cvertex& b) {
    cvertex m{scaled(a.x + b.x, 0.5), scaled(a.y + b.y, 0.5), {}, {}};
    if (!need_p_) return m;
    const cnum sum = a.q + b.q;
    m.p = (cnum(1.0, sum.counts()) / sum) * (a.q * a.p + b.q * b.p);
    m.q = scaled(sum, 0.5);
    return m;
}

// One part's set-up (counted), judged against the budget and split through its edge midpoints when
// it misses; returns its index in `nodes`.
int fast_phong_renderer::build_part(const triangle_setup& ts, const gradient_terms& grads,
                                    const std::array<cvertex, 3>& v, unsigned depth, std::vector<part>& nodes) {
    op_counts* ops = &fs_.setup;
    auto c = [ops](double x) { return cnum(x, ops); };
    const int index = static_cast<int>(nodes.size());
    nodes.emplace_back();
    ++fs_.setups;
    part p;
    for (int i = 0; i < 3; ++i) p.v[i] = {v[i].x.value(), v[i].y.value()};
    const cnum third = c(1.0 / 3.0);
    const cnum xc = (v[0].x + v[1].x + v[2].x) * third, yc = (v[0].y + v[1].y + v[2].y) * third;
    p.xc = xc.value();
    p.yc = yc.value();
    // U_N at the centroid: the planes g_i there and sum g_i N_i.
    const mesh& m = r_.src->objects[ts.object].geometry;
    const auto& tri = m.triangles[ts.triangle];
    std::array<cnum, 3> g;
    for (int i = 0; i < 3; ++i) g[i] = c(ts.plane[i].x) * xc + c(ts.plane[i].y) * yc + c(ts.plane[i].z);
    auto cv = [&c](const glm::dvec3& x) { return cvec3{c(x.x), c(x.y), c(x.z)}; };
    const cvec3 u0 = g[0] * cv(m.normals[tri[0]]) + g[1] * cv(m.normals[tri[1]]) + g[2] * cv(m.normals[tri[2]]);
    const centroid_frame f = directions(ts, g);
    const bool judge = cfg_.budget > 0.0 && depth < cfg_.max_depth;
    const inverse_length s = expand_inverse_length(u0, grads, judge);
    std::vector<expansion> e;
    for (const cvec3& a : f.dirs) {
        e.push_back(expand_one(s, a, u0, grads, judge));
        p.expr.push_back(e.back().q);
    }
    const material& mat = r_.src->objects[ts.object].mat;
    const bool split = judge && error_estimate(p, mat, e, f, v) > c(cfg_.budget);
    nodes[static_cast<std::size_t>(index)] = p;
    if (!split) {
        ++fs_.parts;
        return index;
    }
    const cvertex m01 = midpoint(v[0], v[1]), m12 = midpoint(v[1], v[2]), m02 = midpoint(v[0], v[2]);
    const std::array<std::array<cvertex, 3>, 4> kids{
        {{v[0], m01, m02}, {m01, v[1], m12}, {m02, m12, v[2]}, {m12, m02, m01}}};
    for (int k = 0; k < 4; ++k) {
        const int child = build_part(ts, grads, kids[static_cast<std::size_t>(k)], depth + 1, nodes);
        nodes[static_cast<std::size_t>(index)].child[static_cast<std::size_t>(k)] = child;
    }
    return index;
}

void fast_phong_renderer::setup_triangle(int32_t t) {
    const triangle_setup& ts = r_.setups[static_cast<std::size_t>(t)];
    const mesh& m = r_.src->objects[ts.object].geometry;
    const auto& tri = m.triangles[ts.triangle];
    op_counts* ops = &fs_.setup;
    auto c = [ops](double v) { return cnum(v, ops); };
    // U_N = sum g_i N_i: its gradients sum a_i N_i and sum b_i N_i (3 mul, 2 add per component each).
    auto grad = [&](int k) {
        cvec3 u{};
        for (int i = 0; i < 3; ++i) {
            const cvec3 n{c(m.normals[tri[i]].x), c(m.normals[tri[i]].y), c(m.normals[tri[i]].z)};
            const cvec3 term = c(ts.plane[i][k]) * n;
            u = i == 0 ? term : u + term;
        }
        return u;
    };
    const gradient_terms grads = products(grad(0), grad(1));
    // The rasteriser's screen vertices, vertex i where g_j = g_k = 0, and 1/w there, g_i (uncounted,
    // the rasteriser's); the world positions are the mesh's.
    std::array<cvertex, 3> v;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3 h = glm::cross(ts.plane[(i + 1) % 3], ts.plane[(i + 2) % 3]);
        const glm::dvec3 at(h.x / h.z, h.y / h.z, 1.0);
        const glm::dvec3& pos = m.positions[tri[i]];
        v[i] = {c(at.x), c(at.y), {c(pos.x), c(pos.y), c(pos.z)}, c(glm::dot(ts.plane[i], at))};
    }
    std::vector<part>& nodes = parts_[static_cast<std::size_t>(t)];
    const std::size_t leaves_before = fs_.parts;
    build_part(ts, grads, v, 0, nodes);
    ++fs_.triangles;
    const std::size_t leaves = fs_.parts - leaves_before;
    if (leaves > 1) ++fs_.split_triangles;
    fs_.max_parts = std::max(fs_.max_parts, leaves);
}

// The leaf part holding the screen point: at each split, the corner whose screen barycentric is at
// least 1/2, else the middle (the rasteriser's coverage of the parts, uncounted).
int leaf_of(const std::vector<part>& nodes, double px, double py) {
    int i = 0;
    while (nodes[static_cast<std::size_t>(i)].child[0] >= 0) {
        const part& p = nodes[static_cast<std::size_t>(i)];
        auto cross = [](glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; };
        const glm::dvec2 q(px, py);
        const double area = cross(p.v[1] - p.v[0], p.v[2] - p.v[0]);
        const double l0 = cross(p.v[1] - q, p.v[2] - q) / area, l1 = cross(p.v[2] - q, p.v[0] - q) / area;
        const int k = l0 >= 0.5 ? 0 : l1 >= 0.5 ? 1 : (1.0 - l0 - l1) >= 0.5 ? 2 : 3;
        i = p.child[static_cast<std::size_t>(k)];
    }
    return i;
}

// shade.h's lighting on the stepped expressions: d = run[2 li], s = run[2 li + 1].
rgb fast_phong_renderer::shade(const material& m, const std::vector<runner>& run, op_counts* ops) {
    auto c = [ops](double v) { return cnum(v, ops); };
    const cnum zero = c(0.0);
    const auto& lights = r_.src->lights;
    std::array<cnum, 3> acc{c(full_scale * m.ambient.x), c(full_scale * m.ambient.y), c(full_scale * m.ambient.z)};
    for (std::size_t li = 0; li < lights.size(); ++li) {
        const cnum d = c(run[2 * li].f.value());
        if (!(d > zero)) continue;
        const cnum s = max(c(run[2 * li + 1].f.value()), zero);
        std::array<cnum, 3> spec;
        if (cfg_.power == specular_path::device) {
            const rgb ks_i = m.k_s * lights[li].intensity;  // frame constants: the device's 8-bit codes
            const std::array<uint64_t, 3> ksi{ksi_code(ks_i.x), ksi_code(ks_i.y), ksi_code(ks_i.z)};
            const auto out = device_specular(dev_, m.n, cos_code(s.value()), ksi);
            if (ops) *ops += device_sample_ops(dev_, m.n);  // the device's multipliers and adders
            for (int ch = 0; ch < 3; ++ch) spec[ch] = c(device_out_value(out[ch]));
        } else {
            const cnum power = c(tables_.at(m.n).value(s.value()));
            ++fs_.lookups;
            const rgb ksi = full_scale * m.k_s * lights[li].intensity;  // frame constant
            for (int ch = 0; ch < 3; ++ch) spec[ch] = c(ksi[ch]) * power;
        }
        const rgb kdi = full_scale * m.k_d * lights[li].intensity;  // frame constant
        for (int ch = 0; ch < 3; ++ch) acc[ch] = acc[ch] + c(kdi[ch]) * d + spec[ch];
    }
    return glm::clamp(rgb(acc[0].value(), acc[1].value(), acc[2].value()), rgb(0.0), rgb(full_scale));
}

shaded_image fast_phong_renderer::render(render_stats& st) {
    shaded_image img;
    img.width = r_.width;
    img.height = r_.height;
    img.value.assign(static_cast<std::size_t>(r_.width) * r_.height, rgb(0.0));
    img.covered.assign(img.value.size(), 0);
    const std::size_t exprs = 2 * r_.src->lights.size();
    std::vector<runner> run(exprs);
    for (unsigned y = 0; y < r_.height; ++y) {
        int32_t cur_t = -1;
        int cur_part = -1;
        unsigned cur_x = 0;
        for (const span& sp : line_spans(r_, y))
            for (unsigned x = sp.x_begin; x < sp.x_end; ++x) {
                const int32_t t = r_.tri[r_.index(x, y)];
                std::vector<part>& nodes = parts_[static_cast<std::size_t>(t)];
                if (nodes.empty()) setup_triangle(t);
                const int leaf = leaf_of(nodes, x + 0.5, y + 0.5);
                const part& p = nodes[static_cast<std::size_t>(leaf)];
                if (t == cur_t && leaf == cur_part && x == cur_x + 1) {
                    for (runner& s : run) step_run(s, &fs_.step);
                    ++fs_.steps;
                } else {
                    op_counts* ops = &fs_.run_start;
                    const cnum dx = cnum(x + 0.5, ops) - cnum(p.xc, ops), dy = cnum(y + 0.5, ops) - cnum(p.yc, ops);
                    for (std::size_t k = 0; k < exprs; ++k) run[k] = start_run(p.expr[k], dx, dy);
                    ++fs_.run_starts;
                }
                cur_t = t;
                cur_part = leaf;
                cur_x = x;
                const uint32_t object = r_.setups[static_cast<std::size_t>(t)].object;
                const std::size_t i = r_.index(x, y);
                img.value[i] = shade(r_.src->objects[object].mat, run, &st.shading);
                img.covered[i] = 1;
                ++st.pixels;
            }
    }
    return img;
}

void validate_config(const fast_phong_config& c) {
    if (c.table_bits < 1 || c.table_bits > 16)
        throw scene_error("fast Phong: table_bits must be 1..16 (a table of 2..65536 entries), not " +
                          std::to_string(c.table_bits));
    if (!(c.budget >= 0.0) || !std::isfinite(c.budget))
        throw scene_error("fast Phong: the error budget must be a finite number of 8-bit levels >= 0 (0: no split), "
                          "not " +
                          std::to_string(c.budget));
    if (c.max_depth > 8)
        throw scene_error("fast Phong: max_depth must be 0..8 (up to 4^8 parts a triangle), not " +
                          std::to_string(c.max_depth));
}
}  // namespace

shaded_image render_fast_phong(const rasterised& r, const device_config& dev, const fast_phong_config& c,
                               render_stats* stats, scheme_state* state, fast_phong_stats* fs) {
    validate_config(c);
    const auto t0 = std::chrono::steady_clock::now();
    fast_phong_stats f;
    render_stats st;
    fast_phong_renderer renderer(r, dev, c, f);
    renderer.build_tables(&f.table_build);
    shaded_image img = renderer.render(st);
    st.geometry = f.setup;
    st.geometry += f.run_start;
    st.geometry += f.step;
    st.shading += f.table_build;
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (state) {
        *state = {};
        const unsigned exprs = 2 * static_cast<unsigned>(r.src->lights.size());
        // Per part: the expansion point, 6 coefficients and the stepped (F, D) per expression; a live
        // triangle holds all its parts.
        state->per_triangle_words = (2 + 8 * exprs) * static_cast<unsigned>(std::max<std::size_t>(f.max_parts, 1));
        if (c.power == specular_path::table) {
            std::map<unsigned, bool> seen;  // one table per exponent
            for (const auto& o : r.src->objects) {
                if (seen[o.mat.n]) continue;
                seen[o.mat.n] = true;
                state->fixed.push_back(
                    {"specular power table, n = " + std::to_string(o.mat.n), uint64_t{1} << c.table_bits, 16});
            }
        }
    }
    if (stats) *stats = st;
    if (fs) *fs = f;
    return img;
}

}  // namespace shading::scene
