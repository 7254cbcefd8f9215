#include "bvh/depth_boxes.h"

#include <algorithm>
#include <utility>

namespace penumbra::bvh {
namespace {

// Visits (node, depth) pairs depth-first (root: depth 1) with an explicit stack (trees can be
// deep); a node's children are skipped when visit returns false. Interior nodes: the left child
// follows its parent, firstOrRight is the right.
template <class Visit>
void walk(std::span<const shader::BvhNode> nodes, Visit&& visit) {
    if (nodes.empty()) return;
    std::vector<std::pair<std::uint32_t, std::size_t>> stack{{0u, 1u}};
    while (!stack.empty()) {
        const auto [index, depth] = stack.back();
        stack.pop_back();
        const shader::BvhNode& n = nodes[index];
        const bool descend = visit(n, depth);
        if (!descend || n.triCount > 0) continue;
        stack.push_back({n.firstOrRight, depth + 1});
        stack.push_back({index + 1, depth + 1});
    }
}

}  // namespace

std::vector<shader::BvhNode> nodesAtDepth(std::span<const shader::BvhNode> nodes, std::size_t depth,
                                          std::size_t maxCount) {
    std::vector<shader::BvhNode> out;
    walk(nodes, [&](const shader::BvhNode& n, std::size_t d) {
        if (d == depth && out.size() < maxCount) out.push_back(n);
        return d < depth && out.size() < maxCount;
    });
    return out;
}

std::size_t treeDepth(std::span<const shader::BvhNode> nodes) {
    std::size_t deepest = 0;
    walk(nodes, [&](const shader::BvhNode&, std::size_t d) {
        deepest = std::max(deepest, d);
        return true;
    });
    return deepest;
}

}  // namespace penumbra::bvh
