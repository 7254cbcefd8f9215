// Grid movement (interact/grid_walk.h): a step moves one tile, walls stop it, turns are quarter
// turns, and the camera glides between poses over the step.
#include <gtest/gtest.h>

#include <cmath>

#include "interact/grid_walk.h"

namespace penumbra::viewer {
namespace {

// 3 x 3 tiles of 2 m, the centre column open, the rest walls except the middle row.
//   # . #
//   . . .
//   # . #
TileGrid plus() {
    TileGrid g;
    g.tileSize = 2;
    g.width = g.depth = 3;
    g.walkable = {0, 1, 0, 1, 1, 1, 0, 1, 0};
    return g;
}

Camera facingNorthFromCentre() {
    Camera c;
    c.position = {3, 1.6f, 3};
    c.lookAt = {3, 1.6f, 2};
    return c;
}

void finishStep(GridWalker& g) {
    for (int i = 0; i < 20; ++i) g.update(CameraInput{}, 0.05f);
}

TEST(GridWalk, StepsOneTileAndGlides) {
    GridWalker g(plus(), facingNorthFromCentre());
    EXPECT_EQ(g.tileX(), 1);
    EXPECT_EQ(g.tileZ(), 1);
    EXPECT_EQ(g.facing(), 0);
    CameraInput forward;
    forward.forward = 1;
    g.update(forward, 0.0f);
    EXPECT_TRUE(g.stepping());
    EXPECT_EQ(g.tileZ(), 0);
    g.update(CameraInput{}, GridWalker::kStepSeconds / 2);
    const Vec3 halfway = g.camera().position;
    EXPECT_NEAR(halfway.z, 2.0f, 1e-4f);  // smoothstep is 1/2 at the middle: between z = 3 and 1
    finishStep(g);
    EXPECT_FALSE(g.stepping());
    EXPECT_NEAR(g.camera().position.z, 1.0f, 1e-5f);
    EXPECT_NEAR(g.camera().position.y, 1.6f, 1e-5f);
    g.update(forward, 0.0f);  // a wall (outside the map) ahead: no step
    EXPECT_FALSE(g.stepping());
    EXPECT_EQ(g.tileZ(), 0);
}

TEST(GridWalk, StepsBobTheHeadAndTurnsDoNot) {
    GridWalker g(plus(), facingNorthFromCentre());
    const float eye = g.camera().position.y;
    const float lift = GridWalker::kBobFraction * 2.0f;  // of the 2 m tile
    CameraInput forward;
    forward.forward = 1;
    g.update(forward, 0.0f);
    EXPECT_NEAR(g.camera().position.y, eye, 1e-5f);  // the step starts on the ground
    float highest = eye;
    for (int i = 1; i <= 8; ++i) {
        g.update(CameraInput{}, GridWalker::kStepSeconds / 8);
        const float y = g.camera().position.y;
        EXPECT_GE(y, eye - 1e-5f);
        EXPECT_LE(y, eye + lift + 1e-5f);
        highest = std::max(highest, y);
        if (i == 4) {
            EXPECT_NEAR(y, eye + lift, 1e-5f) << "the top of the bob is mid-step";
        }
    }
    EXPECT_NEAR(highest, eye + lift, 1e-5f);
    EXPECT_NEAR(g.camera().position.y, eye, 1e-5f);  // and it ends on the ground
    CameraInput turn;
    turn.turn = 1;
    g.update(turn, 0.0f);
    for (int i = 1; i <= 8; ++i) {
        g.update(CameraInput{}, GridWalker::kStepSeconds / 8);
        EXPECT_NEAR(g.camera().position.y, eye, 1e-6f) << "turning does not bob";
    }
}

TEST(GridWalk, TurnsAQuarterAndStrafesIntoOpenTilesOnly) {
    GridWalker g(plus(), facingNorthFromCentre());
    CameraInput left;
    left.turn = 1;
    g.update(left, 0.0f);
    finishStep(g);
    EXPECT_EQ(g.facing(), 1);  // west
    const Camera c = g.camera();
    EXPECT_NEAR(c.lookAt.x - c.position.x, -1.0f, 1e-5f);
    EXPECT_NEAR(c.lookAt.z - c.position.z, 0.0f, 1e-5f);
    CameraInput right;
    right.right = 1;  // facing west, right is north
    g.update(right, 0.0f);
    finishStep(g);
    EXPECT_EQ(g.tileX(), 1);
    EXPECT_EQ(g.tileZ(), 0);
    g.update(right, 0.0f);  // facing west at (1, 0): north of it is outside the map
    EXPECT_FALSE(g.stepping());
    // Four right turns from west come back to west, the short way round each time.
    CameraInput turnRight;
    turnRight.turn = -1;
    for (int i = 0; i < 4; ++i) {
        g.update(turnRight, 0.0f);
        g.update(CameraInput{}, GridWalker::kStepSeconds / 2);
        const Camera mid = g.camera();
        const Vec3 d = mid.lookAt - mid.position;
        EXPECT_NEAR(std::hypot(d.x, d.z), 1.0f, 1e-4f);
        finishStep(g);
    }
    EXPECT_EQ(g.facing(), 1);
}

}  // namespace
}  // namespace penumbra::viewer
