// The Morton (linear) BVH builder: a valid tree over random soups, degenerate inputs (every box
// at one point, empty and non-finite boxes), closest hits equal to brute force, and its SAH cost
// against the binned-SAH build's (a worse tree, but not a broken one).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "bvh/morton_build.h"
#include "bvh/stats.h"
#include "bvh/validate.h"
#include "bvh_test_util.h"
#include "core/parallel.h"

namespace penumbra::bvh {
namespace {

TEST(MortonBuild, ValidOnRandomAndDegenerateInputs) {
    for (std::size_t n : {1u, 2u, 3u, 17u, 1000u}) {
        const std::vector<Aabb> boxes = test::boxesOf(test::randomSoup(n, std::uint32_t(n)));
        const Bvh bvh = buildMorton(boxes);
        validate(bvh, boxes);
        EXPECT_EQ(bvh.nodes.size(), 2 * n - 1);
    }
    // Every box the same point: the codes are all equal, median splits keep it balanced.
    std::vector<Aabb> same(5000);
    for (Aabb& b : same) b.grow(Vec3{1, 2, 3});
    const Bvh flat = buildMorton(same);
    validate(flat, same);
    EXPECT_LE(computeStats(flat, {}).maxDepth, 14u);
    // Empty and non-finite boxes are kept as points (sanitizedBounds), as build() does.
    std::vector<Aabb> odd = test::boxesOf(test::randomSoup(50, 3));
    odd[3] = Aabb{};
    odd[7].hi.x = std::numeric_limits<float>::infinity();
    odd[9].lo.y = std::numeric_limits<float>::quiet_NaN();
    validate(buildMorton(odd), odd);
    EXPECT_TRUE(buildMorton({}).nodes.empty());
}

TEST(MortonBuild, ClosestHitsMatchBruteForce) {
    test::Prepared p;
    p.tris = test::randomSoup(2000, 11);
    const std::vector<Aabb> boxes = test::boxesOf(p.tris);
    p.bvh = buildMorton(boxes);
    p.leafTris = leafOrderTriVerts(p.bvh, p.tris);
    for (const auto& t : p.tris) p.originalTris.push_back(toTriVerts(t));
    const std::vector<Ray> rays = test::mixedRays(p.tris, 300, 5);
    for (std::size_t i = 0; i < rays.size(); ++i) test::expectMatchesBrute(p, rays[i], i);
}

TEST(MortonBuild, TreeQualityIsWithinReachOfBinnedSah) {
    const std::vector<Aabb> boxes = test::boxesOf(test::randomSoup(10000, 21));
    BuildOptions one;
    one.maxLeafSize = 1;
    const double sah = computeStats(build(boxes, one), one).sahCost;
    const double morton = computeStats(buildMorton(boxes), one).sahCost;
    RecordProperty("sah_cost_binned", std::to_string(sah));
    RecordProperty("sah_cost_morton", std::to_string(morton));
    std::printf("SAH cost, one primitive per leaf: binned %.2f, Morton %.2f (x%.2f)\n", sah, morton, morton / sah);
    EXPECT_GE(morton, sah * 0.95);  // SAH-driven splits are the better tree...
    EXPECT_LE(morton, sah * 1.6);   // ...but a Morton tree is not far off on scattered boxes
}

bool sameBits(const std::vector<shader::BvhNode>& a, const std::vector<shader::BvhNode>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(shader::BvhNode)) == 0;
}

// The pooled build (keys, sort and subtrees in parallel) is the one-thread build to the bit, on
// 4 worker threads whatever the machine has, at sizes around the parallel grain and with many
// equal codes (median splits) and odd boxes.
TEST(MortonBuild, ParallelBuildIsTheSerialOneToTheBit) {
    ThreadArena four(4);
    for (std::size_t n : {2 * kMortonParallelGrain - 1, 2 * kMortonParallelGrain, std::size_t(9001), std::size_t(40000)}) {
        std::vector<Aabb> boxes = test::boxesOf(test::randomSoup(n, std::uint32_t(n) + 1));
        for (std::size_t i = 0; i < n; i += 7) boxes[i] = boxes[0];  // a cluster of equal codes
        boxes[5] = Aabb{};
        boxes[11].hi.x = std::numeric_limits<float>::infinity();
        const Bvh serial = buildMorton(boxes, BuildThreads::One);
        Bvh pooled;
        four.run([&] { pooled = buildMorton(boxes, BuildThreads::Pool); });
        EXPECT_TRUE(sameBits(serial.nodes, pooled.nodes)) << n << " boxes";
        EXPECT_EQ(serial.primOrder, pooled.primOrder) << n << " boxes";
        validate(pooled, boxes);
    }
}

}  // namespace
}  // namespace penumbra::bvh
