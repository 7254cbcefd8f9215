// The overlay's boxes by depth, checked against the tree's own structure, and the one depth
// convention (root: 1) shared by `penumbra info` (BvhStats) and the viewer (treeDepth).
#include "bvh/depth_boxes.h"
#include "bvh/stats.h"
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

    EXPECT_TRUE(nodesAtDepth(tree.nodes, 0, 100).empty());  // the root is depth 1
    const auto root = nodesAtDepth(tree.nodes, 1, 100);
    ASSERT_EQ(root.size(), 1u);
    EXPECT_TRUE(same(root[0], tree.nodes[0]));
    const auto children = nodesAtDepth(tree.nodes, 2, 100);
    ASSERT_EQ(children.size(), 2u);
    EXPECT_TRUE(same(children[0], tree.nodes[1]));  // the left child follows its parent
    EXPECT_TRUE(same(children[1], tree.nodes[tree.nodes[0].firstOrRight]));

    std::size_t total = 0;
    std::vector<shader::BvhNode> above;
    for (std::size_t d = 1; d <= depth; ++d) {
        const auto level = nodesAtDepth(tree.nodes, d, tree.nodes.size());
        EXPECT_FALSE(level.empty()) << d;
        total += level.size();
        for (const auto& n : level) {
            bool hasParent = d == 1;
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

shader::BvhNode node(float lo, float hi, std::uint32_t firstOrRight, std::uint32_t triCount) {
    shader::BvhNode n{};
    n.boundsMin = Vec3(lo, 0.0f, 0.0f);
    n.boundsMax = Vec3(hi, 1.0f, 1.0f);
    n.firstOrRight = firstOrRight;
    n.triCount = triCount;
    return n;
}

// A hand-built tree of three levels: root (0) -> interior 1 and leaf 4; 1 -> leaves 2 and 3.
// `penumbra info` prints BvhStats::maxDepth and the viewer's box slider tops out at treeDepth:
// both must say 3, and the slider's top must be the deepest level that still has boxes.
TEST(DepthBoxes, InfoAndTheViewerGiveAHandBuiltTreeTheSameDepth) {
    Bvh tree;
    tree.nodes = {node(0, 4, 4, 0), node(0, 2, 3, 0), node(0, 1, 0, 1), node(1, 2, 1, 1), node(2, 4, 2, 1)};
    tree.primOrder = {0, 1, 2};
    const std::size_t info = computeStats(tree, {}).maxDepth, viewer = treeDepth(tree.nodes);
    EXPECT_EQ(info, 3u);
    EXPECT_EQ(viewer, 3u);
    EXPECT_EQ(nodesAtDepth(tree.nodes, viewer, 10).size(), 2u);  // leaves 2 and 3
    EXPECT_TRUE(nodesAtDepth(tree.nodes, viewer + 1, 10).empty());

    // A lone leaf is one level; no nodes, none.
    Bvh leaf;
    leaf.nodes = {node(0, 1, 0, 1)};
    leaf.primOrder = {0};
    EXPECT_EQ(computeStats(leaf, {}).maxDepth, 1u);
    EXPECT_EQ(treeDepth(leaf.nodes), 1u);
    EXPECT_EQ(computeStats(Bvh{}, {}).maxDepth, 0u);
    EXPECT_EQ(treeDepth({}), 0u);
}

TEST(DepthBoxes, InfoAndTheViewerAgreeOnBuiltTrees) {
    for (std::size_t count : {1u, 2u, 300u, 5000u}) {
        const Bvh tree = buildTriangles(randomSoup(count, 11));
        EXPECT_EQ(computeStats(tree, {}).maxDepth, treeDepth(tree.nodes)) << count;
        EXPECT_FALSE(nodesAtDepth(tree.nodes, treeDepth(tree.nodes), 1).empty()) << count;
    }
}

}  // namespace
}  // namespace penumbra::bvh::test
