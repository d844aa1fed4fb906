// The scene side's images (src/scene/image.h): PNG files, heat maps, comparison sheets, against
// file facts and hand-worked pixels. No simulation here: these tests may share a process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "scene/image.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_scene_images {

using namespace shading;
using namespace shading::scene;

// The PNG written is a PNG of the right size (signature and IHDR read back by hand).
TEST(SceneImage, PngSignatureAndSize) {
    rgb_image img(5, 3, 0);
    img.at(4, 2)[0] = 255;
    const std::string path = ::testing::TempDir() + "shading_scene_test.png";
    save_png(img, path);
    std::ifstream f(path, std::ios::binary);
    std::vector<unsigned char> head(24);
    f.read(reinterpret_cast<char*>(head.data()), 24);
    ASSERT_TRUE(f);
    const unsigned char sig[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
    for (int i = 0; i < 8; ++i) EXPECT_EQ(head[i], sig[i]);
    EXPECT_EQ(head[19], 5);  // width, big-endian at 16..19
    EXPECT_EQ(head[23], 3);  // height at 20..23
    EXPECT_THROW(save_png(img, ::testing::TempDir() + "no_such_dir/x.png"), image_error);
}

TEST(SceneImage, HeatMapEnds) {
    const rgb_image h = heat_map({0.0, 10.0, 20.0}, 3, 1, 10.0);
    EXPECT_EQ(h.at(0, 0)[0] + h.at(0, 0)[1] + h.at(0, 0)[2], 0);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(h.at(1, 0)[c], 255);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(h.at(2, 0)[c], 255);
}

// A value that is not a number has no 8-bit level: both conversions name the pixel, (1, 1) of a
// 2 x 2 image; masked out, the heat map draws it grey.
TEST(SceneImage, NotANumberIsAClearError) {
    shaded_image s;
    s.width = s.height = 2;
    s.value.assign(4, rgb(10.0));
    s.covered.assign(4, 1);
    s.value[3].y = std::nan("");
    try {
        to_rgb8(s);
        ADD_FAILURE() << "to_rgb8 took NaN";
    } catch (const image_error& e) {
        EXPECT_NE(std::string(e.what()).find("pixel (1, 1) channel 1"), std::string::npos) << e.what();
    }
    std::vector<double> v(4, 1.0);
    v[2] = std::nan("");
    try {
        heat_map(v, 2, 2, 10.0);
        ADD_FAILURE() << "heat_map took NaN";
    } catch (const image_error& e) {
        EXPECT_NE(std::string(e.what()).find("pixel (0, 1)"), std::string::npos) << e.what();
    }
    const std::vector<uint8_t> mask = {1, 1, 0, 1};
    const rgb_image h = heat_map(v, 2, 2, 10.0, &mask);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(h.at(0, 1)[c], 40);
}

// NMSE and largest error by hand: ref (10, 20, 30) and an uncovered pixel; test (11, 20, 27) and
// anything on the uncovered pixel: NMSE = (1 + 0 + 9) / (100 + 400 + 900), largest error 3.
TEST(SceneImage, CompareImagesHandWorked) {
    shaded_image ref, test;
    ref.width = test.width = 2;
    ref.height = test.height = 1;
    ref.value = {rgb(10, 20, 30), rgb(0.0)};
    ref.covered = {1, 0};
    test.value = {rgb(11, 20, 27), rgb(200, 0, 0)};
    test.covered = {1, 1};
    const image_diff d = compare_images(test, ref);
    EXPECT_DOUBLE_EQ(d.nmse, 10.0 / 1400.0);
    EXPECT_DOUBLE_EQ(d.max_abs, 3.0);
    shaded_image other = ref;
    other.width = 1;
    other.height = 2;
    EXPECT_THROW(compare_images(other, ref), image_error);
}

// Rows stacked left-aligned on the sheets' background (24); the heat map's key: its bar runs from
// the map's 0 (black) to its full scale (white); too small to draw: background only.
TEST(SceneImage, StackedAndLegend) {
    const rgb_image s = stacked({rgb_image(3, 2, 7), rgb_image(5, 1, 9)});
    EXPECT_EQ(s.width, 5u);
    EXPECT_EQ(s.height, 3u);
    EXPECT_EQ(s.at(2, 1)[0], 7);
    EXPECT_EQ(s.at(4, 1)[0], 24);
    EXPECT_EQ(s.at(4, 2)[0], 9);
    const rgb_image k = heat_map_legend(200, 100, 8.0, "KEY");
    ASSERT_EQ(k.width, 200u);
    ASSERT_EQ(k.height, 100u);
    const unsigned y = 50;  // the bar's middle line: (100 - 24) / 2 + 12
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(k.at(16, y)[c], 0) << c;          // left end: 0
        EXPECT_EQ(k.at(200 - 17, y)[c], 255) << c;  // right end: full scale
        EXPECT_EQ(k.at(5, y)[c], 24) << c;          // margin: background
    }
    const rgb_image tiny = heat_map_legend(10, 10, 8.0, "KEY");
    EXPECT_TRUE(std::all_of(tiny.data.begin(), tiny.data.end(), [](uint8_t v) { return v == 24; }));
}

// Uncounted geometry (ops = nullptr) gives the same values as counted geometry.

}  // namespace test_scene_images
