// Two-level BVHs on the CPU: bottom levels over random soups, instances with affine transforms
// (mirrors and shears included), traversal against brute force over instances x triangles and
// against one flat BVH over the transformed triangles.
#include <gtest/gtest.h>

#include <cstring>

#include "bvh/two_level.h"
#include "bvh_test_util.h"
#include "core/parallel.h"

namespace penumbra::bvh {
namespace {

struct TwoLevel {
    std::vector<shader::BvhNode> nodes;
    std::vector<shader::TriVerts> tris;
    std::vector<shader::Instance> instances;
    std::uint32_t topRoot = 0;
    TwoLevelView view() const { return {nodes, tris, instances, topRoot}; }
};

Affine placement(int k) {
    Affine shear;
    shear.m[0][1] = 0.3f * float(k % 3);
    return Affine::translation({1.5f * float(k % 4), 0.7f * float(k / 4), -0.5f * float(k % 3)}) *
           Affine::eulerDegrees({17.0f * float(k), 31.0f * float(k), 0}) * shear *
           Affine::scaling({k % 5 == 2 ? -0.8f : 0.8f, 1.0f + 0.1f * float(k), 0.9f});
}

TEST(TwoLevel, InverseUndoesTheTransform) {
    for (int k = 0; k < 8; ++k) {
        const Affine t = placement(k), inv = t.inverse();
        const Vec3 p{0.3f, -1.2f, 2.5f};
        EXPECT_LT(length(inv.point(t.point(p)) - p), 1e-5f);
    }
}

TEST(TwoLevel, TraversalMatchesBruteForceAndTheFlattenedScene) {
    const std::vector<std::vector<Triangle>> meshes = {test::randomSoup(300, 1), test::randomSoup(150, 2)};
    TwoLevel s;
    std::vector<std::uint32_t> roots, firsts;
    std::vector<Aabb> localBounds;
    for (const auto& mesh : meshes) {
        const Bvh b = buildTriangles(mesh);
        firsts.push_back(std::uint32_t(s.tris.size()));
        roots.push_back(appendBottomLevel(s.nodes, b, firsts.back()));
        for (const auto& t : leafOrderTriVerts(b, mesh)) s.tris.push_back(t);
        localBounds.push_back(test::boundsOf(mesh));
    }
    std::vector<Triangle> flat;
    std::vector<Aabb> worldBounds;
    for (int k = 0; k < 10; ++k) {
        const std::size_t m = std::size_t(k % 2);
        s.instances.push_back(makeInstance(placement(k), roots[m], firsts[m], std::uint32_t(meshes[m].size()), std::uint32_t(k)));
        worldBounds.push_back(transformBounds(localBounds[m], placement(k)));
        for (const Triangle& t : meshes[m])
            flat.push_back({placement(k).point(t.v0), placement(k).point(t.v1), placement(k).point(t.v2)});
    }
    const auto top = buildTopLevel(worldBounds, std::uint32_t(s.nodes.size()));
    s.topRoot = std::uint32_t(s.nodes.size());
    s.nodes.insert(s.nodes.end(), top.begin(), top.end());
    const test::Prepared reference = test::prepare(flat);

    std::size_t hits = 0, disagree = 0;
    const auto rays = test::mixedRays(flat, 4000, 9);
    for (const Ray& ray : rays) {
        const Hit fast = closestHit(s.view(), ray), brute = closestHitBrute(s.view(), ray);
        ASSERT_EQ(fast.triangle, brute.triangle);
        ASSERT_EQ(fast.instance, brute.instance);
        ASSERT_EQ(fast.t, brute.t);
        ASSERT_EQ(anyHit(s.view(), ray), brute.triangle != PN_NO_HIT);
        const Hit world = closestHit(reference.bvh.nodes, reference.leafTris, ray);
        if ((world.triangle == PN_NO_HIT) != (fast.triangle == PN_NO_HIT) ||
            (world.triangle != PN_NO_HIT && std::abs(world.t - fast.t) > 1e-4f * std::max(1.0f, world.t)))
            ++disagree;
        hits += fast.triangle != PN_NO_HIT;
    }
    EXPECT_GT(hits, rays.size() / 4);
    // The instance's ray is the world ray through the inverse transform: rounding may let a ray
    // that grazes an edge hit or miss it.
    EXPECT_LE(disagree, rays.size() / 500);
}

TEST(TwoLevel, TopLevelLeavesHoldOneInstanceEach) {
    std::vector<Aabb> boxes;
    for (int k = 0; k < 100; ++k) boxes.push_back(Aabb{Vec3{float(k)}, Vec3{float(k) + 0.5f}});
    const auto top = buildTopLevel(boxes, 1000);
    std::vector<int> seen(boxes.size(), 0);
    for (const auto& n : top) {
        if (n.triCount == 0) {
            EXPECT_GE(n.firstOrRight, 1000u);
            continue;
        }
        ASSERT_EQ(n.triCount, 1u);
        ASSERT_LT(n.firstOrRight, boxes.size());
        ++seen[n.firstOrRight];
    }
    for (int s : seen) EXPECT_EQ(s, 1);
}

// The per-frame rebuild of 10,000 instances on the worker pool (boxes through the transforms and
// the Morton build in parallel) writes the nodes the one-thread rebuild writes, to the bit, into
// warm buffers too.
TEST(TwoLevel, PooledTopLevelRebuildIsTheSerialOneToTheBit) {
    std::vector<shader::Instance> instances;
    std::vector<Aabb> objectBounds;
    for (int k = 0; k < 10000; ++k) {
        instances.push_back(makeInstance(Affine::translation({0.01f * float(k % 100), 0.0f, 0.02f * float(k / 100)}) *
                                             placement(k % 16),
                                         0, 0, 1, std::uint32_t(k)));
        Aabb b;
        b.grow(Vec3{-1.0f, -0.5f * float(k % 3), -0.8f});
        b.grow(Vec3{1.0f, 1.5f, 0.8f + 0.1f * float(k % 5)});
        objectBounds.push_back(b);
    }
    std::vector<shader::BvhNode> serial(37), pooled(37);  // stand-ins for bottom levels
    TopLevelScratch serialScratch, pooledScratch;
    ThreadArena four(4);
    for (int frame = 0; frame < 2; ++frame) {
        instances[std::size_t(frame) * 977].objectToWorld[1].w += 3.0f;  // an instance moves
        replaceTopLevel(serial, 37, instances, objectBounds, serialScratch, BuildThreads::One);
        four.run([&] { replaceTopLevel(pooled, 37, instances, objectBounds, pooledScratch, BuildThreads::Pool); });
        ASSERT_EQ(serial.size(), pooled.size());
        EXPECT_EQ(serial.size(), 37u + 2 * instances.size() - 1);
        EXPECT_EQ(std::memcmp(serial.data(), pooled.data(), serial.size() * sizeof(shader::BvhNode)), 0)
            << "frame " << frame;
    }
}

}  // namespace
}  // namespace penumbra::bvh
