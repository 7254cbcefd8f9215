#include "bvh/stats.h"

#include <algorithm>
#include <utility>
#include <vector>

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

    double interiorArea = 0, leafCost = 0;
    std::size_t prims = 0;
    // (node, depth) pairs; an explicit stack because foreign trees may be arbitrarily deep.
    std::vector<std::pair<std::uint32_t, std::size_t>> stack{{0, 1}};
    while (!stack.empty()) {
        auto [index, depth] = stack.back();
        stack.pop_back();
        const shader::BvhNode& node = bvh.nodes[index];
        stats.maxDepth = std::max(stats.maxDepth, depth);
        if (node.triCount > 0) {
            ++stats.leaves;
            prims += node.triCount;
            stats.maxLeafSize = std::max<std::size_t>(stats.maxLeafSize, node.triCount);
            leafCost += halfArea(node) * node.triCount;
        } else {
            interiorArea += halfArea(node);
            stack.push_back({index + 1, depth + 1});
            stack.push_back({node.firstOrRight, depth + 1});
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
