// The binned builder approximates the SAH (few bins on mid-sized nodes, bin boundaries instead of
// every primitive): these tests bound what that costs against a full sweep, which tries every
// object partition along every axis at every node.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <vector>

#include "bvh/builder.h"
#include "bvh/stats.h"
#include "bvh/validate.h"
#include "bvh_test_util.h"

namespace penumbra::bvh {
namespace {

// Top-down SAH with the exact sweep at every node and the binned builder's leaf rule (a node of
// at most maxLeafSize primitives stays a leaf unless a split costs less), written for clarity.
class FullSweepBuilder {
public:
    FullSweepBuilder(std::span<const Aabb> boxes, const BuildOptions& options)
        : boxes_(boxes), options_(options) {}

    Bvh build() {
        Bvh bvh;
        bvh.primOrder.resize(boxes_.size());
        std::iota(bvh.primOrder.begin(), bvh.primOrder.end(), 0u);
        node(bvh, 0, std::uint32_t(boxes_.size()));
        return bvh;
    }

private:
    Aabb boundsOf(const std::vector<std::uint32_t>& ids, std::uint32_t begin,
                  std::uint32_t end) const {
        Aabb box;
        for (std::uint32_t i = begin; i < end; ++i) box.grow(boxes_[ids[i]]);
        return box;
    }

    // Appends the subtree over primOrder[begin, end) depth-first and returns its root's index.
    std::uint32_t node(Bvh& bvh, std::uint32_t begin, std::uint32_t end) {
        std::vector<std::uint32_t>& ids = bvh.primOrder;
        const Aabb box = boundsOf(ids, begin, end);
        const std::uint32_t index = std::uint32_t(bvh.nodes.size());
        bvh.nodes.push_back({});
        bvh.nodes[index].boundsMin = box.lo;
        bvh.nodes[index].boundsMax = box.hi;
        const std::uint32_t n = end - begin;
        float bestCost = std::numeric_limits<float>::infinity();
        int bestAxis = -1;
        std::uint32_t bestLeft = 0;
        for (int axis = 0; axis < 3; ++axis) {
            sortByCentroid(ids, begin, end, axis);
            std::vector<float> rightArea(n);
            Aabb right;
            for (std::uint32_t k = n; k-- > 1;) {
                right.grow(boxes_[ids[begin + k]]);
                rightArea[k] = right.halfArea() * float(n - k);
            }
            Aabb left;
            for (std::uint32_t k = 1; k < n; ++k) {
                left.grow(boxes_[ids[begin + k - 1]]);
                const float cost =
                    options_.traversalCost * box.halfArea() +
                    options_.intersectCost * (left.halfArea() * float(k) + rightArea[k]);
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestLeft = k;
                }
            }
        }
        const float leafCost = options_.intersectCost * float(n) * box.halfArea();
        if (n <= 1 || (n <= std::uint32_t(options_.maxLeafSize) && !(bestCost < leafCost))) {
            bvh.nodes[index].firstOrRight = begin;
            bvh.nodes[index].triCount = n;
            return index;
        }
        sortByCentroid(ids, begin, end, bestAxis);
        node(bvh, begin, begin + bestLeft);
        const std::uint32_t right = node(bvh, begin + bestLeft, end);
        bvh.nodes[index].firstOrRight = right;
        bvh.nodes[index].triCount = 0;
        return index;
    }

    void sortByCentroid(std::vector<std::uint32_t>& ids, std::uint32_t begin, std::uint32_t end,
                        int axis) const {
        std::stable_sort(ids.begin() + begin, ids.begin() + end,
                         [&](std::uint32_t p, std::uint32_t q) {
                             return boxes_[p].center()[axis] < boxes_[q].center()[axis];
                         });
    }

    std::span<const Aabb> boxes_;
    BuildOptions options_;
};

// A closed, curved surface as a mesh would give it: a torus of rings x segments quads.
std::vector<Triangle> torus(int rings, int segments) {
    auto point = [&](int i, int j) {
        const float u = 6.2831853f * float(i) / float(rings);
        const float v = 6.2831853f * float(j) / float(segments);
        const float r = 1.0f + 0.3f * std::cos(v);
        return Vec3(r * std::cos(u), r * std::sin(u), 0.3f * std::sin(v));
    };
    std::vector<Triangle> tris;
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const Vec3 a = point(i, j), b = point(i + 1, j), c = point(i + 1, j + 1),
                       d = point(i, j + 1);
            tris.push_back({a, b, c});
            tris.push_back({a, c, d});
        }
    return tris;
}

void expectCloseToFullSweep(const std::vector<Triangle>& tris) {
    const BuildOptions options;
    const std::vector<Aabb> boxes = test::boxesOf(tris);
    const Bvh binned = buildTriangles(tris, options);
    ASSERT_NO_THROW(validate(binned, boxes));
    const Bvh exact = FullSweepBuilder(boxes, options).build();
    ASSERT_NO_THROW(validate(exact, boxes));
    const double binnedCost = computeStats(binned, options).sahCost;
    const double exactCost = computeStats(exact, options).sahCost;
    std::printf("SAH cost: binned %.3f, full sweep %.3f (x%.4f)\n", binnedCost, exactCost,
                binnedCost / exactCost);
    EXPECT_LT(binnedCost, exactCost * 1.03)
        << "binned " << binnedCost << ", full sweep " << exactCost;
    EXPECT_GT(binnedCost, 1.0);
}

TEST(BvhSahQuality, SoupWithinThreePercentOfTheFullSweep) {
    expectCloseToFullSweep(test::randomSoup(20'000, 7));
}

TEST(BvhSahQuality, MeshWithinThreePercentOfTheFullSweep) {
    expectCloseToFullSweep(torus(100, 100));  // 20,000 triangles
}

}  // namespace
}  // namespace penumbra::bvh
