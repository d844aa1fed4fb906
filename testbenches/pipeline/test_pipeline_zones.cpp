// The zone map of the head (zones.cpp) against landmarks found on the head's mesh, and the plan's
// zones policy and every policy on the head. No simulation here: these tests may share a process.
#include "plan_test_fixtures.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_pipeline_zones {

using namespace shading;
using namespace shading::pipeline;
using namespace plan_test;

// ---- Zones ----

TEST(PipelineZones, Names) {
    const char* names[] = {"other", "brows", "forehead", "eyes", "cheeks", "nose", "mouth", "chin"};
    for (unsigned z = 0; z < zone_count; ++z) EXPECT_STREQ(zone_name(z), names[z]);
    EXPECT_STREQ(zone_name(zone_count), "?");
    // The interpolation paper: zones 2, 4 and 7 quadratic; with our numbering forehead, cheeks and chin.
    for (unsigned z = 0; z < zone_count; ++z) EXPECT_EQ(zone_is_quadratic(z), z == 2 || z == 4 || z == 7) << z;
}

// Landmarks found on the head's mesh, independently of the zone boxes: the nose tip (the vertex
// farthest along +z), the top of the skull, the lowest vertex (the shoulders), and along the face's
// centre line the most forward vertex at a given height (forehead, chin) and beside the nose.
TEST(PipelineZones, LandmarksOfTheHead) {
    const auto& f = head();
    const scene::mesh& m = f.w.objects[0].geometry;
    auto zone_at = [&f](const glm::dvec3& p) {
        scene::pixel_geometry g;
        g.object = 0;
        g.p = {scene::cnum(p.x, nullptr), scene::cnum(p.y, nullptr), scene::cnum(p.z, nullptr)};
        return head_zone(f.r, g);
    };
    glm::dvec3 tip = m.positions[0], top = m.positions[0], low = m.positions[0];
    for (const auto& p : m.positions) {
        if (p.z > tip.z) tip = p;
        if (p.y > top.y) top = p;
        if (p.y < low.y) low = p;
    }
    EXPECT_STREQ(zone_name(zone_at(tip)), "nose");
    EXPECT_STREQ(zone_name(zone_at(top)), "other");
    EXPECT_STREQ(zone_name(zone_at(low)), "other");
    // The most forward vertex near the centre line (|x - tip.x| < 5 mm) within a band of heights.
    auto front = [&m, &tip](double x_off, double y_lo, double y_hi) {
        glm::dvec3 best(0.0, 0.0, -1e9);
        for (const auto& p : m.positions)
            if (std::abs(p.x - tip.x - x_off) < 0.005 && p.y >= y_lo && p.y < y_hi && p.z > best.z) best = p;
        return best;
    };
    const double h = top.y - tip.y;  // about 0.15 world units
    // Forehead: the centre line halfway between the brows' ridge and the top, well above the eyes.
    EXPECT_STREQ(zone_name(zone_at(front(0.0, tip.y + 0.6 * h, tip.y + 0.7 * h))), "forehead");
    // Chin: the most forward point of the centre line's lowest tenth of the face (below the lips).
    EXPECT_STREQ(zone_name(zone_at(front(0.0, tip.y - 0.6 * h, tip.y - 0.45 * h))), "chin");
    // Beside the nose, a third of h out, level with the tip: the cheek.
    EXPECT_STREQ(zone_name(zone_at(front(0.3 * h, tip.y - 0.05 * h, tip.y + 0.05 * h))), "cheeks");
    // The eye socket: the deepest point of the line through the eye (x = 0.033), between the brow
    // ridge and the cheek.
    glm::dvec3 socket(0.0, 0.0, 1e9);
    for (const auto& p : m.positions)
        if (std::abs(p.x - tip.x - 0.033) < 0.004 && p.y > tip.y + 0.05 * h && p.y < tip.y + 0.35 * h && p.z < socket.z &&
            p.z > tip.z - 0.3 * h)
            socket = p;
    EXPECT_STREQ(zone_name(zone_at(socket)), "eyes");
    // The brow ridge: the most forward point of that line above the socket.
    EXPECT_STREQ(zone_name(zone_at(front(0.033, socket.y + 0.12 * h, socket.y + 0.35 * h))), "brows");
    // The lips: the most forward point of the centre line below the nose, above the chin.
    EXPECT_STREQ(zone_name(zone_at(front(0.0, tip.y - 0.3 * h, tip.y - 0.12 * h))), "mouth");
}

// Without a position (an orthographic camera and a directional light: geometry_at leaves g.p at 0)
// there is no zone, rather than the zone of the origin.
TEST(PipelineZones, NoPositionNoZone) {
    scene::world w = scene::builtin_scene("head", SHADING_SOURCE_DIR, 48, 48);
    w.cam.fov_y_deg = 0.0;
    w.cam.ortho_height = 0.6;
    const scene::rasterised r = scene::rasterise(w);
    std::size_t covered = 0;
    for (unsigned y = 0; y < r.height; ++y)
        for (unsigned x = 0; x < r.width; ++x)
            if (r.covered(x, y)) {
                ++covered;
                EXPECT_EQ(head_zone(r, scene::geometry_at(r, x, y, nullptr)), 0u);
            }
    EXPECT_GT(covered, 0u);
    // The same head in perspective has face zones.
    const auto& f = head();
    std::size_t face = 0;
    for (unsigned y = 0; y < f.r.height; ++y)
        for (unsigned x = 0; x < f.r.width; ++x)
            if (f.r.covered(x, y)) face += head_zone(f.r, scene::geometry_at(f.r, x, y, nullptr)) != 0;
    EXPECT_GT(face, 0u);
}

// Every zone is on the rendered head, the face's zones in the face's pixels; writes the zone map over
// the shaded head (build/out/pipeline/zones_head.png) to look at.
TEST(PipelineZones, ZoneMapOfTheHead) {
    const auto& f = head();
    const scene::shaded_image img = scene::render_phong(f.r);
    scene::rgb_image out = scene::to_rgb8(img);
    // other grey, brows red, forehead green, eyes blue, cheeks yellow, nose magenta, mouth cyan, chin orange.
    const uint8_t palette[zone_count][3] = {{128, 128, 128}, {255, 0, 0},   {0, 200, 0},   {0, 0, 255},
                                            {255, 255, 0},   {255, 0, 255}, {0, 255, 255}, {255, 128, 0}};
    std::vector<std::size_t> count(zone_count, 0);
    for (unsigned y = 0; y < f.r.height; ++y)
        for (unsigned x = 0; x < f.r.width; ++x) {
            if (!f.r.covered(x, y)) continue;
            const unsigned z = head_zone(f.r, scene::geometry_at(f.r, x, y, nullptr));
            ASSERT_LT(z, zone_count);
            ++count[z];
            uint8_t* p = out.at(x, y);
            for (int ch = 0; ch < 3; ++ch) p[ch] = static_cast<uint8_t>((p[ch] + palette[z][ch]) / 2);
        }
    const std::size_t face = f.r.covered_pixels();
    for (unsigned z = 1; z < zone_count; ++z) EXPECT_GT(count[z] * 200, face) << zone_name(z) << ": under 0.5 %";
    // The face is a part of the bust, not most of it.
    EXPECT_GT(count[0] * 3, face);
    std::filesystem::create_directories("out/pipeline");
    scene::save_png(out, "out/pipeline/zones_head.png");
}

TEST(PipelinePlan, ZonesPolicyIsTheZoneMap) {
    const auto& f = head();
    plan_config c = head_fixed(3);
    c.degree = degree_policy::zones;
    const plan p = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, p, c);
    std::size_t quad = 0, cubic = 0;
    for (const auto& j : p.jobs) {
        if (j.m == 0) continue;
        const bool q = zone_is_quadratic(head_zone(f.r, scene::geometry_at(f.r, j.x0, j.y, nullptr)));
        EXPECT_EQ(j.deg2, q) << "line " << j.y << ", x " << j.x0;
        (q ? quad : cubic) += 1;
    }
    EXPECT_GT(quad, 0u);
    EXPECT_GT(cubic, 0u);
    // Quadratic intervals do not compute the quarter point: the geometry is exactly the jobs' points.
    EXPECT_EQ(p.geometry_points, sample_pixels(p, c.set).size());
    EXPECT_EQ(p.geometry, geometry_cost(f.r, sample_pixels(p, c.set)));
    EXPECT_EQ(p.check_samples, 0u);
}

TEST(PipelinePlan, HeadWithEveryPolicy) {
    const auto& f = head();
    for (auto len : {length_policy::fixed, length_policy::adaptive})
        for (auto deg : {degree_policy::cubic, degree_policy::quadratic, degree_policy::zones, degree_policy::adaptive}) {
            SCOPED_TRACE(std::string(length_policy_name(len)) + " / " + degree_policy_name(deg));
            plan_config c;
            c.length = len;
            c.degree = deg;
            const plan p = make_plan(f.r, f.k, patent, c);
            expect_valid_plan(f.r, p, c);
        }
}

}  // namespace test_pipeline_zones
