// The fit's parametrised golden model (squared_variants.h) against the device's own golden model
// and hand-worked words; the trial law's exponents and fit against hand-worked values; the cos distribution's
// measure against values known without it. No simulation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "arith/squared_arith.h"
#include "formats/specular_formats.h"
#include "formats/squared_formats.h"
#include "head_surface.h"
#include "scene/image.h"
#include "scene/raster.h"
#include "scene/shade.h"
#include "scene/world.h"
#include "squared_variants.h"
#include "trial_law.h"

using namespace shading;
using namespace shading::study;

TEST(SquaredVariants, TheDeviceVariantIsTheDeviceBitForBit) {
    const squared_variant dev = squared_device_variant();
    const std::array<uint64_t, 3> ksi{255, 1, 200};
    for (unsigned n = 0; n < 1024; ++n) {
        ASSERT_EQ(variant_a(dev, n), golden_squared_a(n).a) << n;
        ASSERT_EQ(variant_k(n), golden_squared_a(n).k) << n;
        for (uint64_t c = 0; c <= spec::cos_one; c += (c < 512 || c > spec::cos_one - 512) ? 1 : 7) {
            const auto want = golden_squared(n, c, ksi, overflow_mode::saturate);
            ASSERT_EQ(variant_word(dev, n, c), want.brdf) << "n " << n << " cos " << c;
            ASSERT_EQ(variant_out(dev, n, c, ksi), want.out) << "n " << n << " cos " << c;
        }
    }
}

TEST(SquaredVariants, HandWorkedBends) {
    // n = 3: k = 1, f = 0.5 = 256/512, ~f = 255, e = 65280 (Q0.18); a = f + e / 2^(18 - 12 + 1 + s)
    // on Q0.12, f = 2048: s = 1: 65280 >> 8 = 255; s = 2: >> 9 = 127; s = 3: >> 10 = 63.
    const auto bends = bend_variants();
    auto a_of = [&](const char* id) {
        for (const auto& v : bends)
            if (v.id == id) return variant_a(v, 3);
        ADD_FAILURE() << id;
        return uint64_t{0};
    };
    EXPECT_EQ(a_of("f"), 2048u);
    EXPECT_EQ(a_of("s1"), 2048u + 255u);
    EXPECT_EQ(a_of("s2"), 2048u + 127u);
    EXPECT_EQ(a_of("s3"), 2048u + 63u);
    EXPECT_EQ(a_of("s2s3"), 2048u + 127u + 63u);  // 3/8: each shifted copy floored on its own bus
}

TEST(SquaredVariants, BendsAreTheirLawOnTheGrid) {
    // a = f + sum_s floor(f (1 - f - 2^-9) / 2^(k + s) * 2^12) / 2^12, in doubles from n alone.
    for (const auto& v : bend_variants())
        for (unsigned n = 1; n <= 1000; ++n) {
            unsigned k = 0;
            while (n >> (k + 1)) ++k;
            const double f = std::ldexp(n, -static_cast<int>(k)) - 1.0;
            double a = f;
            for (unsigned s : v.bend_shifts)
                a += std::floor(std::ldexp(f * (1.0 - f - 1.0 / 512.0), 12 - static_cast<int>(k + s)) + 1e-9) / 4096.0;
            EXPECT_DOUBLE_EQ(to_real(variant_a(v, n), squared::a_fmt), a) << v.id << " n " << n;
            EXPECT_LT(variant_a(v, n), 4096u) << v.id << " n " << n;  // a < 1 on Q0.12
        }
}

TEST(SquaredVariants, HandWorkedPixelAtSixteenFractionBits) {
    // n = 3, cos = 0.5, device bend (a = 2175, Q0.12), Q1.16: d = -2^28 (Q2.30); a d >> (42 - 16)
    // = -8700; q = 0.5 * 2^16 - 8700 = 24068; one square: 24068^2 = 579268624, >> 16 = 8838.
    squared_variant v = squared_device_variant();
    v.q_frac = 16;
    EXPECT_EQ(variant_word(v, 3, 0x4000), 8838u);
    // Q1.20: a d >> 22 = -139200; q = 2^19 - 139200 = 385088; 385088^2 = 148292767744, >> 20 = 141423.
    v.q_frac = 20;
    EXPECT_EQ(variant_word(v, 3, 0x4000), 141423u);
    // cos = 1.0 stays exactly 1.0 at every word length and n.
    for (const auto& f : fraction_variants()) {
        for (unsigned n : {1u, 3u, 20u, 1000u}) {
            EXPECT_DOUBLE_EQ(variant_value(f, n, spec::cos_one), 1.0) << f.id << " n " << n;
        }
    }
}

TEST(TrialLaw, HandWorkedExponents) {
    // n' = n / 2^k in [2, 4) with k = floor(log2 n) - 1; n < 4: k = 0.
    EXPECT_EQ(trial_k(1), 0u);
    EXPECT_EQ(trial_k(3), 0u);
    EXPECT_EQ(trial_k(4), 1u);
    EXPECT_EQ(trial_k(20), 3u);
    EXPECT_DOUBLE_EQ(trial_n_prime(20), 2.5);
    EXPECT_EQ(trial_k(1000), 8u);
    EXPECT_DOUBLE_EQ(trial_n_prime(1000), 3.90625);
    // n' = 2: the paper's a(2) = (t - 1)/(t - 1) = 1, and q = c^2 exactly; squared once: c^4.
    EXPECT_DOUBLE_EQ(trial_a_inflection(4), 1.0);
    EXPECT_NEAR(trial_law(0.9, 1.0, 4), std::pow(0.9, 4), 1e-15);
}

TEST(TrialLaw, TheFitIsNoWorseThanTheInflection) {
    // On a spread of codes, the fitted a's NMSE cannot exceed the inflection a's (it is searched
    // in a bracket that holds it) nor any point of a dense grid, and for n = 4 (q = c^2 exact at
    // a = 1) the fit finds a = 1.
    cos_distribution d;
    for (uint32_t c = 0; c <= spec::cos_one; c += 97) {
        d.codes.push_back(c);
        d.weight.push_back(1.0 + (c % 5));
        d.samples += 1 + (c % 5);
    }
    for (unsigned n : {5u, 20u, 333u}) {
        auto law = [n](double a) {
            return [n, a](uint64_t c) { return trial_law(std::ldexp(static_cast<double>(c), -15), a, n); };
        };
        const double fitted = trial_a_fitted(d, n), best = distribution_nmse(d, n, law(fitted));
        EXPECT_LE(best, distribution_nmse(d, n, law(trial_a_inflection(n)))) << n;
        // No point of a 301-point grid over the bracket (the law's first fit) does better (brute force).
        const double ai = trial_a_inflection(n), lo = std::max(0.5 * ai, 0.0), hi = 1.5 * ai + 0.01;
        for (int i = 0; i <= 300; ++i) EXPECT_LE(best, distribution_nmse(d, n, law(lo + (hi - lo) * i / 300)) * (1 + 1e-12)) << n;
    }
    EXPECT_NEAR(trial_a_fitted(d, 4), 1.0, 1e-6);
}

TEST(HeadSurface, DistributionAndItsNmse) {
    const scene::world w = scene::builtin_scene("sphere", "", 48, 48);
    const scene::rasterised r = scene::rasterise(w);
    const cos_distribution d = nh_distribution(r);
    double sum = 0;
    for (std::size_t i = 0; i < d.codes.size(); ++i) {
        sum += d.weight[i];
        if (i > 0) {
            EXPECT_LT(d.codes[i - 1], d.codes[i]);
        }
    }
    EXPECT_DOUBLE_EQ(sum, static_cast<double>(d.samples));
    EXPECT_GT(d.samples, 0u);
    EXPECT_LE(d.samples, r.covered_pixels() * w.lights.size());
    // The exact law has NMSE 0, the zero law 1, half the exact law 1/4, whatever the distribution.
    auto exact = [](double scale) {
        return [scale](uint64_t c) { return scale * std::pow(std::ldexp(static_cast<double>(c), -15), 20); };
    };
    EXPECT_DOUBLE_EQ(distribution_nmse(d, 20, exact(1.0)), 0.0);
    EXPECT_DOUBLE_EQ(distribution_nmse(d, 20, exact(0.0)), 1.0);
    EXPECT_NEAR(distribution_nmse(d, 20, exact(0.5)), 0.25, 1e-12);
}

TEST(HeadSurface, ReplayIsTheSceneLibraryBitForBit) {
    // The replayed references against the scene library's own renders of the same raster.
    head_surface head(SHADING_SOURCE_DIR, 64);
    const shading_replay replay(head.raster());
    const scene::specular_fn squared = [](unsigned n, uint32_t c, const std::array<uint64_t, 3>& ksi) {
        return golden_squared(n, c, ksi, overflow_mode::saturate).out;
    };
    for (unsigned n : {1u, 3u, 20u, 777u}) {
        head.set_n(n);
        const auto check = [n](const scene::shaded_image& got, const scene::shaded_image& want, const char* what) {
            ASSERT_EQ(got.covered, want.covered) << what << " n " << n;
            EXPECT_GT(std::count(want.covered.begin(), want.covered.end(), 1), 1000) << "the head covers the image";
            std::size_t differ = 0;
            for (std::size_t i = 0; i < want.value.size(); ++i) differ += got.value[i] != want.value[i];
            EXPECT_EQ(differ, 0u) << what << " n " << n;
        };
        const scene::shaded_image phong = scene::render_phong(head.raster());
        const scene::shaded_image device = scene::render_device(head.raster(), {scene::specular_device::squared,
                                                                                overflow_mode::saturate});
        const auto rp = replay.phong(n), rs = replay.specular(n, squared);
        check(replay.image(rp), phong, "phong");
        check(replay.image(rs), scene::render_specular(head.raster(), squared), "squared");
        check(replay.image(rs), device, "squared as a scene device");
        const scene::image_diff want = scene::compare_images(device, phong), got = shading_replay::compare(rs, rp);
        EXPECT_EQ(got.nmse, want.nmse) << n;
        EXPECT_EQ(got.max_abs, want.max_abs) << n;
    }
}
