// The exact sweep for small nodes against brute force over the same candidates.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "bvh/sah_binning.h"

namespace penumbra::bvh::sah {
namespace {

float halfArea(const Aabb& b) { return b.halfArea(); }

Aabb boxOf(const PrimRef& p) { return {simd::vec3(p.bottom()), simd::vec3(p.hi)}; }

// The cheapest candidate the builder may take: on each axis, the first k primitives in centroid
// order against the rest, wherever a plane separates their centroids.
float bruteForceCost(const std::vector<PrimRef>& prims, const BuildOptions& o, const Aabb& node) {
    float best = std::numeric_limits<float>::infinity();
    for (int a = 0; a < 3; ++a) {
        std::vector<PrimRef> sorted = prims;
        // std::sort, not stable_sort: libstdc++ 12's stable_sort buffer ignores PrimRef's 32-byte
        // alignment (UBSan: misaligned reference), and ties are skipped below, so order among
        // equal centroids changes no cost.
        std::sort(sorted.begin(), sorted.end(), [a](const PrimRef& p, const PrimRef& q) {
            return p.centroid()[a] < q.centroid()[a];
        });
        for (std::size_t k = 1; k < sorted.size(); ++k) {
            if (!(sorted[k - 1].centroid()[a] < sorted[k].centroid()[a])) continue;
            Aabb l, r;
            for (std::size_t i = 0; i < sorted.size(); ++i) (i < k ? l : r).grow(boxOf(sorted[i]));
            float cost =
                o.traversalCost * halfArea(node) +
                o.intersectCost * (float(k) * halfArea(l) + float(sorted.size() - k) * halfArea(r));
            best = std::min(best, cost);
        }
    }
    return best;
}

TEST(SahSmall, FindsTheCheapestSplitAndMovesEveryPrimitiveOnce) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    BuildOptions options;
    SahBinning sah(options);
    for (int trial = 0; trial < 2000; ++trial) {
        const std::uint32_t n = 2 + trial % (SahBinning::kSmallNode - 1);
        std::vector<PrimRef> prims;
        Range range;
        range.end = n;
        for (std::uint32_t i = 0; i < n; ++i) {
            Vec3 c(u(rng), u(rng), u(rng));
            // Every fourth trial snaps centroids to a coarse grid, so ties and coincident
            // centroids come up.
            if (trial % 4 == 0)
                c = Vec3(std::round(c.x * 2), std::round(c.y * 2), std::round(c.z * 2));
            Vec3 h(0.05f + 0.2f * u(rng), 0.05f + 0.2f * u(rng), 0.05f + 0.2f * u(rng));
            prims.push_back(PrimRef::make({c - h, c + h}, 100 + i));
            range.bounds.grow(prims.back().bottom(), prims.back().hi);
            range.centroids.grow(prims.back().centroid());
        }
        std::vector<PrimRef> dst(n);
        Range left, right;
        const float expected = bruteForceCost(prims, options, range.bounds.aabb());
        const bool split = sah.splitSmall(prims.data(), dst.data(), range,
                                          std::numeric_limits<float>::infinity(), left, right);
        ASSERT_EQ(split, expected < std::numeric_limits<float>::infinity()) << "trial " << trial;
        if (!split) continue;
        ASSERT_EQ(left.begin, 0u);
        ASSERT_EQ(left.end, right.begin);
        ASSERT_EQ(right.end, n);
        ASSERT_GT(left.size(), 0u);
        ASSERT_GT(right.size(), 0u);
        Aabb l, r;
        std::vector<std::uint32_t> ids;
        for (std::uint32_t i = 0; i < n; ++i) {
            (i < left.end ? l : r).grow(boxOf(dst[i]));
            ids.push_back(dst[i].id());
        }
        std::sort(ids.begin(), ids.end());
        std::vector<std::uint32_t> want(n);
        std::iota(want.begin(), want.end(), 100u);
        ASSERT_EQ(ids, want) << "trial " << trial;
        EXPECT_EQ(left.bounds.aabb().lo, l.lo);
        EXPECT_EQ(left.bounds.aabb().hi, l.hi);
        EXPECT_EQ(right.bounds.aabb().lo, r.lo);
        EXPECT_EQ(right.bounds.aabb().hi, r.hi);
        const float cost = options.traversalCost * halfArea(range.bounds.aabb()) +
                           options.intersectCost * (float(left.size()) * halfArea(l) +
                                                    float(right.size()) * halfArea(r));
        EXPECT_NEAR(cost, expected, 1e-5f * expected) << "trial " << trial << ", n " << n;
        // A stop cost at or below the best keeps the node whole and moves nothing.
        std::vector<PrimRef> untouched(n, PrimRef::make({Vec3(9.0f), Vec3(9.0f)}, 0));
        EXPECT_FALSE(
            sah.splitSmall(prims.data(), untouched.data(), range, expected * 0.999f, left, right));
        EXPECT_EQ(untouched[0].id(), 0u);
    }
}

}  // namespace
}  // namespace penumbra::bvh::sah
