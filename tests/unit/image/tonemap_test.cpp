#include "image/tonemap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace penumbra {
namespace {

TEST(Srgb, KnownValues) {
    EXPECT_EQ(srgbOetf(0.0f), 0.0f);
    EXPECT_NEAR(srgbOetf(1.0f), 1.0f, 1e-6f);
    EXPECT_EQ(toSrgb8(0.0f), 0);
    EXPECT_EQ(toSrgb8(1.0f), 255);
    // Middle grey: 0.18 linear encodes to 0.4614, i.e. 117.7 -> 118.
    EXPECT_NEAR(srgbOetf(0.18f), 0.4614f, 1e-4f);
    EXPECT_EQ(toSrgb8(0.18f), 118);
    EXPECT_EQ(toSrgb8(2.0f), 255);
    EXPECT_EQ(toSrgb8(-1.0f), 0);
}

TEST(Srgb, PiecewiseSegmentsMeetAtBoundary) {
    const float b = 0.0031308f;
    float below = srgbOetf(std::nextafter(b, 0.0f));
    float above = srgbOetf(std::nextafter(b, 1.0f));
    EXPECT_NEAR(srgbOetf(b), 12.92f * b, 1e-7f);  // 0.04045, the decoding threshold
    EXPECT_NEAR(below, above, 1e-5f);
}

TEST(Srgb, Monotonic) {
    float prev = -1;
    for (int i = 0; i <= 1000; ++i) {
        float v = srgbOetf(static_cast<float>(i) / 1000.0f);
        EXPECT_GE(v, prev);
        prev = v;
    }
}

TEST(Reinhard, MapsXToXOverOnePlusX) {
    for (float x : {0.0f, 0.25f, 1.0f, 3.0f, 100.0f}) {
        EXPECT_FLOAT_EQ(toneMapChannel(x, {}), x / (1 + x)) << x;
    }
}

TEST(Reinhard, ExposurePlusOneDoublesInput) {
    ToneMapSettings plusOne{1.0f};
    ToneMapSettings minusOne{-1.0f};
    for (float x : {0.1f, 0.5f, 2.0f}) {
        EXPECT_FLOAT_EQ(toneMapChannel(x, plusOne), toneMapChannel(2 * x, {})) << x;
        EXPECT_FLOAT_EQ(toneMapChannel(x, minusOne), toneMapChannel(x / 2, {})) << x;
    }
}

TEST(Reinhard, NonFiniteAndNegativeAreSafe) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(reinhard(nan), 0.0f);
    EXPECT_EQ(reinhard(inf), 1.0f);
    EXPECT_EQ(reinhard(-inf), 0.0f);
    EXPECT_EQ(reinhard(-0.5f), 0.0f);
}

TEST(ToneMapToSrgb8, LayoutAndSpecialValues) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    ImageRgb img(2, 1);
    img.at(0, 0) = {nan, inf, 0.0f};
    img.at(1, 0) = {1.0f, 0.25f, -inf};
    auto bytes = toneMapToSrgb8(img, {});
    ASSERT_EQ(bytes.size(), 6u);
    EXPECT_EQ(bytes[0], 0);    // NaN -> black
    EXPECT_EQ(bytes[1], 255);  // +inf -> white
    EXPECT_EQ(bytes[2], 0);
    EXPECT_EQ(bytes[3], toSrgb8(0.5f));  // 1 / (1 + 1)
    EXPECT_EQ(bytes[4], toSrgb8(0.2f));  // 0.25 / 1.25
    EXPECT_EQ(bytes[5], 0);
}

}  // namespace
}  // namespace penumbra
