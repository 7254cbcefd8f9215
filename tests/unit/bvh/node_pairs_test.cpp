// The GPU's node pairs (bvh/node_pairs.h) hold exactly the binary tree: every child's bounds and
// leaf range, every leaf once, and a one-leaf tree as a pair of that leaf.
#include <gtest/gtest.h>

#include <map>

#include "bvh/builder.h"
#include "bvh/node_pairs.h"
#include "bvh_test_util.h"

namespace penumbra::bvh {
namespace {

void expectSameBox(Vec3 lo, Vec3 hi, const shader::BvhNode& n) {
    EXPECT_EQ(lo, n.boundsMin);
    EXPECT_EQ(hi, n.boundsMax);
}

// Walks the pairs from pair `p`, which stands for binary interior node `b`.
void walk(const Bvh& tree, const std::vector<shader::BvhNodePair>& pairs, std::uint32_t p, std::uint32_t b,
          std::map<std::uint32_t, std::uint32_t>& leaves) {
    const shader::BvhNodePair& pair = pairs.at(p);
    const std::uint32_t children[2] = {b + 1, tree.nodes[b].firstOrRight};
    const Vec3 lo[2] = {pair.leftMin, pair.rightMin}, hi[2] = {pair.leftMax, pair.rightMax};
    const std::uint32_t index[2] = {pair.leftIndex, pair.rightIndex}, count[2] = {pair.leftCount, pair.rightCount};
    for (int k = 0; k < 2; ++k) {
        const shader::BvhNode& c = tree.nodes[children[k]];
        expectSameBox(lo[k], hi[k], c);
        ASSERT_EQ(count[k], c.triCount);
        if (c.triCount > 0) {
            EXPECT_EQ(index[k], c.firstOrRight);
            EXPECT_TRUE(leaves.emplace(index[k], count[k]).second) << "leaf " << index[k] << " twice";
        } else {
            walk(tree, pairs, index[k], children[k], leaves);
        }
    }
}

TEST(NodePairs, HoldEveryChildOfTheBinaryTree) {
    for (std::size_t n : {2u, 7u, 1000u, 20000u}) {
        const Bvh tree = buildTriangles(test::randomSoup(n, 3));
        const auto pairs = toNodePairs(tree.nodes);
        std::size_t interior = 0;
        for (const shader::BvhNode& node : tree.nodes) interior += node.triCount == 0;
        ASSERT_EQ(pairs.size(), interior) << n << " triangles";
        std::map<std::uint32_t, std::uint32_t> leaves;
        walk(tree, pairs, 0, 0, leaves);
        std::uint32_t next = 0;
        for (auto [first, count] : leaves) {  // the leaves tile the triangles, in order
            EXPECT_EQ(first, next);
            next = first + count;
        }
        EXPECT_EQ(next, n);
    }
}

TEST(NodePairs, OneLeafTreeIsAPairOfThatLeaf) {
    const Bvh tree = buildTriangles(test::randomSoup(1, 5));
    ASSERT_EQ(tree.nodes.size(), 1u);
    const auto pairs = toNodePairs(tree.nodes);
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0].leftCount, 1u);
    EXPECT_EQ(pairs[0].rightCount, 1u);
    EXPECT_EQ(pairs[0].leftIndex, 0u);
    expectSameBox(pairs[0].leftMin, pairs[0].leftMax, tree.nodes[0]);
    EXPECT_TRUE(toNodePairs({}).empty());
}

}  // namespace
}  // namespace penumbra::bvh
