// The viewer's camera controller (no window needed): moves, turns, clamps and resets as the
// controls promise.
#include <gtest/gtest.h>

#include "app/viewer/camera_controller.h"

namespace penumbra::viewer {
namespace {

Camera start() {
    Camera c;
    c.position = {1, 2, 3};
    c.lookAt = {1, 2, 4};  // looking down +z
    c.up = {0, 1, 0};
    return c;
}

Vec3 forwardOf(const Camera& c) { return normalize(c.lookAt - c.position); }

void expectNear(Vec3 a, Vec3 b, float tol = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(ViewerCamera, StartsWhereTheSceneCameraIs) {
    CameraController c(start(), 2.0f);
    expectNear(c.camera().position, {1, 2, 3});
    expectNear(forwardOf(c.camera()), {0, 0, 1});
}

TEST(ViewerCamera, WasdAndSpaceMoveAlongTheViewAxesAtTheSetSpeed) {
    CameraController c(start(), 2.0f);
    c.update({.forward = 1}, 0.5f);  // 2 m/s for 0.5 s
    expectNear(c.camera().position, {1, 2, 4});
    // Right of a camera looking down +z with +y up is -x (the renderer's convention).
    c.update({.right = 1}, 0.5f);
    expectNear(c.camera().position, {0, 2, 4});
    c.update({.up = 1, .fast = true}, 0.25f);  // Shift: four times faster
    expectNear(c.camera().position, {0, 4, 4});
}

TEST(ViewerCamera, QTurnsLeftAndMouseDragLooksAround) {
    CameraController c(start(), 1.0f);
    const float quarterTurnSeconds = 1.5707963f / 1.5f;  // kTurnRate is 1.5 rad/s
    c.update({.turn = 1}, quarterTurnSeconds);
    expectNear(forwardOf(c.camera()), {1, 0, 0}, 1e-4f);  // left of +z is +x
    c.update({.lookY = -10000}, 0.0f);  // drag far up: pitch stops short of the zenith
    Vec3 f = forwardOf(c.camera());
    EXPECT_GT(f.y, 0.99f);
    EXPECT_LT(f.y, 1.0f);
}

TEST(ViewerCamera, ScrollScalesSpeedAndResetRestoresEverything) {
    CameraController c(start(), 1.0f);
    c.scaleSpeed(2.0f);
    EXPECT_FLOAT_EQ(c.speed(), 2.0f);
    c.update({.forward = 1, .turn = 1}, 1.0f);
    c.reset();
    EXPECT_FLOAT_EQ(c.speed(), 1.0f);
    expectNear(c.camera().position, {1, 2, 3});
    expectNear(forwardOf(c.camera()), {0, 0, 1});
}

}  // namespace
}  // namespace penumbra::viewer
