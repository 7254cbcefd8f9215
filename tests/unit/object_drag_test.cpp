// Dragging an instance with the mouse (interact/object_drag.h): the grabbed point follows the
// cursor in the plane facing the camera at its depth. The oracle projects points with the pinhole
// camera written out here (vertical field of view, square pixels, row 0 at the top).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "interact/object_drag.h"
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

// Turning by a Shift drag (turnAboutCentre, dragTurnDegrees), applied as the viewer applies it:
// moveInstance with the turn's offset and yaw, one step per frame of cursor motion.
void turnBy(Scene& scene, Vec3 centreLocal, float dxPixels) {
    const InstanceTurn turn = turnAboutCentre(scene.instances[0].transform, centreLocal, dragTurnDegrees(dxPixels, kWidth));
    moveInstance(scene, 0, turn.offset, turn.yawDegrees);
}

float maxDifference(const Affine& a, const Affine& b) {
    float d = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) d = std::max(d, std::abs(a.m[i][j] - b.m[i][j]));
    return d;
}

Scene sceneWithTurnedBox() {
    Scene scene;
    Mesh box;  // a box from (1, 0, 2) to (3, 1, 6): its centre (2, 0.5, 4) is far from the origin
    box.positions = {{1, 0, 2}, {3, 1, 6}, {3, 0, 2}};
    scene.prototypes.push_back({"box", {box}});
    // Scaled, sheared and turned: the centre must stay put whatever the linear part.
    Affine shear;
    shear.m[0][1] = 0.4f;
    scene.instances.push_back({0, Affine::translation({0.5f, 1, 8}) * Affine::eulerDegrees({10, 35, 0}) * shear *
                                      Affine::scaling({1.5f, 0.7f, 1.2f})});
    return scene;
}

TEST(ObjectTurn, TheCentreStaysAndTheTurnIsAboutTheVertical) {
    Scene scene = sceneWithTurnedBox();
    const Vec3 centre = prototypeCentre(scene, 0);
    EXPECT_NEAR(length(centre - Vec3{2, 0.5f, 4}), 0, 1e-6f);
    const Affine before = scene.instances[0].transform;
    const Vec3 corner{1, 0, 2};
    for (float dx : {13.0f, 160.0f, -47.5f}) {
        const Affine start = scene.instances[0].transform;
        turnBy(scene, centre, dx);
        const Affine& now = scene.instances[0].transform;
        EXPECT_LT(length(now.point(centre) - before.point(centre)), 1e-5f) << dx;
        // Any point keeps its height and its distance from the vertical through the centre, and
        // turns by the drag's angle about it.
        const Vec3 c = before.point(centre), p0 = start.point(corner) - c, p1 = now.point(corner) - c;
        EXPECT_NEAR(p1.y, p0.y, 1e-5f);
        const float a0 = std::atan2(p0.x, p0.z), a1 = std::atan2(p1.x, p1.z);
        const float turned = std::remainder(a1 - a0, 2.0f * kPiF);
        EXPECT_NEAR(turned, degreesToRadians(dx * 360.0f / float(kWidth)), 1e-5f) << dx;
        EXPECT_NEAR(std::hypot(p1.x, p1.z), std::hypot(p0.x, p0.z), 1e-5f);
    }
}

TEST(ObjectTurn, ADragAndBackAndAWholeWindowWidthGiveTheTransformBack) {
    Scene scene = sceneWithTurnedBox();
    const Vec3 centre = prototypeCentre(scene, 0);
    const Affine before = scene.instances[0].transform;
    // Out and back over several frames of uneven cursor steps.
    for (float dx : {3.0f, 41.0f, 17.5f, 90.0f}) turnBy(scene, centre, dx);
    for (float dx : {-60.0f, -91.5f}) turnBy(scene, centre, dx);
    EXPECT_LT(maxDifference(scene.instances[0].transform, before), 2e-5f);
    // Dragging across the whole window turns it once around.
    for (int step = 0; step < 8; ++step) turnBy(scene, centre, float(kWidth) / 8.0f);
    EXPECT_LT(maxDifference(scene.instances[0].transform, before), 5e-5f);
}

TEST(ObjectTurn, DraggingRightTurnsTheSideFacingTheCameraRight) {
    // Seen from several directions around the object: the point of it nearest the camera moves
    // right on the screen when the cursor does, and left when it goes left.
    for (float heading : {0.0f, 70.0f, 180.0f, 250.0f}) {
        Scene scene = sceneWithTurnedBox();
        const Vec3 centre = prototypeCentre(scene, 0);
        const Vec3 c = scene.instances[0].transform.point(centre);
        const Vec3 toCamera = Affine::eulerDegrees({0, heading, 0}).vector(Vec3{0, 0, 1});
        Camera cam;
        cam.position = c + toCamera * 6.0f + Vec3{0, 2, 0};
        cam.lookAt = c;
        cam.fovYDegrees = 60.0f;
        const Vec3 nearLocal = scene.instances[0].transform.inverse().point(c + toCamera);  // on the near side
        for (float dx : {20.0f, -20.0f}) {
            Scene turned = scene;
            const float x0 = project(cam, turned.instances[0].transform.point(nearLocal)).x;
            turnBy(turned, centre, dx);
            const float x1 = project(cam, turned.instances[0].transform.point(nearLocal)).x;
            EXPECT_GT((x1 - x0) * dx, 0.0f) << "heading " << heading << ", dx " << dx;
        }
    }
}

}  // namespace
}  // namespace penumbra::viewer
