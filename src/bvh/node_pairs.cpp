#include "bvh/node_pairs.h"

#include "core/error.h"

namespace penumbra::bvh {

std::vector<shader::BvhNodePair> toNodePairs(std::span<const shader::BvhNode> nodes) {
    std::vector<shader::BvhNodePair> pairs;
    if (nodes.empty()) return pairs;
    // Interior nodes become pairs in the same depth-first order.
    std::vector<std::uint32_t> pairOf(nodes.size(), PN_NO_HIT);
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].triCount == 0) pairOf[i] = static_cast<std::uint32_t>(pairs.size()), pairs.emplace_back();
    auto child = [&](std::size_t c, Vec3& lo, Vec3& hi, std::uint32_t& index, std::uint32_t& count) {
        PN_CHECK(c < nodes.size());
        lo = nodes[c].boundsMin;
        hi = nodes[c].boundsMax;
        count = nodes[c].triCount;
        index = count > 0 ? nodes[c].firstOrRight : pairOf[c];
    };
    if (pairs.empty()) {  // the root is a leaf
        shader::BvhNodePair p{};
        child(0, p.leftMin, p.leftMax, p.leftIndex, p.leftCount);
        child(0, p.rightMin, p.rightMax, p.rightIndex, p.rightCount);
        pairs.push_back(p);
        return pairs;
    }
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        if (nodes[i].triCount != 0) continue;
        shader::BvhNodePair& p = pairs[pairOf[i]];
        child(i + 1, p.leftMin, p.leftMax, p.leftIndex, p.leftCount);
        child(nodes[i].firstOrRight, p.rightMin, p.rightMax, p.rightIndex, p.rightCount);
    }
    return pairs;
}

}  // namespace penumbra::bvh
