#include "bvh/refit.h"

#include "bvh/builder.h"
#include "bvh/sphere.h"
#include "core/aabb.h"
#include "core/error.h"

namespace penumbra::bvh {
namespace {

Aabb primitiveBounds(const shader::TriVerts& p) {
    if (isSphere(p)) return sphereBounds(p.v0, p.e1.x);
    Aabb box;
    box.grow(p.v0);
    box.grow(p.v0 + p.e1);
    box.grow(p.v0 + p.e2);
    return sanitizedBounds(box);
}

}  // namespace

void refit(std::span<shader::BvhNode> nodes, std::uint32_t first, std::uint32_t count,
           std::span<const shader::TriVerts> prims) {
    PN_CHECK(std::uint64_t(first) + count <= nodes.size());
    for (std::uint32_t i = first + count; i-- > first;) {
        shader::BvhNode& node = nodes[i];
        Aabb box;
        if (node.triCount > 0) {
            PN_CHECK(std::uint64_t(node.firstOrRight) + node.triCount <= prims.size());
            for (std::uint32_t p = node.firstOrRight; p < node.firstOrRight + node.triCount; ++p)
                box.grow(primitiveBounds(prims[p]));
        } else {
            PN_CHECK(i + 1 < first + count && node.firstOrRight > i && node.firstOrRight < first + count);
            for (std::uint32_t child : {i + 1, node.firstOrRight}) {
                box.grow(nodes[child].boundsMin);
                box.grow(nodes[child].boundsMax);
            }
        }
        node.boundsMin = box.lo;
        node.boundsMax = box.hi;
    }
}

}  // namespace penumbra::bvh
