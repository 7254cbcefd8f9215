#include "bvh/refit.h"

#include "core/error.h"

namespace penumbra::bvh {

void refit(std::span<shader::BvhNode> nodes, std::uint32_t first, std::uint32_t count,
           std::span<const Aabb> primBounds, std::uint32_t slotBase) {
    PN_CHECK(std::uint64_t(first) + count <= nodes.size());
    for (std::uint32_t i = first + count; i-- > first;) {
        shader::BvhNode& node = nodes[i];
        Aabb box;
        if (node.triCount > 0) {
            PN_CHECK(node.firstOrRight >= slotBase &&
                     std::uint64_t(node.firstOrRight - slotBase) + node.triCount <= primBounds.size());
            for (std::uint32_t p = node.firstOrRight; p < node.firstOrRight + node.triCount; ++p)
                box.grow(primBounds[p - slotBase]);
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
