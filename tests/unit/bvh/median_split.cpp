#include "median_split.h"

#include <algorithm>
#include <numeric>

namespace penumbra::bvh::test {
namespace {

struct MedianBuilder {
    std::span<const Aabb> boxes;
    std::vector<std::uint32_t>& order;
    std::vector<shader::BvhNode>& nodes;
    std::uint32_t leafSize;

    void build(std::uint32_t begin, std::uint32_t end) {
        Aabb box, centroids;
        for (std::uint32_t i = begin; i < end; ++i) {
            box.grow(boxes[order[i]]);
            centroids.grow(boxes[order[i]].center());
        }
        std::size_t self = nodes.size();
        nodes.push_back({box.lo, begin, box.hi, end - begin});
        if (end - begin <= leafSize) return;
        Vec3 e = centroids.extent();
        int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
        std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             return boxes[a].center()[axis] < boxes[b].center()[axis];
                         });
        nodes[self].triCount = 0;
        build(begin, mid);
        nodes[self].firstOrRight = std::uint32_t(nodes.size());
        build(mid, end);
    }
};

}  // namespace

Bvh buildMedianSplit(std::span<const Aabb> primBounds, int maxLeafSize) {
    Bvh bvh;
    bvh.primOrder.resize(primBounds.size());
    std::iota(bvh.primOrder.begin(), bvh.primOrder.end(), 0u);
    if (primBounds.empty()) return bvh;
    MedianBuilder b{primBounds, bvh.primOrder, bvh.nodes, std::uint32_t(maxLeafSize)};
    b.build(0, std::uint32_t(primBounds.size()));
    return bvh;
}

}  // namespace penumbra::bvh::test
