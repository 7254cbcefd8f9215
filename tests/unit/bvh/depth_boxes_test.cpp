// The overlay's boxes by depth, checked against the tree's own structure.
#include "bvh/depth_boxes.h"
#include "bvh_test_util.h"

namespace penumbra::bvh::test {
namespace {

bool inside(const shader::BvhNode& child, const shader::BvhNode& parent) {
    return child.boundsMin.x >= parent.boundsMin.x && child.boundsMin.y >= parent.boundsMin.y &&
           child.boundsMin.z >= parent.boundsMin.z && child.boundsMax.x <= parent.boundsMax.x &&
           child.boundsMax.y <= parent.boundsMax.y && child.boundsMax.z <= parent.boundsMax.z;
}

bool same(const shader::BvhNode& a, const shader::BvhNode& b) {
    return a.firstOrRight == b.firstOrRight && a.triCount == b.triCount && a.boundsMin.x == b.boundsMin.x &&
           a.boundsMax.x == b.boundsMax.x && a.boundsMin.y == b.boundsMin.y && a.boundsMax.z == b.boundsMax.z;
}

TEST(DepthBoxes, EveryNodeAppearsAtExactlyOneDepthInsideAParentOfTheDepthAbove) {
    const std::vector<Triangle> tris = randomSoup(300, 7);
    const Bvh tree = buildTriangles(tris);
    ASSERT_GT(tree.nodes.size(), 3u);
    const std::size_t depth = treeDepth(tree.nodes);
    ASSERT_GE(depth, 2u);

    const auto root = nodesAtDepth(tree.nodes, 0, 100);
    ASSERT_EQ(root.size(), 1u);
    EXPECT_TRUE(same(root[0], tree.nodes[0]));
    const auto children = nodesAtDepth(tree.nodes, 1, 100);
    ASSERT_EQ(children.size(), 2u);
    EXPECT_TRUE(same(children[0], tree.nodes[1]));  // the left child follows its parent
    EXPECT_TRUE(same(children[1], tree.nodes[tree.nodes[0].firstOrRight]));

    std::size_t total = 0;
    std::vector<shader::BvhNode> above;
    for (std::size_t d = 0; d <= depth; ++d) {
        const auto level = nodesAtDepth(tree.nodes, d, tree.nodes.size());
        EXPECT_FALSE(level.empty()) << d;
        total += level.size();
        for (const auto& n : level) {
            bool hasParent = d == 0;
            for (const auto& p : above) hasParent = hasParent || (p.triCount == 0 && inside(n, p));
            EXPECT_TRUE(hasParent) << "depth " << d;
        }
        above = level;
    }
    EXPECT_EQ(total, tree.nodes.size());  // the depths partition the nodes
    EXPECT_TRUE(nodesAtDepth(tree.nodes, depth + 1, 100).empty());
    EXPECT_EQ(nodesAtDepth(tree.nodes, depth, 1).size(), 1u);  // the cap holds
    EXPECT_TRUE(nodesAtDepth({}, 0, 10).empty());
}

}  // namespace
}  // namespace penumbra::bvh::test
