#include "image/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"

namespace penumbra {
namespace {

TEST(Metrics, MeanLuminanceUsesRec709Weights) {
    ImageRgb img(2, 1);
    img.at(0, 0) = {1, 0, 0};
    img.at(1, 0) = {0, 1, 1};
    EXPECT_NEAR(meanLuminance(img), 0.5, 1e-6);  // (0.2126 + 0.7152 + 0.0722) / 2
    EXPECT_NEAR(meanLuminance(ImageRgb(4, 4, Vec3(0.5f))), 0.5, 1e-6);
    EXPECT_EQ(meanLuminance(ImageRgb()), 0.0);
}

TEST(Metrics, Rmse) {
    ImageRgb a(2, 2, Vec3(1.0f));
    ImageRgb b = a;
    EXPECT_EQ(rmse(a, b), 0.0);
    b.at(0, 0) = {3, 1, 1};  // one channel of twelve off by 2: sqrt(4 / 12)
    EXPECT_NEAR(rmse(a, b), std::sqrt(4.0 / 12.0), 1e-12);
    EXPECT_THROW(rmse(a, ImageRgb(2, 3)), Error);
    b.at(1, 1).x = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(std::isnan(rmse(a, b)));
}

TEST(Metrics, DisplayedPsnrMeasuresWhatAPngShows) {
    ImageRgb ref(4, 4), img(4, 4);
    for (Vec3& p : ref.pixels) p = Vec3{0.5f};
    img = ref;
    EXPECT_TRUE(std::isinf(displayedPsnr(img, ref)));
    // Displayed values: reinhard then sRGB. One pixel's three channels changed from 0.5 to 1.
    img.at(1, 2) = Vec3{1.0f};
    const double d = srgbOetf(0.5f) - srgbOetf(1.0f / 3.0f);
    EXPECT_NEAR(displayedPsnr(img, ref), -20.0 * std::log10(std::sqrt(d * d / 16.0)), 1e-4);
    // A blown-out light barely counts: 100 vs 1000 is almost the same white.
    ImageRgb light = ref, brighter = ref;
    light.at(0, 0) = Vec3{100.0f};
    brighter.at(0, 0) = Vec3{1000.0f};
    EXPECT_GT(displayedPsnr(brighter, light), 40.0);
}

TEST(Metrics, GradientEnergyOfAStripePattern) {
    // Vertical stripes of luminance 0 and 1 on a 4x3 image: 3 horizontal differences of 1 per
    // row, none vertical.
    ImageRgb img(4, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) img.at(x, y) = Vec3{float(x % 2)};
    EXPECT_NEAR(gradientEnergy(img), 9.0, 1e-9);
    EXPECT_EQ(gradientEnergy(ImageRgb(5, 5)), 0.0);
}

TEST(ImageRgb, StatsAndAccess) {
    ImageRgb img(3, 2);
    img.at(2, 1) = {6, 0, 3};
    EXPECT_EQ(img.pixels[5], Vec3(6, 0, 3));  // row-major
    EXPECT_EQ(img.mean(), Vec3(1, 0, 0.5f));
    EXPECT_FALSE(img.hasNonFinite());
    img.at(0, 0).y = std::numeric_limits<float>::infinity();
    EXPECT_TRUE(img.hasNonFinite());
}

}  // namespace
}  // namespace penumbra
