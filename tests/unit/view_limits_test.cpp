// shared/view_limits.h on the CPU: the render distance's exit from the cylinder around the
// camera, against points along the ray, and the ranges the settings share.
#include "shared/view_limits.h"

#include <gtest/gtest.h>

#include <cmath>

#include "render/view_settings.h"
#include "core/error.h"

namespace penumbra {
namespace {

TEST(RenderDistance, RaysEndWhereTheyLeaveTheCylinderAroundTheCamera) {
    using shader::renderDistanceExit;
    // From the camera straight across the floor: the distance itself, whatever the height.
    EXPECT_FLOAT_EQ(renderDistanceExit(0, 0, 1, 0, 10), 10.0f);
    EXPECT_FLOAT_EQ(renderDistanceExit(0, 0, 0.6f, 0.8f, 10), 10.0f);
    // Half up (a unit direction with 0.5 across the floor) goes twice as far along the ray.
    EXPECT_FLOAT_EQ(renderDistanceExit(0, 0, 0.5f, 0, 10), 20.0f);
    // Straight up or down: never leaves. Off (0): no limit.
    EXPECT_EQ(renderDistanceExit(3, 4, 0, 0, 10), float(PN_RENDER_DISTANCE_UNLIMITED));
    EXPECT_EQ(renderDistanceExit(0, 0, 1, 0, 0), float(PN_RENDER_DISTANCE_UNLIMITED));
    // From a point 6 m east, heading west: leaves 16 m on. Heading east: 4 m on.
    EXPECT_FLOAT_EQ(renderDistanceExit(6, 0, -1, 0, 10), 16.0f);
    EXPECT_FLOAT_EQ(renderDistanceExit(6, 0, 1, 0, 10), 4.0f);
    // Outside and missing the cylinder, or outside and heading away: nothing to hit.
    EXPECT_EQ(renderDistanceExit(20, 20, 1, 0, 10), 0.0f);
    EXPECT_EQ(renderDistanceExit(20, 0, 1, 0, 10), 0.0f);
    // Many rays: the exit point lies on the circle, and just before it inside.
    for (int i = 0; i < 100; ++i) {
        const float a = 0.37f * float(i), px = 3 * std::cos(1.7f * float(i)), pz = 2 * std::sin(0.9f * float(i));
        const float dx = std::cos(a) * 0.7f, dz = std::sin(a) * 0.7f;
        const float t = renderDistanceExit(px, pz, dx, dz, 7);
        EXPECT_NEAR(std::hypot(px + t * dx, pz + t * dz), 7.0f, 1e-4f) << i;
        EXPECT_LT(std::hypot(px + 0.99f * t * dx, pz + 0.99f * t * dz), 7.0f) << i;
    }
}

TEST(ViewSettingRanges, TheCommandLineChecksEverySettingsRange) {
    ViewSettings v;
    EXPECT_NO_THROW(checkViewSettingRanges(v));
    v.textureSaturation = 2.5f;
    EXPECT_THROW(checkViewSettingRanges(v), UsageError);
    v = ViewSettings{};
    v.renderDistance = -1;
    EXPECT_THROW(checkViewSettingRanges(v), UsageError);
    v = ViewSettings{};
    v.resolutionScale = 0.2f;
    EXPECT_THROW(checkViewSettingRanges(v), UsageError);
}

}  // namespace
}  // namespace penumbra
