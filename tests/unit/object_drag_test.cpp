// Dragging an instance with the mouse (app/viewer/object_drag.h): the grabbed point follows the
// cursor in the plane facing the camera at its depth. The oracle projects points with the pinhole
// camera written out here (vertical field of view, square pixels, row 0 at the top).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "app/viewer/object_drag.h"
#include "scene/objects.h"
#include "shared/constants.h"

namespace penumbra::viewer {
namespace {

constexpr std::uint32_t kWidth = 640, kHeight = 360;

struct Projected {
    float x, y, depth;
};

Projected project(const Camera& c, Vec3 p) {
    const Vec3 forward = normalize(c.lookAt - c.position);
    const Vec3 right = normalize(cross(forward, c.up));
    const Vec3 up = cross(right, forward);
    const Vec3 v = p - c.position;
    const float depth = dot(v, forward);
    const float tanHalf = std::tan(degreesToRadians(c.fovYDegrees * 0.5f));
    const float aspect = float(kWidth) / float(kHeight);
    const float ndcX = dot(v, right) / depth / (aspect * tanHalf), ndcY = dot(v, up) / depth / tanHalf;
    return {(ndcX + 1) * 0.5f * float(kWidth), (1 - ndcY) * 0.5f * float(kHeight), depth};
}

Camera lookingDownZ() {
    Camera c;
    c.position = {1, 2, 3};
    c.lookAt = {1, 2, 4};
    c.up = {0, 1, 0};
    c.fovYDegrees = 60.0f;
    return c;
}

TEST(ObjectDrag, DraggingNPixelsMovesByNPixelWidthsAtTheObjectsDepth) {
    const Camera c = lookingDownZ();
    const Vec3 grabbed{1, 2, 13};  // on the axis, 10 m ahead: under the image centre
    const float pixel = 2.0f * 10.0f * std::tan(degreesToRadians(30.0f)) / float(kHeight);
    const Vec3 right = dragOffset(c, kWidth, kHeight, grabbed, kWidth / 2.0f + 25, kHeight / 2.0f);
    // Right of a camera looking down +z with +y up is -x.
    EXPECT_NEAR(right.x, -25 * pixel, 1e-4f);
    EXPECT_NEAR(right.y, 0, 1e-5f);
    EXPECT_NEAR(right.z, 0, 1e-5f);
    const Vec3 up = dragOffset(c, kWidth, kHeight, grabbed, kWidth / 2.0f, kHeight / 2.0f - 40);
    EXPECT_NEAR(up.x, 0, 1e-5f);
    EXPECT_NEAR(up.y, 40 * pixel, 1e-4f);
    EXPECT_NEAR(up.z, 0, 1e-5f);
    // No drag, no move.
    const Vec3 still = dragOffset(c, kWidth, kHeight, grabbed, kWidth / 2.0f, kHeight / 2.0f);
    EXPECT_NEAR(length(still), 0, 1e-5f);
}

TEST(ObjectDrag, TheGrabbedPointLandsUnderTheCursorAtTheSameDepth) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> coord(-5, 5), px(0, float(kWidth)), py(0, float(kHeight)), fov(20, 100);
    int checked = 0;
    for (int i = 0; i < 200; ++i) {
        Camera c;
        c.position = {coord(rng), coord(rng), coord(rng)};
        c.lookAt = c.position + Vec3{coord(rng), coord(rng) * 0.3f, coord(rng)};
        c.fovYDegrees = fov(rng);
        if (length(c.lookAt - c.position) < 0.5f) continue;
        const Vec3 p{coord(rng), coord(rng), coord(rng)};
        const Projected before = project(c, p);
        if (!(before.depth > 0.5f)) continue;
        const float x = px(rng), y = py(rng);
        const Projected after = project(c, p + dragOffset(c, kWidth, kHeight, p, x, y));
        EXPECT_NEAR(after.x, x, 2e-3f * (1 + before.depth));
        EXPECT_NEAR(after.y, y, 2e-3f * (1 + before.depth));
        EXPECT_NEAR(after.depth, before.depth, 1e-5f * (1 + before.depth));
        ++checked;
    }
    EXPECT_GT(checked, 50);
}

TEST(ObjectDrag, ADraggedInstanceKeepsItsGrabbedPointUnderTheCursor) {
    const Camera c = lookingDownZ();
    Scene scene;
    scene.prototypes.push_back({"thing", {}});
    scene.instances.push_back({0, Affine::translation({0, 1, 8}) * Affine::eulerDegrees({0, 35, 0})});
    // Grab at a pixel whose surface lies 5 m deep, then drag across a few frames.
    const std::optional<ObjectDrag> drag =
        startObjectDrag(0, scene.instances[0].transform, c, kWidth, kHeight, 300, 150, 5.0f);
    ASSERT_TRUE(drag.has_value());
    EXPECT_NEAR(project(c, scene.instances[0].transform.point(drag->grabbedLocal)).x, 300, 1e-3f);
    for (const auto& [x, y] : {std::pair{310.0f, 150.0f}, {420.0f, 90.0f}, {20.0f, 350.0f}}) {
        const Vec3 grabbed = scene.instances[0].transform.point(drag->grabbedLocal);
        moveInstance(scene, drag->instance, dragOffset(c, kWidth, kHeight, grabbed, x, y), 0.0f);
        const Projected now = project(c, scene.instances[0].transform.point(drag->grabbedLocal));
        EXPECT_NEAR(now.x, x, 1e-3f);
        EXPECT_NEAR(now.y, y, 1e-3f);
        EXPECT_NEAR(now.depth, 5.0f, 1e-4f);
    }
}

TEST(ObjectDrag, NothingToGrabOrBehindTheCameraMovesNothing) {
    const Camera c = lookingDownZ();
    EXPECT_FALSE(startObjectDrag(0, Affine{}, c, kWidth, kHeight, 10, 10, 0.0f).has_value());
    const Vec3 behind = dragOffset(c, kWidth, kHeight, Vec3{1, 2, -4}, 100, 100);
    EXPECT_EQ(length(behind), 0.0f);
}

}  // namespace
}  // namespace penumbra::viewer
