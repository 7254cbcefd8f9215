#include "bvh/stats.h"

#include <algorithm>
#include <vector>

#include "bvh/depth_boxes.h"

namespace penumbra::bvh {
namespace {

double halfArea(const shader::BvhNode& node) {
    Aabb box{node.boundsMin, node.boundsMax};
    return box.halfArea();
}

}  // namespace

BvhStats computeStats(const Bvh& bvh, const BuildOptions& options) {
    BvhStats stats;
    stats.nodes = bvh.nodes.size();
    if (bvh.nodes.empty()) return stats;
    stats.maxDepth = treeDepth(bvh.nodes);  // the viewer's figure too: one convention (depth_boxes.h)

    double interiorArea = 0, leafCost = 0;
    std::size_t prims = 0;
    // The nodes reachable from the root; an explicit stack because foreign trees may be deep.
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        const shader::BvhNode& node = bvh.nodes[stack.back()];
        const std::uint32_t index = stack.back();
        stack.pop_back();
        if (node.triCount > 0) {
            ++stats.leaves;
            prims += node.triCount;
            stats.maxLeafSize = std::max<std::size_t>(stats.maxLeafSize, node.triCount);
            leafCost += halfArea(node) * node.triCount;
        } else {
            interiorArea += halfArea(node);
            stack.push_back(index + 1);
            stack.push_back(node.firstOrRight);
        }
    }
    double rootArea = halfArea(bvh.nodes[0]);
    if (rootArea > 0)
        stats.sahCost =
            (interiorArea * options.traversalCost + leafCost * options.intersectCost) / rootArea;
    stats.avgLeafSize = stats.leaves ? double(prims) / double(stats.leaves) : 0.0;
    return stats;
}

}  // namespace penumbra::bvh
