// The exact SAH sweep for the smallest nodes, which are most of a tree's nodes: for them a
// binning pass, its bins and their sweep cost more than sorting a handful of centroids.
#include <cstdint>

#include "bvh/sah_binning.h"

namespace penumbra::bvh::sah {

using simd::Box4;
using simd::F4;

// Two primitives, the most common node of all: the only split puts one on each side.
bool SahBinning::splitPair(const PrimRef* src, PrimRef* dst, const Range& range, float stopCost,
                           Range& left, Range& right) const {
    const PrimRef& p = src[range.begin];
    const PrimRef& q = src[range.begin + 1];
    const F4 cp = p.centroid(), cq = q.centroid();
    int axis = 0;
    while (axis < 3 && cp[axis] == cq[axis]) ++axis;
    if (axis == 3) return false;  // no plane separates them
    const Box4 bp{p.bottom(), p.hi}, bq{q.bottom(), q.hi};
    const float cost =
        ct_ * range.bounds.halfArea() + ci_ * (1.0f * bp.halfArea() + 1.0f * bq.halfArea());
    if (!(cost < stopCost)) return false;
    const bool pFirst = cp[axis] < cq[axis];
    dst[range.begin] = pFirst ? p : q;
    dst[range.begin + 1] = pFirst ? q : p;
    left = {range.begin, range.begin + 1, pFirst ? bp : bq, pFirst ? Box4{cp, cp} : Box4{cq, cq}};
    right = {range.begin + 1, range.end, pFirst ? bq : bp, pFirst ? Box4{cq, cq} : Box4{cp, cp}};
    return true;
}

bool SahBinning::splitSmall(const PrimRef* src, PrimRef* dst, const Range& range, float stopCost,
                            Range& left, Range& right) const {
    if (range.size() == 2) return splitPair(src, dst, range, stopCost, left, right);
    using simd::I4;
    constexpr int kMax = int(kSmallNode);
    const int n = int(range.size());
    F4 lo[kMax], hi[kMax], c[kMax];
    for (int i = 0; i < n; ++i) {
        const PrimRef& p = src[range.begin + i];
        lo[i] = p.bottom();
        hi[i] = p.hi;
        c[i] = p.centroid();
    }
    // Each primitive's place in centroid order on all three axes at once (lanes), by counting
    // the centroids before it: no branch, where sorting random centroids would mispredict
    // every other comparison. Ties go by index.
    std::uint8_t order[3][kMax];
    for (int i = 0; i < n; ++i) {
        I4 rank{0, 0, 0, 0};
        for (int j = 0; j < i; ++j) rank -= c[j] <= c[i];
        for (int j = i + 1; j < n; ++j) rank -= c[j] < c[i];
        for (int a = 0; a < 3; ++a) order[a][rank[a]] = std::uint8_t(i);
    }
    // The sweep of the binned builder, over primitives instead of bins: step k puts the first k
    // of each axis's order on the left.
    F4 rightCost[kMax];
    Box4 x, y, z;
    for (int k = n - 1; k > 0; --k) {
        x.grow(lo[order[0][k]], hi[order[0][k]]);
        y.grow(lo[order[1][k]], hi[order[1][k]]);
        z.grow(lo[order[2][k]], hi[order[2][k]]);
        rightCost[k] = float(n - k) * halfAreas(x, y, z);
    }
    x = y = z = Box4{};
    const float nodeCost = ct_ * range.bounds.halfArea();
    F4 bestCost = simd::kPosInf;
    I4 bestLeft{0, 0, 0, 0};
    for (int k = 1; k < n; ++k) {
        const int lx = order[0][k - 1], ly = order[1][k - 1], lz = order[2][k - 1];
        x.grow(lo[lx], hi[lx]);
        y.grow(lo[ly], hi[ly]);
        z.grow(lo[lz], hi[lz]);
        const F4 cost = nodeCost + ci_ * (float(k) * halfAreas(x, y, z) + rightCost[k]);
        // Only where a plane separates the centroids, as with bins: a node of identical
        // centroids is left to the median split, which keeps such piles balanced.
        const F4 before{c[lx][0], c[ly][1], c[lz][2], 0},
            after{c[order[0][k]][0], c[order[1][k]][1], c[order[2][k]][2], 0};
        const I4 better = (before < after) & (cost < bestCost);
        bestCost = better ? cost : bestCost;
        bestLeft = better ? I4{k, k, k, k} : bestLeft;
    }
    int axis = -1;
    float best = simd::kInf;
    for (int a = 0; a < 3; ++a)
        if (bestCost[a] < best) {
            best = bestCost[a];
            axis = a;
        }
    if (axis < 0 || !(best < stopCost)) return false;
    // The children's bounds come from the arrays above rather than a gather() over dst: the
    // same minima and maxima, without loading the primitives again.
    const int k = bestLeft[axis];
    const std::uint32_t mid = range.begin + std::uint32_t(k);
    left = {range.begin, mid, {}, {}};
    right = {mid, range.end, {}, {}};
    for (int i = 0; i < n; ++i) {
        const int p = order[axis][i];
        dst[range.begin + i] = src[range.begin + p];
        Range& side = i < k ? left : right;
        side.bounds.grow(lo[p], hi[p]);
        side.centroids.grow(c[p]);
    }
    return true;
}

}  // namespace penumbra::bvh::sah
