// Moving instances by hand (scene/objects.h moveInstance), and what the animation clock does to
// such a move: an animated instance keeps the user's edit composed with its animation
// (node_animation.h editedTransform) instead of having its animation overwrite it.
#include <gtest/gtest.h>

#include "scene/animation.h"
#include "scene/objects.h"

namespace penumbra::test {
namespace {

void expectNear(Vec3 a, Vec3 b, float tolerance = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

// One instance of an empty prototype, placed by `placement`, animated by `chain` if it has nodes.
Scene oneInstance(const Affine& placement, std::vector<NodeMotion> chain = {}) {
    Scene s;
    s.prototypes.push_back({"thing", {}});
    s.instances.push_back({0, placement});
    if (!chain.empty()) s.instanceAnimations.push_back({0, std::move(chain), Affine{}});
    return s;
}

// A scene-file motion: 2 m/s along +x from (1, 0, 0), spinning 90 degrees per second about +y.
NodeMotion patrol() {
    NodeMotion node;
    node.fixed = Affine::translation({1, 0, 0});
    ScriptedMotion m;
    m.path = {{0, 0, 0}, {10, 0, 0}};
    m.speed = 2.0f;
    m.repeat = MotionRepeat::Once;
    m.spinDegreesPerSecond = 90.0f;
    node.scripted = m;
    return node;
}

// A glTF node whose translation is keyed linearly from (0, 0, 0) at 0 s to (0, 4, 0) at 2 s.
NodeMotion keyedLift() {
    NodeMotion node;
    node.trs = true;
    node.translationTrack.times = {0.0f, 2.0f};
    node.translationTrack.values = {KeyValue{0, 0, 0, 0}, KeyValue{0, 4, 0, 0}};
    return node;
}

TEST(InstanceEdit, AStillInstanceTurnsAboutItsOriginThenMoves) {
    Scene s = oneInstance(Affine::translation({2, 0, 0}));
    moveInstance(s, 0, {0, 1, 0}, 90.0f);
    const Affine& t = s.instances[0].transform;
    expectNear(t.point({0, 0, 0}), {2, 1, 0});  // the origin moved by the offset only
    // A quarter turn about +y (right-handed) takes +x to -z, about the origin at (2, 0, 0).
    expectNear(t.point({1, 0, 0}), {2, 1, -1});
}

// The bug this guards against: the viewer's clock applied the animation every frame and the
// user's move was gone on the next one.
TEST(InstanceEdit, AMovedAnimatedInstanceKeepsTheMoveAsItsAnimationPlays) {
    const std::vector<NodeMotion> chain = {patrol()};
    Scene s = oneInstance(Affine{}, chain);
    applyInstanceAnimations(s, 1.0);
    moveInstance(s, 0, {0, 0, 3}, 0.0f);
    expectNear(s.instances[0].transform.point({0, 0, 0}), chainTransform(chain, 1.0).point({0, 0, 0}) + Vec3{0, 0, 3});
    for (double seconds : {1.0, 1.5, 2.0, 3.25}) {
        applyInstanceAnimations(s, seconds);
        const Affine animated = chainTransform(chain, seconds);
        // Still patrolling and spinning, 3 m to the side of where the animation alone puts it.
        for (Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 2, -1}})
            expectNear(s.instances[0].transform.point(p), animated.point(p) + Vec3{0, 0, 3});
    }
}

TEST(InstanceEdit, ATurnOfAnAnimatedInstanceStaysAboutItsMovingOrigin) {
    const std::vector<NodeMotion> chain = {patrol()};
    Scene s = oneInstance(Affine{}, chain);
    applyInstanceAnimations(s, 0.5);
    moveInstance(s, 0, {0, 0, 0}, 90.0f);
    const Affine quarter = Affine::eulerDegrees({0, 90, 0});
    for (double seconds : {0.5, 1.0, 2.5}) {
        applyInstanceAnimations(s, seconds);
        const Affine animated = chainTransform(chain, seconds);
        const Vec3 origin = animated.point({0, 0, 0});
        expectNear(s.instances[0].transform.point({0, 0, 0}), origin);  // the patrol is unchanged
        // Every object-space direction comes out turned a further quarter about +y.
        for (Vec3 d : {Vec3{1, 0, 0}, Vec3{0, 0, 1}, Vec3{0, 1, 0}})
            expectNear(s.instances[0].transform.point(d) - origin, quarter.vector(animated.vector(d)));
    }
}

TEST(InstanceEdit, AKeyframedGltfNodeKeepsTheMoveToo) {
    const std::vector<NodeMotion> chain = {keyedLift()};
    Scene s = oneInstance(Affine{}, chain);
    applyInstanceAnimations(s, 0.0);
    moveInstance(s, 0, {5, 0, 0}, 0.0f);
    applyInstanceAnimations(s, 1.0);
    expectNear(s.instances[0].transform.point({0, 0, 0}), {5, 2, 0});
    applyInstanceAnimations(s, 2.0);
    expectNear(s.instances[0].transform.point({0, 0, 0}), {5, 4, 0});
}

TEST(InstanceEdit, MovesAddUpInEitherClockOrder) {
    // Two moves, the animation applied between them or not, end where one combined edit puts it.
    const std::vector<NodeMotion> chain = {patrol()};
    Scene a = oneInstance(Affine{}, chain), b = oneInstance(Affine{}, chain);
    moveInstance(a, 0, {1, 0, 0}, 30.0f);
    applyInstanceAnimations(a, 0.7);
    moveInstance(a, 0, {0, -2, 0.5f}, -75.0f);
    applyInstanceAnimations(a, 1.9);
    Affine combined = Affine::eulerDegrees({0, -45, 0});
    combined.m[0][3] = 1, combined.m[1][3] = -2, combined.m[2][3] = 0.5f;
    b.instanceAnimations[0].userEdit = combined;
    applyInstanceAnimations(b, 1.9);
    for (Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 2, 3}})
        expectNear(a.instances[0].transform.point(p), b.instances[0].transform.point(p));
}

TEST(InstanceEdit, OtherInstancesAndRenderTimeAreUntouched) {
    const std::vector<NodeMotion> chain = {patrol()};
    Scene s = oneInstance(Affine{}, chain);
    s.instances.push_back({0, Affine::translation({0, 0, -5})});
    s.instanceAnimations.push_back({1, chain, Affine{}});
    moveInstance(s, 0, {0, 7, 0}, 0.0f);
    applyInstanceAnimations(s, 1.0);
    expectNear(s.instances[1].transform.point({0, 0, 0}), chainTransform(chain, 1.0).point({0, 0, 0}));
    // A scene as loaded (no edits) renders the moment the animation says (render --time).
    const Scene fresh = sceneAtTime(oneInstance(Affine{}, chain), 1.0);
    expectNear(fresh.instances[0].transform.point({0, 0, 0}), chainTransform(chain, 1.0).point({0, 0, 0}));
}

}  // namespace
}  // namespace penumbra::test
