// The GPU walk's records (bvh/child_pairs.h): each interior node's record holds its children's
// indices and boxes, and those two boxes together make the node's own; a leaf's holds its
// primitives; a top level converted on its own (after its bottom levels) gives the records a whole
// conversion gives there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "bvh/child_pairs.h"
#include "bvh/triangle.h"
#include "bvh_test_util.h"

namespace penumbra::bvh {
namespace {

TEST(ChildPairs, EveryRecordHoldsItsChildrenWhoseBoxesMakeTheNodes) {
    const Bvh tree = buildTriangles(test::randomSoup(2000, 5));
    const std::vector<shader::BvhPair> pairs = childPairs(tree.nodes);
    ASSERT_EQ(pairs.size(), tree.nodes.size());
    std::size_t leaves = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const shader::BvhNode& node = tree.nodes[i];
        const shader::BvhPair& p = pairs[i];
        if (node.triCount > 0) {
            EXPECT_EQ(p.leafCount, node.triCount) << i;
            EXPECT_EQ(p.left, node.firstOrRight) << i;
            ++leaves;
            continue;
        }
        EXPECT_EQ(p.leafCount, 0u) << i;
        EXPECT_EQ(p.left, i + 1) << i;
        EXPECT_EQ(p.right, node.firstOrRight) << i;
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_EQ(std::min(p.leftMin[axis], p.rightMin[axis]), node.boundsMin[axis]) << i;
            EXPECT_EQ(std::max(p.leftMax[axis], p.rightMax[axis]), node.boundsMax[axis]) << i;
        }
    }
    EXPECT_EQ(leaves * 2 - 1, pairs.size());  // a binary tree
}

TEST(ChildPairs, AConvertedTailMatchesTheWholeConversion) {
    const Bvh tree = buildTriangles(test::randomSoup(500, 9));
    const std::vector<shader::BvhPair> whole = childPairs(tree.nodes);
    // The right subtree of the root stands for a top level stored after its bottom levels.
    const std::size_t first = tree.nodes[0].firstOrRight;
    std::vector<shader::BvhPair> tail(tree.nodes.size() - first);
    writeChildPairs(tree.nodes, first, tail);
    for (std::size_t k = 0; k < tail.size(); ++k)
        EXPECT_EQ(std::memcmp(&tail[k], &whole[first + k], sizeof(shader::BvhPair)), 0) << k;
}

}  // namespace
}  // namespace penumbra::bvh
