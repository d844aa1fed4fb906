// The scene side (src/scene): OBJ loading, the scan-line rasteriser, the per-pixel references and
// their operation counts, against file facts, hand-worked pixels and the golden models called
// directly. No simulation here: these tests may share a process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "arith/specular_arith.h"
#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "arith/ua22802_arith.h"
#include "arith/ua60553_tuned_arith.h"
#include "scene/image.h"
#include "scene/raster.h"
#include "scene/scene.h"
#include "scene/shade.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_scene {

using namespace shading;
using namespace shading::scene;

namespace {
std::string head_path() { return std::string(SHADING_SOURCE_DIR) + "/" + head_obj_relpath; }

std::string write_temp(const std::string& name, const std::string& text) {
    const std::string path = ::testing::TempDir() + "shading_scene_" + name;
    std::ofstream(path) << text;
    return path;
}

// The error's message must name the file and contain `problem`.
void expect_obj_error(const std::string& path, const std::string& problem) {
    try {
        load_obj(path);
        ADD_FAILURE() << "no error for " << path;
    } catch (const obj_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path), std::string::npos) << what;
        EXPECT_NE(what.find(problem), std::string::npos) << what;
        EXPECT_EQ(e.path(), path);
    }
}

// An 8x8 orthographic camera one world unit per pixel: screen (sx, sy) = (X + 4, 4 - Y), depth 10 - Z.
camera ortho8() {
    camera c;
    c.position = {0.0, 0.0, 10.0};
    c.target = {0.0, 0.0, 0.0};
    c.fov_y_deg = 0.0;
    c.ortho_height = 8.0;
    c.width = c.height = 8;
    return c;
}

glm::dvec3 world_of_screen(double sx, double sy, double z) { return {sx - 4.0, 4.0 - sy, z}; }

// A mesh of screen-space triangles at depth 10 - z, normals +z.
object screen_object(const std::string& name, const std::vector<std::array<glm::dvec2, 3>>& tris, double z) {
    object o{name, mesh{}, material{}};
    for (const auto& t : tris) {
        const auto base = static_cast<uint32_t>(o.geometry.positions.size());
        for (const auto& p : t) {
            o.geometry.positions.push_back(world_of_screen(p.x, p.y, z));
            o.geometry.normals.push_back({0.0, 0.0, 1.0});
        }
        o.geometry.triangles.push_back({base, base + 1, base + 2});
    }
    return o;
}

world ortho_scene(std::vector<object> objects) {
    world s;
    s.name = "test";
    s.cam = ortho8();
    s.lights.push_back({});
    s.objects = std::move(objects);
    return s;
}

// The hand-worked pixel: N = +z, L = (0, 0.6, 0.8), V = +z, so H = (0, 0.6, 1.8)/sqrt(3.6),
// N.L = 0.8, (N.H)^2 = 3.24/3.6 = 0.9 exactly.
pixel_geometry hand_pixel(op_counts* ops) {
    auto c = [ops](double v) { return cnum(v, ops); };
    pixel_geometry g;
    g.n = {c(0.0), c(0.0), c(1.0)};
    g.v = {c(0.0), c(0.0), c(1.0)};
    g.l.push_back({c(0.0), c(0.6), c(0.8)});
    const double k = 1.0 / std::sqrt(3.6);
    g.h.push_back({c(0.0), c(0.6 * k), c(1.8 * k)});
    return g;
}

material hand_material() {
    material m;
    m.ambient = {0.1, 0.1, 0.1};
    m.k_d = {0.5, 0.4, 0.3};
    m.k_s = {0.2, 0.2, 0.2};
    m.n = 4;
    return m;
}
}  // namespace

// ---- OBJ loading -------------------------------------------------------------------------------

// The head scan's facts (data/head/README.md): 8 844 vertices, 8 842 quads, no normals.
TEST(SceneObj, HeadScanCountsAndNormals) {
    const mesh m = load_obj(head_path());
    EXPECT_EQ(m.positions.size(), 8844u);
    EXPECT_EQ(m.file_faces, 8842u);
    EXPECT_EQ(m.file_quads, 8842u);
    EXPECT_EQ(m.triangles.size(), 17684u);
    EXPECT_FALSE(m.file_had_normals);
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (const auto& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
    // The face looks along +z: the nose tip (largest z) has a normal pointing forwards.
    std::size_t tip = 0;
    for (std::size_t i = 1; i < m.positions.size(); ++i)
        if (m.positions[i].z > m.positions[tip].z) tip = i;
    EXPECT_GT(m.normals[tip].z, 0.5);
}

// A unit square in the z = 0 plane, counter-clockwise seen from +z: two triangles, normals +z,
// whichever weighting.
TEST(SceneObj, TinyQuadHasKnownNormal) {
    const std::string path = write_temp("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    for (auto w : {normal_weighting::area, normal_weighting::angle}) {
        const mesh m = load_obj(path, w);
        ASSERT_EQ(m.triangles.size(), 2u);
        EXPECT_EQ(m.file_quads, 1u);
        for (const auto& n : m.normals) {
            EXPECT_NEAR(n.x, 0.0, 1e-15);
            EXPECT_NEAR(n.y, 0.0, 1e-15);
            EXPECT_NEAR(n.z, 1.0, 1e-15);
        }
    }
}

// Two faces folded at a right angle along the edge x = z = 0 (one in z = 0 facing +z, one in x = 0
// facing +x): each ridge vertex has the same angle in both (90 degrees at the origin, 45 at (0,1,0))
// and the faces have the same area, so with either weighting its normal is (1, 0, 1)/sqrt(2).
TEST(SceneObj, RidgeNormalBisects) {
    const std::string path =
        write_temp("ridge.obj", "v 0 0 0\nv 0 1 0\nv -1 0 0\nv 0 0 -1\nf 1 2 3\nf 1 4 2\n");
    for (auto w : {normal_weighting::area, normal_weighting::angle}) {
        const mesh m = load_obj(path, w);
        for (int v : {0, 1}) {
            EXPECT_NEAR(m.normals[v].x, std::sqrt(0.5), 1e-12) << v;
            EXPECT_NEAR(m.normals[v].y, 0.0, 1e-12);
            EXPECT_NEAR(m.normals[v].z, std::sqrt(0.5), 1e-12);
        }
    }
}

// The same ridge drawn near the largest and the smallest doubles: its normals are the hand-worked
// (1, 0, 1)/sqrt(2) still (cross products of 1e200 coordinates overflow, of 1e-200 ones underflow to
// a degenerate face, unless the loader scales them). File normals of such a length are unit too.
TEST(SceneObj, NormalsDoNotDependOnTheModelsScale) {
    for (const std::string s : {"1e200", "1e-200", "3"}) {
        const std::string path = write_temp("ridge_" + s + ".obj", "v 0 0 0\nv 0 " + s + " 0\nv -" + s + " 0 0\nv 0 0 -" +
                                                                       s + "\nf 1 2 3\nf 1 4 2\n");
        for (auto w : {normal_weighting::area, normal_weighting::angle}) {
            const mesh m = load_obj(path, w);
            for (int v : {0, 1}) {
                EXPECT_NEAR(m.normals[v].x, std::sqrt(0.5), 1e-12) << s << " vertex " << v;
                EXPECT_NEAR(m.normals[v].y, 0.0, 1e-12) << s;
                EXPECT_NEAR(m.normals[v].z, std::sqrt(0.5), 1e-12) << s;
            }
        }
    }
    for (const std::string vn : {"0 6e250 8e250", "0 6e-250 8e-250"}) {
        const mesh m = load_obj(write_temp("vn_scale.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn " + vn + "\nf 1//1 2//1 3//1\n"));
        for (const auto& n : m.normals) EXPECT_NEAR(glm::length(n - glm::dvec3(0.0, 0.6, 0.8)), 0.0, 1e-12) << vn;
    }
}

// Normals given in the file are used (not recomputed from the faces).
TEST(SceneObj, FileNormalsAreUsed) {
    const std::string path =
        write_temp("vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0.6 0.8\nf 1//1 2//1 3//1\n");
    const mesh m = load_obj(path);
    EXPECT_TRUE(m.file_had_normals);
    for (const auto& n : m.normals) EXPECT_NEAR(glm::length(n - glm::dvec3(0.0, 0.6, 0.8)), 0.0, 1e-12);
}

TEST(SceneObj, MissingFileIsAClearError) { expect_obj_error(::testing::TempDir() + "no_such_file.obj", "cannot be opened"); }

TEST(SceneObj, EmptyFileIsAClearError) {
    expect_obj_error(write_temp("empty.obj", ""), "empty");
    expect_obj_error(write_temp("vertices_only.obj", "v 0 0 0\nv 1 0 0\n"), "empty: no faces");
}

TEST(SceneObj, MalformedFileIsAClearError) {
    expect_obj_error(write_temp("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n"), "refers to vertex 7 of 3");
    expect_obj_error(write_temp("zero_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), "malformed");
}

TEST(SceneWorld, UnknownSceneAndBadMaterialAreErrors) {
    EXPECT_THROW(builtin_scene("teapot", SHADING_SOURCE_DIR, 16, 16), scene_error);
    world s = builtin_scene("sphere", SHADING_SOURCE_DIR, 16, 16);
    s.objects[0].mat.n = 1001;
    EXPECT_THROW(validate(s), scene_error);
    s.objects[0].mat.n = 0;
    EXPECT_THROW(rasterise(s), scene_error);
}

// An octahedron of half-diagonal `s` (an OBJ the framing can see from any side).
std::string octahedron(const std::string& s) {
    const std::string text = "v " + s + " 0 0\nv -" + s + " 0 0\nv 0 " + s + " 0\nv 0 -" + s + " 0\nv 0 0 " + s +
                             "\nv 0 0 -" + s + "\nf 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
    return write_temp("octahedron_" + s + ".obj", text);
}

// The framing squares coordinates and extents: a model at 1e200 framed to an empty picture and one at
// 1e-200 to a camera on its target. Outside +-1e100 and 1e-100 the model is refused with both
// figures and what to do; at the limits it frames as at size 1 (the same view, scaled).
TEST(SceneWorld, ObjOutsideTheFramingRangeIsAClearError) {
    for (const std::string s : {"1e200", "1e-200", "3e100"}) {
        try {
            (void)obj_scene(octahedron(s), 32, 32);
            ADD_FAILURE() << "no error at " << s;
        } catch (const scene_error& e) {
            EXPECT_NE(std::string(e.what()).find("scale the model"), std::string::npos) << e.what();
        }
    }
    const std::size_t unit = rasterise(obj_scene(octahedron("1"), 32, 32)).covered_pixels();
    EXPECT_GT(unit, 100u);  // the octahedron fills about a sixth of the frame
    for (const std::string s : {"1e100", "1e-100"}) {
        const std::size_t n = rasterise(obj_scene(octahedron(s), 32, 32)).covered_pixels();
        EXPECT_NEAR(double(n), double(unit), 2.0) << s;
    }
}

// ---- Rasteriser --------------------------------------------------------------------------------

// Screen triangle (0,0), (8,0), (0,8): a centre (x + 0.5, y + 0.5) lies inside when x + y < 7,
// on the hypotenuse when x + y = 7 (excluded: half-open right edge). 28 pixels. Its complement
// (8,0), (8,8), (0,8) covers the other 36: no pixel twice, none missed.
TEST(SceneRaster, OneTriangleCoversKnownPixels) {
    const world s = ortho_scene({screen_object("a", {{{{0, 0}, {8, 0}, {0, 8}}}}, 0.0)});
    const rasterised r = rasterise(s);
    for (unsigned y = 0; y < 8; ++y)
        for (unsigned x = 0; x < 8; ++x) {
            EXPECT_EQ(r.covered(x, y), x + y <= 6) << x << "," << y;
            if (r.covered(x, y)) {
                EXPECT_DOUBLE_EQ(r.depth[r.index(x, y)], 10.0);
            }
        }
    EXPECT_EQ(r.covered_pixels(), 28u);
    const auto spans = line_spans(r, 2);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_EQ(spans[0].x_begin, 0u);
    EXPECT_EQ(spans[0].x_end, 5u);

    const world both = ortho_scene({screen_object("a", {{{{0, 0}, {8, 0}, {0, 8}}}, {{{8, 0}, {8, 8}, {0, 8}}}}, 0.0)});
    const rasterised rb = rasterise(both);
    EXPECT_EQ(rb.covered_pixels(), 64u);
    for (unsigned y = 0; y < 8; ++y)
        for (unsigned x = 0; x < 8; ++x) EXPECT_EQ(rb.setups[rb.tri[rb.index(x, y)]].triangle, x + y <= 6 ? 0u : 1u);
}

// A vertex 1e15 pixels off the screen (as an OBJ vertex 1e12 units aside, near the camera plane,
// projects): the triangle is clipped to the screen before any pixel index is formed. Each triangle
// below has two edges within a hair of the screen's own and so covers all 64 pixels.
TEST(SceneRaster, VertexFarOffScreenIsClipped) {
    using tri = std::array<glm::dvec2, 3>;
    for (const tri& t : {tri{{{0, 0}, {0, 8}, {1e15, 4}}}, tri{{{8, 0}, {8, 8}, {-1e15, 4}}},
                         tri{{{0, 0}, {8, 0}, {4, 1e15}}}, tri{{{0, 8}, {8, 8}, {4, -1e15}}}}) {
        const rasterised r = rasterise(ortho_scene({screen_object("far", {t}, 0.0)}));
        EXPECT_EQ(r.covered_pixels(), 64u) << t[2].x << "," << t[2].y;
    }
}

// A far square (depth 10) and a nearer triangle (depth 8) over its top-left corner: the nearer one
// wins where both cover, whichever is drawn first.
TEST(SceneRaster, DepthBufferKeepsTheNearer) {
    const object far = screen_object("far", {{{{0, 0}, {8, 0}, {0, 8}}}, {{{8, 0}, {8, 8}, {0, 8}}}}, 0.0);
    const object near = screen_object("near", {{{{0, 0}, {4, 0}, {0, 4}}}}, 2.0);
    for (bool near_first : {false, true}) {
        const world s = near_first ? ortho_scene({near, far}) : ortho_scene({far, near});
        const rasterised r = rasterise(s);
        const int32_t near_id = near_first ? 0 : 1;
        for (unsigned y = 0; y < 8; ++y)
            for (unsigned x = 0; x < 8; ++x) {
                const bool in_near = x + y <= 2;  // centres inside (0,0), (4,0), (0,4)
                EXPECT_EQ(r.object_at(x, y), in_near ? near_id : 1 - near_id) << x << "," << y;
                EXPECT_DOUBLE_EQ(r.depth[r.index(x, y)], in_near ? 8.0 : 10.0);
            }
    }
}

// A perspective camera looking straight at the plane z = 0 from z = 5: every covered pixel has
// view depth 5 (perspective-correct depth on a plane parallel to the image).
TEST(SceneRaster, PerspectiveDepthOfAFrontPlane) {
    world s = ortho_scene({screen_object("plane", {{{{0, 0}, {8, 0}, {0, 8}}}, {{{8, 0}, {8, 8}, {0, 8}}}}, 0.0)});
    s.cam.position = {0.0, 0.0, 5.0};
    s.cam.fov_y_deg = 60.0;
    const rasterised r = rasterise(s);
    EXPECT_EQ(r.covered_pixels(), 64u);
    for (double d : r.depth) EXPECT_NEAR(d, 5.0, 1e-12);
}

// A background square at depth 10 (pixels 0..7) and, in the same mesh, a nearer square at depth 8
// over x in [2, 6): line 3 jumps at x = 2 and x = 6 (depth steps of 2); it begins at 0 and ends at 8.
// As two meshes, the same places are also object changes.
TEST(SceneRaster, DiscontinuitiesAtAKnownSilhouette) {
    const std::vector<std::array<glm::dvec2, 3>> bg{{{{0, 0}, {8, 0}, {0, 8}}}, {{{8, 0}, {8, 8}, {0, 8}}}};
    const std::vector<std::array<glm::dvec2, 3>> box{{{{2, 1}, {6, 1}, {2, 6}}}, {{{6, 1}, {6, 6}, {2, 6}}}};
    object one = screen_object("one", bg, 0.0);
    const object front = screen_object("front", box, 2.0);
    for (const auto& p : front.geometry.positions) one.geometry.positions.push_back(p);
    for (const auto& n : front.geometry.normals) one.geometry.normals.push_back(n);
    for (auto t : front.geometry.triangles) one.geometry.triangles.push_back({t[0] + 6, t[1] + 6, t[2] + 6});
    {
        const rasterised r = rasterise(ortho_scene({one}));
        const auto d = line_discontinuities(r, 3, 0.5);
        ASSERT_EQ(d.size(), 4u);
        EXPECT_EQ(d[0].x, 0u);
        EXPECT_EQ(d[0].kinds, unsigned{coverage_begin});
        EXPECT_EQ(d[1].x, 2u);
        EXPECT_EQ(d[1].kinds, unsigned{depth_step});
        EXPECT_EQ(d[2].x, 6u);
        EXPECT_EQ(d[2].kinds, unsigned{depth_step});
        EXPECT_EQ(d[3].x, 8u);
        EXPECT_EQ(d[3].kinds, unsigned{coverage_end});
        // A threshold above the step finds only the coverage edges.
        EXPECT_EQ(line_discontinuities(r, 3, 2.5).size(), 2u);
        // Line 0 is above the box: no jump inside.
        EXPECT_EQ(line_discontinuities(r, 0, 0.5).size(), 2u);
    }
    {
        const rasterised r = rasterise(ortho_scene({screen_object("bg", bg, 0.0), front}));
        const auto d = line_discontinuities(r, 3, 0.5);
        ASSERT_EQ(d.size(), 4u);
        EXPECT_EQ(d[1].kinds, unsigned{object_change | depth_step});
        EXPECT_EQ(d[2].kinds, unsigned{object_change | depth_step});
    }
}

// Vertex normals +z, +x, +y at screen (0,0), (8,0), (0,8): pixel (0, 0)'s centre has barycentrics
// (14, 1, 1)/16 (orthographic: screen-linear = perspective-correct), so N = (1, 1, 14)/sqrt(198).
TEST(SceneRaster, InterpolatedNormalHandWorked) {
    object o = screen_object("a", {{{{0, 0}, {8, 0}, {0, 8}}}}, 0.0);
    o.geometry.normals = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
    const world s = ortho_scene({o});
    const rasterised r = rasterise(s);
    op_counts ops;
    const pixel_geometry g = geometry_at(r, 0, 0, &ops);
    const double k = 1.0 / std::sqrt(198.0);
    EXPECT_NEAR(g.n.x.value(), k, 1e-15);
    EXPECT_NEAR(g.n.y.value(), k, 1e-15);
    EXPECT_NEAR(g.n.z.value(), 14.0 * k, 1e-15);
    // Orthographic view along -z: V = +z; the default light is directional along +z, so H = +z.
    EXPECT_DOUBLE_EQ(g.v.z.value(), 1.0);
    EXPECT_NEAR(g.h[0].z.value(), 1.0, 1e-15);
}

// ---- References --------------------------------------------------------------------------------

// I = 255 (ambient + k_d N.L + k_s (N.H)^4) with N.L = 0.8, (N.H)^4 = 0.81:
// R = 255 * 0.662 = 168.81, G = 255 * 0.582 = 148.41, B = 255 * 0.502 = 128.01.
TEST(SceneShade, PhongHandWorkedPixel) {
    op_counts ops;
    const rgb v = shade_phong(hand_pixel(&ops), hand_material(), {light{}});
    EXPECT_NEAR(v.x, 168.81, 1e-9);
    EXPECT_NEAR(v.y, 148.41, 1e-9);
    EXPECT_NEAR(v.z, 128.01, 1e-9);
}

// Shading one pixel, one light, n = 4, counted by hand: N.L (3 mul, 2 add), N.L > 0 (1 cmp),
// N.H (3 mul, 2 add), max(N.H, 0) (1 cmp), (N.H)^4 = two squarings (2 mul), k_s I S per channel
// (3 mul), k_d I N.L per channel (3 mul), two additions per channel (6 add).
TEST(SceneShade, PhongShadingCountsHandCounted) {
    op_counts ops;
    shade_phong(hand_pixel(&ops), hand_material(), {light{}});
    op_counts hand;
    hand.mul = 3 + 3 + 2 + 3 + 3;
    hand.add = 2 + 2 + 6;
    hand.cmp = 2;
    EXPECT_EQ(ops, hand) << ops;
}

// Geometry of one pixel, perspective camera, one directional light, counted by hand:
// barycentrics 3 x (2 mul, 2 add) + 2 add + 1 div + 3 mul; N = sum b_i N_i (9 mul, 6 add);
// normalise N (6 mul, 2 add, 1 sqrt, 1 div); P = sum b_i P_i (9 mul, 6 add); V = eye - P (3 add)
// and normalise; L constant; H = L + V (3 add) and normalise.
TEST(SceneShade, GeometryCountsHandCounted) {
    world s = ortho_scene({screen_object("plane", {{{{0, 0}, {8, 0}, {0, 8}}}}, 0.0)});
    s.cam.position = {0.0, 0.0, 5.0};
    s.cam.fov_y_deg = 60.0;
    const rasterised r = rasterise(s);
    ASSERT_TRUE(r.covered(1, 1));
    op_counts ops;
    geometry_at(r, 1, 1, &ops);
    op_counts hand;
    hand.mul = 6 + 3 + 9 + 6 + 9 + 6 + 6;
    hand.add = 6 + 2 + 6 + 2 + 6 + 3 + 2 + 3 + 2;
    hand.div = 1 + 1 + 1 + 1;
    hand.sqrt = 3;
    hand.rsqrt = 3;  // N, V and H: each square root is a normalisation's, one 1/sqrt pair with a division
    EXPECT_EQ(ops, hand) << ops;
}

TEST(SceneShade, PowIntCountsAndValue) {
    for (unsigned n : {1u, 2u, 3u, 24u, 1000u}) {
        op_counts ops;
        const cnum r = pow_int(cnum(0.999, &ops), n);
        EXPECT_NEAR(r.value(), std::pow(0.999, n), 1e-15 * n);
        unsigned lg = 0, pc = 0;
        for (unsigned t = n; t > 1; t >>= 1) ++lg;
        for (unsigned t = n; t; t >>= 1) pc += t & 1u;
        EXPECT_EQ(ops.mul, lg + pc - 1) << n;
    }
}

// The device reference's specular term is the golden model's output, called directly here with the
// cos code and 8-bit k_s I codes worked out in the test.
TEST(SceneShade, DeviceReferenceEqualsGolden) {
    const material m = hand_material();
    const double ndh = 1.8 / std::sqrt(3.6);
    const uint64_t code = static_cast<uint64_t>(std::floor(ndh * 32768.0 + 0.5));
    const uint64_t ks = 51;  // 0.2 * 255
    const std::array<uint64_t, 3> ksi{ks, ks, ks};
    for (auto mode : {overflow_mode::saturate, overflow_mode::wrap})
        for (const std::string& name : device_names()) {
            const device_config dev{parse_device(name), mode};
            std::array<uint64_t, 3> want{1u << 20, 1u << 20, 1u << 20};  // no code: fails below
            if (name == "patent") want = golden_ua60553(m.n, code, ksi, mode, ua60553::patent).out;
            if (name == "minimax") want = golden_ua60553_tuned(m.n, code, ksi, mode, ua60553::minimax).out;
            if (name == "rom_matched") want = golden_ua60553_tuned(m.n, code, ksi, mode, ua60553::rom_matched).out;
            if (name == "ua22802") want = golden_ua22802(m.n, code, ksi, mode).out;
            if (name == "squared") want = golden_squared(m.n, code, ksi, mode).out;
            if (name == "sqmul") want = golden_sqmul(m.n, code, ksi, mode).out;
            op_counts ops;
            const rgb v = shade_device(hand_pixel(&ops), m, {light{}}, dev);
            const rgb diffuse = 255.0 * (m.ambient + 0.8 * m.k_d);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(v[c], diffuse[c] + static_cast<double>(want[c]) / 256.0, 1e-9) << name << " " << c;
        }
}

// Any specular unit is shaded as a device: its out codes (Q9.8) are added as 8-bit levels, and it
// is asked with the material's n, the pixel's cos code and the 8-bit k_s I codes.
TEST(SceneShade, SpecularUnitIsShadedAsADevice) {
    const material m = hand_material();
    const uint32_t code = static_cast<uint32_t>(std::floor(1.8 / std::sqrt(3.6) * 32768.0 + 0.5));
    unsigned calls = 0;
    const specular_fn unit = [&](unsigned n, uint32_t c, const std::array<uint64_t, 3>& ksi) {
        ++calls;
        EXPECT_EQ(n, m.n);
        EXPECT_EQ(c, code);
        EXPECT_EQ(ksi, (std::array<uint64_t, 3>{51, 51, 51}));  // 0.2 * 255
        return std::array<uint64_t, 3>{256, 512, 0};              // 1.0, 2.0, 0.0 levels
    };
    op_counts ops;
    const rgb v = shade_specular(hand_pixel(&ops), m, {light{}}, unit);
    const rgb diffuse = 255.0 * (m.ambient + 0.8 * m.k_d);
    EXPECT_EQ(calls, 1u);
    EXPECT_NEAR(v.x, diffuse.x + 1.0, 1e-9);
    EXPECT_NEAR(v.y, diffuse.y + 2.0, 1e-9);
    EXPECT_NEAR(v.z, diffuse.z, 1e-9);
    // A whole frame through a unit that calls the squared device's golden model is that device's.
    const world s = builtin_scene("head", SHADING_SOURCE_DIR, 32, 32);
    const rasterised r = rasterise(s);
    const device_config dev{specular_device::squared, overflow_mode::saturate};
    const shaded_image a = render_device(r, dev);
    const shaded_image b = render_specular(r, [&dev](unsigned n, uint32_t c, const std::array<uint64_t, 3>& ksi) {
        return device_specular(dev, n, c, ksi);
    });
    EXPECT_EQ(a.value, b.value);
    EXPECT_EQ(a.covered, b.covered);
}

// The head at 64x64: it fills a good part of the frame, has a specular highlight (red above
// 255 (ambient + k_d) = 186, which diffuse light alone cannot reach), and the tuned device's image
// is close to Phong's (NMSE of order 1e-3, from the quadratic BRDF's clamped tail).
TEST(SceneShade, HeadIsLitWithAHighlight) {
    const world s = builtin_scene("head", SHADING_SOURCE_DIR, 64, 64);
    const material& m = s.objects.front().mat;
    const rasterised r = rasterise(s);
    render_stats st;
    const shaded_image a = render_phong(r, &st);
    const shaded_image b = render_device(r, {specular_device::minimax, overflow_mode::saturate});
    EXPECT_GT(st.pixels, 64u * 64u / 4);
    double peak = 0.0;
    for (const auto& v : a.value) peak = std::max(peak, v.x);
    EXPECT_GT(peak, 255.0 * (m.ambient.x + m.k_d.x) + 10.0);
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < a.value.size(); ++i) {
        const rgb d = b.value[i] - a.value[i];
        num += glm::dot(d, d);
        den += glm::dot(a.value[i], a.value[i]);
    }
    EXPECT_LT(num / den, 1e-2);
}

TEST(SceneRaster, UncountedGeometrySameValues) {
    const world s = builtin_scene("sphere", SHADING_SOURCE_DIR, 32, 32);
    const rasterised r = rasterise(s);
    ASSERT_TRUE(r.covered(16, 16));
    op_counts ops;
    const pixel_geometry a = geometry_at(r, 16, 16, &ops);
    const pixel_geometry b = geometry_at(r, 16, 16, nullptr);
    EXPECT_GT(ops.long_ops(), 0u);
    EXPECT_EQ(dot(a.n, a.h[0]).value(), dot(b.n, b.h[0]).value());
    EXPECT_EQ(dot(a.n, a.l[0]).value(), dot(b.n, b.l[0]).value());
}

}  // namespace test_scene
