// Two-level scenes on the CPU: the reference traversal over instances against brute force and
// against the same world with every instance baked into world meshes; moving an instance (top
// level rebuilt) against building everything again; memory of many instances; emitters baked.
#include <gtest/gtest.h>

#include <random>

#include "bvh/two_level.h"
#include "core/error.h"
#include "instanced_world.h"
#include "render/gpu_scene.h"
#include "render/instance_arrays.h"

namespace penumbra {
namespace {

bvh::TwoLevelView view(const SceneArrays& a) { return {a.nodes, a.triVerts, a.instances, a.topRoot}; }

// Rays from around the room toward random points of it.
std::vector<Ray> roomRays(std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> x(-2.5f, 2.5f), y(-0.2f, 2.6f);
    std::vector<Ray> rays;
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 from{x(rng), y(rng), x(rng) + 1.0f}, to{x(rng) * 0.6f, y(rng) * 0.6f, x(rng) * 0.6f};
        rays.push_back({from, to - from});
    }
    return rays;
}

TEST(Instances, TwoLevelTraversalMatchesBruteForceOverInstances) {
    const SceneArrays a = buildSceneArrays(test::instancedRoom());
    ASSERT_EQ(a.instances.size(), 6u);  // the world, then five spheres
    std::size_t hits = 0;
    for (const Ray& ray : roomRays(3000, 1)) {
        const bvh::Hit fast = bvh::closestHit(view(a), ray), brute = bvh::closestHitBrute(view(a), ray);
        ASSERT_EQ(fast.triangle, brute.triangle);
        ASSERT_EQ(fast.instance, brute.instance);
        ASSERT_EQ(fast.t, brute.t);
        EXPECT_EQ(bvh::anyHit(view(a), ray), brute.triangle != PN_NO_HIT);
        hits += fast.instance != PN_NO_HIT && fast.instance > 0;
    }
    EXPECT_GT(hits, 300u) << "too few rays reach the instances for the test to mean much";
}

TEST(Instances, HitsAreThoseOfTheBakedWorld) {
    const SceneArrays instanced = buildSceneArrays(test::instancedRoom());
    const SceneArrays flat = buildSceneArrays(test::baked(test::instancedRoom()));
    ASSERT_TRUE(flat.instances.empty());
    std::size_t disagree = 0, total = 0;
    for (const Ray& ray : roomRays(3000, 2)) {
        const bvh::Hit a = bvh::closestHit(view(instanced), ray);
        const bvh::Hit b = bvh::closestHit(flat.nodes, flat.triVerts, ray);
        ++total;
        // Rays through a shared edge may pick either side's triangle after rounding: compare t.
        if ((a.triangle == PN_NO_HIT) != (b.triangle == PN_NO_HIT) ||
            (a.triangle != PN_NO_HIT && std::abs(a.t - b.t) > 1e-4f * std::max(1.0f, b.t)))
            ++disagree;
    }
    EXPECT_LE(disagree, total / 1000) << disagree << " of " << total << " rays see another surface";
}

TEST(Instances, MovingAnInstanceGivesTheHitsOfARebuild) {
    Scene scene = test::instancedRoom();
    SceneArrays moved = buildSceneArrays(scene);
    const Affine elsewhere = Affine::translation({0.4f, 0.6f, 0.5f}) * Affine::eulerDegrees({10, 80, 0}) *
                             Affine::scaling({0.4f, 0.2f, 0.3f});
    // Instance 0 of the arrays is the world's own geometry; the scene's instance 2 is entry 3.
    ASSERT_EQ(moved.instances[3].id, 2u);
    setInstanceTransform(moved, 3, elsewhere);
    scene.instances[2].transform = elsewhere;
    const SceneArrays rebuilt = buildSceneArrays(scene);
    std::size_t onMoved = 0;
    for (const Ray& ray : roomRays(3000, 3)) {
        const bvh::Hit a = bvh::closestHit(view(moved), ray), b = bvh::closestHit(view(rebuilt), ray);
        ASSERT_EQ(a.triangle, b.triangle);
        ASSERT_EQ(a.instance, b.instance);
        ASSERT_EQ(a.t, b.t);
        onMoved += a.instance == 3;
    }
    EXPECT_GT(onMoved, 20u);
}

// Above kMortonTopLevelAbove instances the top level is the Morton build, rebuilt into reused
// buffers: moving instances still gives the hits of building everything again, and of brute force.
TEST(Instances, MovingOneOfThousandsGivesTheHitsOfARebuild) {
    Scene scene = test::instancedRoom(1, 3, 4);
    for (int k = 0; k < 3000; ++k) {  // small spheres on a 15 x 10 x 20 grid filling the room
        const Vec3 at{-1.8f + 0.25f * float(k % 15), 0.1f + 0.24f * float((k / 15) % 10), -1.9f + 0.19f * float(k / 150)};
        scene.instances.push_back({0, Affine::translation(at) * Affine::scaling(Vec3{0.06f})});
    }
    SceneArrays moved = buildSceneArrays(scene);
    ASSERT_GT(moved.instances.size(), bvh::kMortonTopLevelAbove);
    // Two rebuilds into the warm buffers, then one from scratch.
    for (std::uint32_t entry : {40u, 1777u}) {
        const std::uint32_t id = moved.instances[entry].id;
        const Affine elsewhere = Affine::translation({0.1f * float(entry % 7), 1.2f, 0.3f}) *
                                 Affine::eulerDegrees({30, float(entry), 0}) * Affine::scaling({0.4f, 0.2f, 0.3f});
        setInstanceTransform(moved, entry, elsewhere);
        scene.instances[id].transform = elsewhere;
    }
    const SceneArrays rebuilt = buildSceneArrays(scene);
    ASSERT_EQ(moved.nodes.size(), rebuilt.nodes.size());
    std::size_t onMoved = 0, index = 0;
    for (const Ray& ray : roomRays(3000, 4)) {
        const bvh::Hit a = bvh::closestHit(view(moved), ray), b = bvh::closestHit(view(rebuilt), ray);
        ASSERT_EQ(a.triangle, b.triangle);
        ASSERT_EQ(a.instance, b.instance);
        ASSERT_EQ(a.t, b.t);
        onMoved += a.instance == 40 || a.instance == 1777;
        if (index++ % 20 == 0) {  // brute force over 3,000 instances is slow: every 20th ray
            const bvh::Hit brute = bvh::closestHitBrute(view(moved), ray);
            ASSERT_EQ(a.triangle, brute.triangle);
            ASSERT_EQ(a.instance, brute.instance);
        }
    }
    EXPECT_GT(onMoved, 20u);
}

TEST(Instances, AHundredInstancesCostLessThanTwiceTheMemoryOfOne) {
    // A sphere of 3,840 triangles (the bunny's 70,000 would only make the margin larger).
    const std::size_t one = deviceBytes(buildSceneArrays(test::instancedRoom(1, 40, 48)));
    const std::size_t hundred = deviceBytes(buildSceneArrays(test::instancedRoom(100, 40, 48)));
    const std::size_t duplicated = deviceBytes(buildSceneArrays(test::baked(test::instancedRoom(100, 40, 48))));
    EXPECT_LT(hundred, 2 * one);
    EXPECT_GT(duplicated, 10 * one) << "the mesh is too small to show what instancing saves";
}

TEST(Instances, EmissivePrototypesAreBakedIntoWorldLights) {
    Scene scene = test::instancedRoom(3);
    scene.materials[scene.prototypes[0].meshes[0].material].emission = Vec3{1.0f};
    const SceneArrays a = buildSceneArrays(scene);
    EXPECT_TRUE(a.instances.empty()) << "emitters must stay world-space triangles";
    const SceneArrays flat = buildSceneArrays(test::baked(scene));
    EXPECT_EQ(a.lightRefs.size(), flat.lightRefs.size());
    EXPECT_EQ(a.triVerts.size(), flat.triVerts.size());
}

// An emitter light sampling does not aim at (glowing eyes) may stay an instance; instances keep
// the scene's own numbers when emissive ones before them were baked (the viewer moves them by it).
TEST(Instances, UnsampledEmittersStayInstancesAndNumbersSurviveBaking) {
    Scene scene = test::instancedRoom(3);
    const std::uint32_t sphereMaterial = scene.prototypes[0].meshes[0].material;
    Material glow = scene.materials[sphereMaterial];
    glow.emission = Vec3{2.0f};
    glow.lightSampled = false;
    scene.materials.push_back(glow);
    scene.prototypes.push_back(scene.prototypes[0]);
    scene.prototypes[1].meshes[0].material = std::uint32_t(scene.materials.size() - 1);
    scene.instances[2].prototype = 1;
    EXPECT_EQ(buildSceneArrays(scene).instances.size(), 4u);  // the world and three instances
    // Now a sampled emitter as instance 0: baked; instances 1 and 2 keep their numbers.
    Material lamp = glow;
    lamp.lightSampled = true;
    scene.materials.push_back(lamp);
    scene.prototypes.push_back(scene.prototypes[0]);
    scene.prototypes[2].meshes[0].material = std::uint32_t(scene.materials.size() - 1);
    scene.instances[0].prototype = 2;
    const SceneArrays a = buildSceneArrays(scene);
    std::vector<std::uint32_t> ids;
    for (const shader::Instance& i : a.instances) ids.push_back(i.id);
    EXPECT_EQ(ids, (std::vector<std::uint32_t>{PN_NO_HIT, 1u, 2u}));
}

TEST(Instances, ASceneWithoutInstancesKeepsItsFlatArrays) {
    const SceneArrays a = buildSceneArrays(test::baked(test::instancedRoom()));
    EXPECT_TRUE(a.instances.empty());
    EXPECT_EQ(a.topRoot, 0u);
    EXPECT_EQ(a.bottomNodeCount, 0u);
}

// The measurement aid (PENUMBRA_FORCE_INSTANCES): the world's meshes as one identity instance give
// exactly the flat BVH's hits (an identity transform rounds nothing).
TEST(Instances, TheWorldAsOneIdentityInstanceChangesNoHit) {
    const Scene flatScene = test::baked(test::instancedRoom());
    Scene instanced = flatScene;
    instanceWorldMeshes(instanced);
    ASSERT_EQ(instanced.instances.size(), 1u);
    EXPECT_EQ(instanced.meshes.size(), 1u) << "the emissive panel stays a world mesh";
    const SceneArrays flat = buildSceneArrays(flatScene), two = buildSceneArrays(instanced);
    ASSERT_EQ(two.instances.size(), 2u);
    for (const Ray& ray : roomRays(2000, 4)) {
        const bvh::Hit a = bvh::closestHit(flat.nodes, flat.triVerts, ray), b = bvh::closestHit(view(two), ray);
        ASSERT_EQ(a.triangle == PN_NO_HIT, b.triangle == PN_NO_HIT);
        if (a.triangle != PN_NO_HIT) {
            EXPECT_EQ(a.t, b.t);
        }
    }
}

TEST(Instances, InvalidTransformsAreRejected) {
    Scene scene = test::instancedRoom(1);
    scene.instances[0].transform = Affine::scaling({1, 0, 1});
    EXPECT_THROW(scene.validate(), Error);
    scene.instances[0] = {7, Affine{}};
    EXPECT_THROW(scene.validate(), Error);
}

}  // namespace
}  // namespace penumbra
