// The rest tree (render/rest_tree.h) on the CPU: while every instance lies where it was modelled,
// its flat walk finds what brute force over the two levels finds; it is built only then; a door
// that moves leaves it to the two-level walk, and coming back to rest finds it intact.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "bvh/two_level.h"
#include "instanced_world.h"
#include "render/gpu_scene.h"
#include "render/instance_arrays.h"
#include "render/rest_tree.h"

namespace penumbra {
namespace {

bvh::TwoLevelView view(const SceneArrays& a) { return {a.nodes, a.triVerts, a.instances, a.topRoot}; }

// Rays from the room's open side toward points in it (through the doorway too).
std::vector<Ray> rays(std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> x(-2.0f, 2.0f), y(0.05f, 2.4f), z(-1.8f, 1.8f);
    std::vector<Ray> out;
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 from{x(rng), y(rng), 2.5f}, to{x(rng), y(rng), z(rng) - 0.5f};
        out.push_back({from, to - from});
    }
    return out;
}

// The rest tree's hits are brute force's over the two levels: the same distance, or both a miss
// (a ray through a shared edge may name either triangle). Returns the rays that hit a mover.
std::size_t expectRestTreeMatchesBruteForce(const SceneArrays& a) {
    std::size_t onMovers = 0;
    for (const Ray& ray : rays(3000, 7)) {
        const bvh::Hit flat = bvh::closestHitBelow(a.nodes, a.triVerts, a.restRoot, ray);
        const bvh::Hit brute = bvh::closestHitBrute(view(a), ray);
        EXPECT_EQ(flat.triangle == PN_NO_HIT, brute.triangle == PN_NO_HIT);
        if (brute.triangle == PN_NO_HIT) continue;
        EXPECT_EQ(flat.t, brute.t);
        onMovers += brute.instance != PN_NO_HIT && a.instances[brute.instance].id != PN_NO_HIT;
    }
    return onMovers;
}

TEST(RestTree, ItsFlatWalkFindsWhatTheTwoLevelsHold) {
    const SceneArrays a = buildSceneArrays(test::moversAtRest());
    ASSERT_EQ(a.instances.size(), 3u);  // the world, the door, the lift
    ASSERT_NE(a.restRoot, PN_NO_HIT);
    EXPECT_LT(a.restRoot, a.bottomNodeCount) << "the top level's rebuilds would overwrite it";
    EXPECT_TRUE(atRest(a));
    EXPECT_GT(expectRestTreeMatchesBruteForce(a), 100u) << "too few rays reach the movers to mean much";
}

TEST(RestTree, ADoorThatMovesLeavesItAndFindsItIntactBackAtRest) {
    Scene scene = test::moversAtRest();
    SceneArrays a = buildSceneArrays(scene);
    const std::vector<shader::BvhNode> before(a.nodes.begin(), a.nodes.begin() + a.bottomNodeCount);
    scene.instances[0].transform = test::doorRaised(1.2f);
    ASSERT_TRUE(moveInstances(a, scene));
    EXPECT_FALSE(atRest(a)) << "the door is up: the rest tree no longer holds";
    for (const Ray& ray : rays(1000, 8)) {  // the two levels walk the raised door
        const bvh::Hit walk = bvh::closestHit(view(a), ray), brute = bvh::closestHitBrute(view(a), ray);
        ASSERT_EQ(walk.t, brute.t);
    }
    scene.instances[0].transform = test::doorRaised(0.0f);
    ASSERT_TRUE(moveInstances(a, scene));
    EXPECT_TRUE(atRest(a));
    const std::vector<shader::BvhNode> after(a.nodes.begin(), a.nodes.begin() + a.bottomNodeCount);
    EXPECT_EQ(std::memcmp(before.data(), after.data(), before.size() * sizeof(shader::BvhNode)), 0);
    expectRestTreeMatchesBruteForce(a);
}

TEST(RestTree, OnlyScenesWhoseInstancesAllRestHaveOne) {
    EXPECT_EQ(buildSceneArrays(test::instancedRoom()).restRoot, PN_NO_HIT);  // placed spheres
    Scene raised = test::moversAtRest();
    raised.instances[1].transform = test::doorRaised(0.5f);
    EXPECT_EQ(buildSceneArrays(raised).restRoot, PN_NO_HIT);
    EXPECT_EQ(buildSceneArrays(test::baked(test::moversAtRest())).restRoot, PN_NO_HIT);  // flat
}

}  // namespace
}  // namespace penumbra
