#include "bvh/stackless.h"

#include <limits>
#include <string>
#include <utility>

#include "bvh/slab.h"
#include "core/error.h"

namespace penumbra::bvh {

namespace {

// The leaf word: first << PN_STACKLESS_COUNT_BITS | count, checked to fit.
std::uint32_t leafWord(const shader::BvhNode& node, std::uint32_t index) {
    const std::uint32_t maxFirst = PN_STACKLESS_END >> PN_STACKLESS_COUNT_BITS;
    if (node.triCount > PN_STACKLESS_COUNT_MASK || node.firstOrRight >= maxFirst)
        throw Error("--accel stackless: leaf " + std::to_string(index) + " holds " + std::to_string(node.triCount) +
                    " primitives from slot " + std::to_string(node.firstOrRight) + "; its node fits at most " +
                    std::to_string(PN_STACKLESS_COUNT_MASK) + " from below slot " + std::to_string(maxFirst) +
                    " (use --accel bvh)");
    return node.firstOrRight << PN_STACKLESS_COUNT_BITS | node.triCount;
}

}  // namespace

void threadTree(std::span<const shader::BvhNode> nodes, std::uint32_t root, std::span<shader::StacklessNode> out) {
    const auto count = std::uint32_t(nodes.size());
    PN_CHECK(out.size() == nodes.size() && root < count);
    // Depth first, carrying the escape each node inherits: a left child escapes to its sibling, a
    // right child where its parent escapes to.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pending{{root, PN_STACKLESS_END}};  // (node, its escape)
    while (!pending.empty()) {
        const auto [n, escape] = pending.back();
        pending.pop_back();
        out[n].boundsMin = nodes[n].boundsMin;
        out[n].boundsMax = nodes[n].boundsMax;
        out[n].escape = escape;
        out[n].leaf = nodes[n].triCount > 0 ? leafWord(nodes[n], n) : 0u;
        if (nodes[n].triCount > 0) continue;
        const std::uint32_t left = n + 1, right = nodes[n].firstOrRight;
        PN_CHECK(left < count && right < count && right > left);
        pending.push_back({right, escape});
        pending.push_back({left, right});
    }
}

std::vector<shader::StacklessNode> threadNodes(std::span<const shader::BvhNode> nodes,
                                               std::span<const std::uint32_t> roots) {
    const auto count = std::uint32_t(nodes.size());
    std::vector<shader::StacklessNode> out(nodes.size());
    // Nodes no root reaches keep their box and end the walk (none in the builder's arrays).
    for (std::uint32_t i = 0; i < count; ++i) {
        out[i].boundsMin = nodes[i].boundsMin;
        out[i].boundsMax = nodes[i].boundsMax;
        out[i].escape = PN_STACKLESS_END;
        out[i].leaf = nodes[i].triCount > 0 ? leafWord(nodes[i], i) : 0u;
    }
    for (std::uint32_t root : roots) threadTree(nodes, root, out);
    return out;
}

namespace {

// The shader's walk over a flat tree; onLeaf(first, count) returns true to stop.
template <typename OnLeaf>
void walk(std::span<const shader::StacklessNode> nodes, const Ray& ray, const float& tMax, TraversalCounts* counts,
          OnLeaf&& onLeaf) {
    if (nodes.empty()) return;
    const SlabRay slab(ray);
    std::uint32_t current = 0;
    while (current != PN_STACKLESS_END) {
        PN_CHECK(current < nodes.size());
        const shader::StacklessNode& node = nodes[current];
        if (counts) ++counts->nodesVisited;
        if (slab.enter(node.boundsMin, node.boundsMax, tMax) == std::numeric_limits<float>::infinity()) {
            current = node.escape;
        } else if (node.leaf == 0) {
            current += 1;
        } else {
            if (onLeaf(node.leaf >> PN_STACKLESS_COUNT_BITS, node.leaf & PN_STACKLESS_COUNT_MASK)) return;
            current = node.escape;
        }
    }
}

}  // namespace

Hit closestHitStackless(std::span<const shader::StacklessNode> nodes, std::span<const shader::TriVerts> tris,
                        const Ray& ray, TraversalCounts* counts) {
    Hit hit;
    hit.t = ray.tMax;
    walk(nodes, ray, hit.t, counts, [&](std::uint32_t first, std::uint32_t n) {
        PN_CHECK(std::uint64_t(first) + n <= tris.size());
        for (std::uint32_t i = first; i < first + n; ++i) {
            if (counts) ++counts->trianglesTested;
            float t, u, v;
            if (intersectPrimitive(tris[i], ray, hit.t, t, u, v)) hit = {t, i, u, v, PN_NO_HIT};
        }
        return false;
    });
    return hit;
}

bool anyHitStackless(std::span<const shader::StacklessNode> nodes, std::span<const shader::TriVerts> tris,
                     const Ray& ray) {
    bool found = false;
    walk(nodes, ray, ray.tMax, nullptr, [&](std::uint32_t first, std::uint32_t n) {
        PN_CHECK(std::uint64_t(first) + n <= tris.size());
        for (std::uint32_t i = first; i < first + n; ++i) {
            float t, u, v;
            if (intersectPrimitive(tris[i], ray, ray.tMax, t, u, v)) return found = true;
        }
        return false;
    });
    return found;
}

}  // namespace penumbra::bvh
