#include "bvh/child_pairs.h"

#include "core/error.h"

namespace penumbra::bvh {

namespace {

shader::BvhPair pairOf(std::span<const shader::BvhNode> nodes, std::size_t i) {
    const shader::BvhNode& node = nodes[i];
    shader::BvhPair p{};
    if (node.triCount > 0) {
        p.left = node.firstOrRight;
        p.leafCount = node.triCount;
        return p;
    }
    const std::size_t left = i + 1, right = node.firstOrRight;
    PN_CHECK(left < nodes.size() && right < nodes.size());
    p.leftMin = nodes[left].boundsMin;
    p.leftMax = nodes[left].boundsMax;
    p.left = std::uint32_t(left);
    p.rightMin = nodes[right].boundsMin;
    p.rightMax = nodes[right].boundsMax;
    p.right = std::uint32_t(right);
    return p;
}

}  // namespace

void writeChildPairs(std::span<const shader::BvhNode> nodes, std::size_t first, std::span<shader::BvhPair> out) {
    PN_CHECK(first + out.size() <= nodes.size());
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = pairOf(nodes, first + k);
}

std::vector<shader::BvhPair> childPairs(std::span<const shader::BvhNode> nodes) {
    std::vector<shader::BvhPair> out(nodes.size());
    writeChildPairs(nodes, 0, out);
    return out;
}

}  // namespace penumbra::bvh
