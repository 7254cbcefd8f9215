// The binned-SAH steps of the builder (internal to src/bvh): primitive references, binning
// centroids, sweeping the bins for the cheapest split, and partitioning a range by it.
// The scheme is Wald's "On fast construction of SAH-based BVHs" (2007): bins over the centroid
// bounds, all three bin indices from one vector subtract-multiply-clamp, all three axes swept
// at once, and the children's boxes and counts read off the bins, so that a partition only
// moves primitives (out of place and without branches). The smallest nodes skip binning for an
// exact sweep over their few centroids (sah_small.cpp).
#pragma once

#include <bit>
#include <cstdint>
#include <vector>

#include "bvh/builder.h"
#include "bvh/simd4.h"

namespace penumbra::bvh::sah {

// 32 bytes: a partition moves whole half cache lines and never chases an index.
struct alignas(32) PrimRef {
    simd::F4 lo;  // w: the primitive's index, as bits (cleared before any arithmetic)
    simd::F4 hi;  // w: 0

    static PrimRef make(const Aabb& box, std::uint32_t id) {
        PrimRef r;
        r.lo = simd::F4{box.lo.x, box.lo.y, box.lo.z, std::bit_cast<float>(id)};
        r.hi = simd::vec(box.hi);
        return r;
    }
    std::uint32_t id() const { return std::bit_cast<std::uint32_t>(lo[3]); }
    simd::F4 bottom() const { return simd::xyz(lo); }
    // Halves first, so coordinates near the float range's end cannot overflow.
    simd::F4 centroid() const { return bottom() * 0.5f + hi * 0.5f; }
};

struct Range {
    std::uint32_t begin = 0, end = 0;
    simd::Box4 bounds;     // exact
    simd::Box4 centroids;  // contains every centroid, not always tightly: it only places the bins

    std::uint32_t size() const { return end - begin; }
};

// The bounds and centroid bounds of refs[begin, end), by a pass over them.
Range gather(const PrimRef* refs, std::uint32_t begin, std::uint32_t end);

// Maps centroids to bins; axes without extent (or with one too small or too large for a finite
// scale) get scale 0, which puts everything in bin 0 and so offers no split there.
struct Binner {
    simd::F4 origin{}, scale{}, lastBin{};
    int bins = 2;

    Binner() = default;
    Binner(const Range& range, int binCount);
    simd::I4 indices(simd::F4 centroid) const;
};

struct Split {
    int axis = -1;  // -1: no split found
    int bin = 0;    // primitives in bins <= bin go left
    float cost = simd::kInf;
    Binner binner;
    Range left, right;  // as the bins give them
    // Set when the node was binned in parallel: its range in chunks of chunkSize primitives
    // (the last one shorter) and how many of each chunk go left, so that partition() can move
    // every chunk at once to where a serial pass would have put it.
    std::uint32_t chunkSize = 0;
    std::vector<std::uint32_t> chunkLeft;
};

struct BinGrid;  // the bins of one node (sah_binning.cpp)

// Half areas of three boxes at once (lane a: the box of axis a's candidate), with
// Aabb::halfArea's arithmetic in the same order; lanes of empty boxes are meaningless.
inline simd::F4 halfAreas(const simd::Box4& x, const simd::Box4& y, const simd::Box4& z) {
    const simd::F4 ex = x.hi - x.lo, ey = y.hi - y.lo, ez = z.hi - z.lo;
    const simd::F4 dx{ex[0], ey[0], ez[0], 0}, dy{ex[1], ey[1], ez[1], 0},
        dz{ex[2], ey[2], ez[2], 0};
    return dx * dy + dy * dz + dz * dx;
}

class SahBinning {
public:
    explicit SahBinning(const BuildOptions& options);

    std::uint32_t leafSize() const { return leafSize_; }
    float leafCost(const Range& range) const {
        return ci_ * float(range.size()) * range.bounds.halfArea();
    }

    // The cheapest split of `range` by the SAH; threads > 1 bins in parallel. axis stays -1
    // when all centroids coincide.
    Split find(const PrimRef* refs, const Range& range, unsigned threads) const;

    // Moves src[range] to dst[range], the left side of `split` first (in source order; the right
    // side after it in reverse source order), on several threads when find() binned in
    // parallel, with the same result as on one. Returns how many went
    // left, which is split.left.size() unless the bins and this pass disagreed on a bin (only
    // conceivable where a compiler fuses the centroid's arithmetic differently in the two);
    // then the caller must gather the children's bounds itself.
    std::uint32_t partition(const PrimRef* src, PrimRef* dst, const Range& range,
                            const Split& split) const;

    // Nodes of at most kSmallNode primitives skip binning: splitSmall() tries every object
    // partition along each axis in centroid order (the binned candidates and more) and writes
    // the cheapest to dst[range], left first. It returns false, moving nothing, when no plane
    // separates the centroids or no candidate costs less than `stopCost` (infinity when the node
    // must be split: the caller then splits at the median).
    // 16 rather than 8: nodes of 9-16 primitives cost less this way than binned, and the
    // exact sweep finds slightly better splits (1M soup SAH 381.50 -> 381.37).
    static constexpr std::uint32_t kSmallNode = 16;
    // Binned nodes of at most kFewBinsNode primitives use kFewBins bins (fewer if
    // BuildOptions::bins says so): resetting and sweeping 16 bins costs more than binning a few
    // dozen primitives, and the SAH loses little (1M soup 381.37 -> 382.41; sah_quality_test
    // bounds the loss against a full sweep).
    static constexpr std::uint32_t kFewBinsNode = 64;
    static constexpr std::uint32_t kFewBins = 8;
    bool splitSmall(const PrimRef* src, PrimRef* dst, const Range& range, float stopCost,
                    Range& left, Range& right) const;

    // Halves the range by count (in place in refs): along the widest centroid axis, or by index
    // when all centroids coincide. Each half needs one level fewer, which is what makes the
    // depth bound hold.
    void medianSplit(PrimRef* refs, const Range& range, Range& left, Range& right) const;

    // Nodes binned in parallel are cut into at most this many chunks per thread (for balance
    // when some threads are busy elsewhere), none smaller than kMinChunk primitives.
    static constexpr std::uint32_t kChunksPerThread = 4;
    static constexpr std::uint32_t kMinChunk = 16 * 1024;

private:
    int binCount(const Range& range) const;
    bool splitPair(const PrimRef* src, PrimRef* dst, const Range& range, float stopCost,
                   Range& left, Range& right) const;
    void sweep(const BinGrid& grid, const Binner& b, const Range& range, Split& best) const;

    int bins_;
    std::uint32_t leafSize_;
    float ct_, ci_;
};

}  // namespace penumbra::bvh::sah
