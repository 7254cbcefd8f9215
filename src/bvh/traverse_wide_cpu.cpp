#include "bvh/traverse_wide_cpu.h"

#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "bvh/slab.h"
#include "bvh/wide.h"
#include "core/error.h"

namespace penumbra::bvh {
namespace {

// A node group: interior children still to visit (bits 24-31, highest first) with the parent's
// interior mask (bits 0-7) and its childBase; or a primitive group: bits 0-23 from primBase.
struct Group {
    std::uint32_t base = 0, bits = 0;
};

constexpr std::uint32_t kInteriorBits = 0xff000000u;

// onPrimitive(slot) returns true to stop the walk (any hit).
template <typename OnPrimitive>
void traverseWide(std::span<const shader::WideNode> nodes, const Ray& ray, const float& tMax,
                  TraversalCounts* counts, OnPrimitive&& onPrimitive) {
    if (nodes.empty()) return;
    const SlabRay slab(ray);
    // Slot s holds the child nearest to rays with sign bits s; XOR with the flipped octant puts
    // this ray's nearest child at the highest bit.
    const std::uint32_t octantFlip =
        7u ^ ((slab.negative[0] ? 1u : 0u) | (slab.negative[1] ? 2u : 0u) |
              (slab.negative[2] ? 4u : 0u));
    Group stack[PN_BVH_STACK_SIZE];
    int sp = 0;
    Group group{0, 0x80000000u};  // the root, as the only interior child of a node with mask 0
    for (;;) {
        Group prims;
        if (group.bits & kInteriorBits) {
            const int bit = 31 - std::countl_zero(group.bits);
            group.bits &= ~(1u << bit);
            if (group.bits & kInteriorBits) {
                PN_CHECK(sp < PN_BVH_STACK_SIZE);
                stack[sp++] = group;
            }
            const std::uint32_t slot = std::uint32_t(bit - 24) ^ octantFlip;
            const std::uint32_t index =
                group.base + std::uint32_t(std::popcount(group.bits & 0xffu & ((1u << slot) - 1u)));
            PN_CHECK(index < nodes.size());
            const shader::WideNode& node = nodes[index];
            if (counts) ++counts->nodesVisited;
            std::uint32_t hits = 0;
            for (int s = 0; s < kWideArity; ++s) {
                const std::uint32_t meta = wideMeta(node, s);
                if (wideSlotEmpty(meta)) continue;
                const Aabb box = wideSlotBounds(node, s);
                if (slab.enter(box.lo, box.hi, tMax) == std::numeric_limits<float>::infinity())
                    continue;
                if (wideSlotInterior(meta))
                    hits |= 1u << (24u + (std::uint32_t(s) ^ octantFlip));
                else
                    hits |= ((1u << wideLeafCount(meta)) - 1u) << wideLeafOffset(meta);
            }
            group = {node.childBase, (hits & kInteriorBits) | (node.exponentsMask >> 24)};
            prims = {node.primBase, hits & ~kInteriorBits};
        } else {
            prims = group;
            group = {};
        }
        while (prims.bits) {
            const int bit = std::countr_zero(prims.bits);
            prims.bits &= prims.bits - 1;
            if (counts) ++counts->trianglesTested;
            if (onPrimitive(prims.base + std::uint32_t(bit))) return;
        }
        if (!(group.bits & kInteriorBits)) {
            if (sp == 0) return;
            group = stack[--sp];
        }
    }
}

void checkSlot(std::uint32_t slot, std::size_t count) {
    if (slot >= count)
        throw Error("wide BVH leaf references primitive " + std::to_string(slot) + " but only " +
                    std::to_string(count) + " exist");
}

}  // namespace

Hit closestHitWide(std::span<const shader::WideNode> nodes, std::span<const shader::TriVerts> tris,
                   const Ray& ray, TraversalCounts* counts) {
    Hit hit;
    hit.t = ray.tMax;
    traverseWide(nodes, ray, hit.t, counts, [&](std::uint32_t i) {
        checkSlot(i, tris.size());
        float t, u, v;
        if (intersectPrimitive(tris[i], ray, hit.t, t, u, v)) hit = {t, i, u, v};
        return false;
    });
    return hit;
}

bool anyHitWide(std::span<const shader::WideNode> nodes, std::span<const shader::TriVerts> tris,
                const Ray& ray, TraversalCounts* counts) {
    const float tMax = ray.tMax;
    bool found = false;
    traverseWide(nodes, ray, tMax, counts, [&](std::uint32_t i) {
        checkSlot(i, tris.size());
        float t, u, v;
        return found = intersectPrimitive(tris[i], ray, tMax, t, u, v);
    });
    return found;
}

}  // namespace penumbra::bvh
