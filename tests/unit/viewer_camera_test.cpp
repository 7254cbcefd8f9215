// The viewer's camera controller (no window needed): moves, turns, clamps and resets as the
// controls promise.
#include <gtest/gtest.h>

#include "interact/camera_controller.h"
#include "scene/io/wad/wad_loader.h"
#include "wad/wad_builder.h"

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

// The test WAD's room: 256 x 256 units (8 m), floor 0, ceiling 128, a pillar at 96..160 and the
// player start at (64, 64) facing north (scene -z).
Scene roomScene() {
    testing::WadBuilder wad;
    testing::roomWithPillar().addTo(wad, "E1M1");
    testing::addTestGraphics(wad);
    return loadWadFromMemory(wad.build("IWAD"), "", "room.wad");
}

TEST(ViewerCamera, DoomLevelsStartWalkingAtEyeHeightAndWallsStopThem) {
    const Scene scene = roomScene();
    CameraController c(scene.camera, 1.0f, scene.walkMap);
    ASSERT_TRUE(c.walking());
    expectNear(c.camera().position, {64 / 32.0f, 41 / 32.0f, -64 / 32.0f});
    c.update({.up = 1}, 0.5f);  // no flying up, no jumping while walking
    expectNear(c.camera().position, {64 / 32.0f, 41 / 32.0f, -64 / 32.0f});
    // A second at Doom's 292 units/s would go 292 units north; the wall at 256 stops the
    // player's 16-unit half-width at 240.
    for (int i = 0; i < 60; ++i) c.update({.forward = 1}, 1.0f / 60);
    expectNear(c.camera().position, {64 / 32.0f, 41 / 32.0f, -240 / 32.0f}, 2e-3f);
    // Looking down does not change where the walk goes or how fast.
    c.reset();
    c.update({.lookY = 300}, 0.0f);
    c.update({.forward = 1}, 0.25f);
    expectNear(c.camera().position, {64 / 32.0f, 41 / 32.0f, -(64 + 0.25f * 292) / 32.0f}, 2e-3f);
}

TEST(ViewerCamera, FreeFlightPassesWallsAndWalkingNeedsRoom) {
    const Scene scene = roomScene();
    CameraController c(scene.camera, 8.0f, scene.walkMap);
    ASSERT_TRUE(c.setWalking(false));
    EXPECT_FALSE(c.walking());
    c.update({.forward = 1}, 1.0f);  // 8 m north: through the wall at 8 m - 2 m
    EXPECT_NEAR(c.camera().position.z, -64 / 32.0f - 8.0f, 1e-4f);
    EXPECT_FALSE(c.setWalking(true)) << "outside the map";
    EXPECT_FALSE(c.walking());
    c.reset();  // back at the start, still flying
    EXPECT_FALSE(c.walking());
    c.update({.forward = 1, .right = 1}, 2.0f / 8.0f);  // 2 m north and east: (128, 128), the pillar's centre
    EXPECT_FALSE(c.setWalking(true)) << "inside the pillar";
    c.reset();
    EXPECT_TRUE(c.setWalking(true));
    CameraController noMap(start(), 1.0f);
    EXPECT_FALSE(noMap.canWalk());
    EXPECT_FALSE(noMap.walking());
    EXPECT_FALSE(noMap.setWalking(true));
}

}  // namespace
}  // namespace penumbra::viewer
