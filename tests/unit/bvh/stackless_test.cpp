// Escape indices (bvh/stackless.h): the threaded tree's structure, and the stackless walk's hits
// against the stack walk and brute force, on random soups and a degenerate median-split tree.
#include <gtest/gtest.h>

#include "bvh/stackless.h"
#include "core/error.h"
#include "bvh_test_util.h"
#include "median_split.h"

namespace penumbra::bvh {
namespace {

using test::Prepared;

std::vector<shader::StacklessNode> thread(const Bvh& bvh) {
    const std::uint32_t roots[] = {0u};
    return threadNodes(bvh.nodes, roots);
}

// Following hits from the root (never missing) visits every node once, in depth-first order,
// and ends at PN_STACKLESS_END; each leaf carries its BvhNode's primitives.
void expectThreadedDepthFirst(const Bvh& bvh, const std::vector<shader::StacklessNode>& t) {
    ASSERT_EQ(t.size(), bvh.nodes.size());
    std::uint32_t current = 0, visited = 0;
    while (current != PN_STACKLESS_END) {
        ASSERT_EQ(current, visited) << "depth-first order is index order";
        ASSERT_LT(visited++, t.size());
        const shader::BvhNode& n = bvh.nodes[current];
        if (n.triCount > 0) {
            EXPECT_EQ(t[current].leaf >> PN_STACKLESS_COUNT_BITS, n.firstOrRight);
            EXPECT_EQ(t[current].leaf & PN_STACKLESS_COUNT_MASK, n.triCount);
            current = t[current].escape;
        } else {
            EXPECT_EQ(t[current].leaf, 0u);
            // A left child escapes to its sibling: missing it goes straight to the right child.
            EXPECT_EQ(t[current + 1].escape, n.firstOrRight);
            EXPECT_EQ(t[n.firstOrRight].escape, t[current].escape);
            current += 1;
        }
    }
    EXPECT_EQ(visited, t.size());
    EXPECT_EQ(t[0].escape, PN_STACKLESS_END);
}

void expectMatchesStackWalk(const Prepared& p, const std::vector<Ray>& rays) {
    const auto threaded = thread(p.bvh);
    expectThreadedDepthFirst(p.bvh, threaded);
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Hit stack = closestHit(p.bvh.nodes, p.leafTris, rays[i]);
        const Hit brute = closestHitBrute(p.leafTris, rays[i]);
        const Hit stackless = closestHitStackless(threaded, p.leafTris, rays[i]);
        ASSERT_EQ(stackless.triangle == PN_NO_HIT, brute.triangle == PN_NO_HIT) << "ray " << i;
        EXPECT_EQ(anyHitStackless(threaded, p.leafTris, rays[i]), brute.triangle != PN_NO_HIT) << "ray " << i;
        if (brute.triangle == PN_NO_HIT) continue;
        EXPECT_TRUE(test::sameT(stackless.t, brute.t)) << stackless.t << " vs " << brute.t << ", ray " << i;
        if (stackless.triangle == stack.triangle) {
            EXPECT_EQ(stackless.t, stack.t) << "ray " << i;
        }
    }
}

TEST(Stackless, RandomSoupsMatchTheStackWalkAndBruteForce) {
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        for (std::size_t n : {1u, 2u, 7u, 64u, 500u, 5000u}) {
            SCOPED_TRACE(::testing::Message() << "seed " << seed << " n " << n);
            Prepared p = test::prepare(test::randomSoup(n, seed));
            expectMatchesStackWalk(p, test::mixedRays(p.tris, 1500, seed * 7 + 1));
            if (HasFailure()) return;
        }
    }
}

TEST(Stackless, MedianSplitTreeMatchesBruteForce) {
    Prepared p = test::prepare(test::randomSoup(3000, 31));
    p.bvh = test::buildMedianSplit(test::boxesOf(p.tris), 3);
    p.leafTris = leafOrderTriVerts(p.bvh, p.tris);
    expectMatchesStackWalk(p, test::mixedRays(p.tris, 2000, 32));
}

// Without a stack the walk still prunes: far fewer primitive tests than brute force's 5000 per ray.
TEST(Stackless, TestsFarFewerPrimitivesThanBruteForce) {
    Prepared p = test::prepare(test::randomSoup(5000, 41));
    const auto threaded = thread(p.bvh);
    TraversalCounts counts;
    const auto rays = test::mixedRays(p.tris, 500, 42);
    for (const Ray& r : rays) closestHitStackless(threaded, p.leafTris, r, &counts);
    EXPECT_LT(counts.trianglesTested, rays.size() * 5000 / 20);
}

TEST(Stackless, ALeafTooLargeForItsWordIsAnErrorNotACorruptTree) {
    Bvh bvh;
    shader::BvhNode leaf{};
    leaf.triCount = PN_STACKLESS_COUNT_MASK + 1;
    bvh.nodes.push_back(leaf);
    EXPECT_THROW(thread(bvh), penumbra::Error);
}

TEST(Stackless, AnEmptyTreeNeverHits) {
    const std::vector<shader::StacklessNode> none;
    const std::vector<shader::TriVerts> tris;
    const Ray ray{{0, 0, 0}, {0, 0, 1}};
    EXPECT_EQ(closestHitStackless(none, tris, ray).triangle, PN_NO_HIT);
    EXPECT_FALSE(anyHitStackless(none, tris, ray));
}

}  // namespace
}  // namespace penumbra::bvh
