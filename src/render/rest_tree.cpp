#include "render/rest_tree.h"

#include <algorithm>
#include <vector>

#include "bvh/depth_boxes.h"
#include "bvh/two_level.h"
#include "render/tuning.h"

namespace penumbra {
namespace {

struct Leaf {
    std::uint32_t first, count;
    Aabb box;
};

// Every leaf of the tree at `root` (depth first, left child next: the builder's layout).
void collectLeaves(const std::vector<shader::BvhNode>& nodes, std::uint32_t root, std::vector<Leaf>& out) {
    std::vector<std::uint32_t> pending{root};
    while (!pending.empty()) {
        const std::uint32_t n = pending.back();
        pending.pop_back();
        const shader::BvhNode& node = nodes.at(n);
        if (node.triCount == 0) {
            pending.push_back(node.firstOrRight);
            pending.push_back(n + 1);
            continue;
        }
        Aabb box;
        box.grow(node.boundsMin);
        box.grow(node.boundsMax);
        out.push_back({node.firstOrRight, node.triCount, box});
    }
}

bool isIdentity(const shader::Instance& i) { return (i.rootNode & PN_INSTANCE_IDENTITY) != 0; }

}  // namespace

void appendRestTree(SceneArrays& a) {
    a.restRoot = PN_NO_HIT;
    if (!renderTuning().restTree || renderTuning().forceInstances || a.instances.size() < 2) return;
    if (!std::all_of(a.instances.begin(), a.instances.end(), isIdentity)) return;
    // Each instance's leaves as they lie (identity: object space is world space). Two instances of
    // one prototype at rest would share their leaves' slots: listed twice, they hit alike.
    std::vector<Leaf> leaves;
    for (const shader::Instance& i : a.instances) collectLeaves(a.nodes, bvh::instanceRoot(i), leaves);
    std::vector<Aabb> boxes(leaves.size());
    std::transform(leaves.begin(), leaves.end(), boxes.begin(), [](const Leaf& l) { return l.box; });
    // A tree over the boxes whose leaves each hold one box (index k); each becomes leaf k's slots.
    std::vector<shader::BvhNode> tree = bvh::buildTopLevel(boxes, 0);
    // Flat walks keep a stack of PN_BVH_STACK_SIZE; a tree deeper than the builder's bound (never
    // seen: the boxes are small and many) leaves the scene to its two levels.
    if (bvh::treeDepth(tree) > PN_BVH_MAX_DEPTH) return;
    const auto base = static_cast<std::uint32_t>(a.nodes.size());
    for (shader::BvhNode& n : tree) {
        if (n.triCount == 0) {
            n.firstOrRight += base;
            continue;
        }
        const Leaf& leaf = leaves.at(n.firstOrRight);
        n.firstOrRight = leaf.first;
        n.triCount = leaf.count;
    }
    a.nodes.insert(a.nodes.end(), tree.begin(), tree.end());
    a.restRoot = base;
}

bool atRest(const SceneArrays& a) {
    return a.restRoot != PN_NO_HIT && std::all_of(a.instances.begin(), a.instances.end(), isIdentity);
}

void walkRestTree(shader::FrameUniforms& frame, const SceneArrays& a) {
    frame.instanceCount = 0;
    frame.topRoot = a.restRoot;
}

}  // namespace penumbra
