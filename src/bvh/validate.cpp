#include "bvh/validate.h"

#include <string>
#include <vector>

#include "core/error.h"

namespace penumbra::bvh {
namespace {

bool contains(const Aabb& outer, const Aabb& inner) {
    return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z &&
           inner.hi.x <= outer.hi.x && inner.hi.y <= outer.hi.y && inner.hi.z <= outer.hi.z;
}

[[noreturn]] void fail(std::uint32_t node, const std::string& what) {
    throw Error("BVH node " + std::to_string(node) + ": " + what);
}

}  // namespace

void validate(const Bvh& bvh, std::span<const Aabb> primBounds) {
    if (bvh.primOrder.size() != primBounds.size())
        throw Error("BVH: primOrder has " + std::to_string(bvh.primOrder.size()) + " entries for " +
                    std::to_string(primBounds.size()) + " primitives");
    if (bvh.nodes.empty()) {
        if (!primBounds.empty()) throw Error("BVH: no nodes for a non-empty primitive list");
        return;
    }
    std::vector<std::uint32_t> seen(primBounds.size(), 0);
    for (std::uint32_t id : bvh.primOrder) {
        if (id >= primBounds.size()) throw Error("BVH: primOrder holds out-of-range index");
        if (seen[id]++) throw Error("BVH: primitive " + std::to_string(id) + " appears twice");
    }

    const auto nodeCount = std::uint32_t(bvh.nodes.size());
    std::vector<std::uint32_t> covered(primBounds.size(), 0);
    struct Item {
        std::uint32_t node;
        std::uint32_t depth;
    };
    std::vector<Item> stack{{0, 1}};
    std::uint32_t visited = 0;
    // Depth-first order means the subtree of node i occupies [i, next sibling); checking that
    // each node's children are the next unvisited ones proves the layout and rules out cycles.
    std::uint32_t expectNext = 0;
    while (!stack.empty()) {
        Item item = stack.back();
        stack.pop_back();
        if (item.node != expectNext) fail(item.node, "not in depth-first order");
        ++expectNext;
        ++visited;
        if (item.depth > PN_BVH_MAX_DEPTH)
            fail(item.node, "depth " + std::to_string(item.depth) + " exceeds PN_BVH_MAX_DEPTH");
        const shader::BvhNode& node = bvh.nodes[item.node];
        Aabb box{node.boundsMin, node.boundsMax};
        if (node.triCount == 0) {
            std::uint32_t left = item.node + 1, right = node.firstOrRight;
            if (left >= nodeCount || right >= nodeCount || right <= left)
                fail(item.node, "child index out of range");
            for (std::uint32_t child : {left, right}) {
                Aabb cb{bvh.nodes[child].boundsMin, bvh.nodes[child].boundsMax};
                if (!contains(box, cb))
                    fail(item.node, "child " + std::to_string(child) + " outside parent box");
            }
            stack.push_back({right, item.depth + 1});
            stack.push_back({left, item.depth + 1});
        } else {
            std::uint64_t end = std::uint64_t(node.firstOrRight) + node.triCount;
            if (end > primBounds.size()) fail(item.node, "primitive range out of bounds");
            for (std::uint32_t i = node.firstOrRight; i < end; ++i) {
                if (covered[i]++) fail(item.node, "primitive slot in two leaves");
                if (!contains(box, sanitizedBounds(primBounds[bvh.primOrder[i]])))
                    fail(item.node, "primitive outside leaf box");
            }
        }
    }
    if (visited != nodeCount) throw Error("BVH: unreachable nodes");
    for (std::size_t i = 0; i < covered.size(); ++i)
        if (!covered[i]) throw Error("BVH: primitive slot " + std::to_string(i) + " in no leaf");
}

}  // namespace penumbra::bvh
