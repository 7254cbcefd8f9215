#include "bvh/sah_binning.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <memory>
#include <vector>

#include "core/error.h"
#include "core/parallel.h"

namespace penumbra::bvh::sah {

using simd::Box4;
using simd::F4;

Range gather(const PrimRef* refs, std::uint32_t begin, std::uint32_t end) {
    Range r;
    r.begin = begin;
    r.end = end;
    for (std::uint32_t i = begin; i < end; ++i) {
        r.bounds.grow(refs[i].bottom(), refs[i].hi);
        r.centroids.grow(refs[i].centroid());
    }
    return r;
}

Binner::Binner(const Range& range, int binCount) : bins(binCount) {
    origin = range.centroids.lo;
    scale = F4{0, 0, 0, 0};
    lastBin = simd::splat(float(bins - 1));
    F4 extent = range.centroids.hi - range.centroids.lo;
    for (int a = 0; a < 3; ++a) {
        float s = float(bins) / extent[a];
        scale[a] = (extent[a] > 0 && std::isfinite(s)) ? s : 0.0f;
    }
}

// Clamped to [0, bins - 1], NaN going to 0 (vmax keeps 0 unless f > 0), so the conversion is
// always defined. partition() decides sides from the same f.
simd::I4 Binner::indices(F4 centroid) const {
    const F4 zero{0, 0, 0, 0};
    return __builtin_convertvector(
        simd::vmin(simd::vmax((centroid - origin) * scale, zero), lastBin), simd::I4);
}

// What one bin of one axis holds: the bounds of its primitives, and in lane w of `lo` how many
// there are (as integer bits). Keeping the count in the box saves the binning loop a third of
// its stores. No initialisers, so a node pays only for the bins it uses (BinGrid::reset).
struct Bin {
    F4 lo, hi;
};

struct BinGrid {
    Bin bin[3][kMaxBins];

    void reset(int bins) {
        const F4 emptyLo{simd::kInf, simd::kInf, simd::kInf, 0.0f};  // w: a count of 0
        for (int a = 0; a < 3; ++a)
            for (int i = 0; i < bins; ++i) bin[a][i] = {emptyLo, simd::kNegInf};
    }
    // lo's lane w must be +inf, so that the minimum keeps the bin's count there (any count below
    // 2^31, read as a float, is less than +inf).
    void addOne(int a, int i, F4 lo, F4 hi) {
        Bin& x = bin[a][i];
        x.lo = F4(simd::I4(simd::vmin(x.lo, lo)) + simd::I4{0, 0, 0, 1});
        x.hi = simd::vmax(x.hi, hi);
    }
    std::uint32_t count(int a, int i) const {
        return std::bit_cast<std::uint32_t>(bin[a][i].lo[3]);
    }
    Box4 box(int a, int i) const { return {simd::xyz(bin[a][i].lo), bin[a][i].hi}; }
    void merge(const BinGrid& other, int bins) {
        for (int a = 0; a < 3; ++a)
            for (int i = 0; i < bins; ++i) {
                Bin& x = bin[a][i];
                const Bin& y = other.bin[a][i];
                const std::uint32_t n = count(a, i) + other.count(a, i);
                x.lo = simd::vmin(x.lo, y.lo);
                x.lo[3] = std::bit_cast<float>(n);
                x.hi = simd::vmax(x.hi, y.hi);
            }
    }
};

namespace {

// The hot loop: one vector subtract-multiply-clamp gives all three bin indices.
void binRange(const Binner& b, const PrimRef* refs, std::uint32_t begin, std::uint32_t end,
              BinGrid& grid) {
    const simd::I4 xyz{-1, -1, -1, 0}, infW{0, 0, 0, std::bit_cast<std::int32_t>(simd::kInf)};
    for (std::uint32_t i = begin; i < end; ++i) {
        const F4 lo = F4((simd::I4(refs[i].lo) & xyz) | infW), hi = refs[i].hi;
        const F4 c = simd::xyz(lo) * 0.5f + hi * 0.5f;
        const simd::I4 bin = b.indices(c);
        for (int a = 0; a < 3; ++a) grid.addOne(a, bin[a], lo, hi);
    }
}

// Bins the range in chunks on all threads, one grid per chunk, and merges them into `grid`;
// the chunks' grids stay in `chunks` for the split's per-chunk counts.
void binParallel(const Binner& b, const PrimRef* refs, const Range& range, unsigned threads,
                 BinGrid& grid, std::vector<std::unique_ptr<BinGrid>>& chunks,
                 std::uint32_t& chunkSize) {
    const std::uint32_t n = range.size();
    const std::uint32_t wanted = std::max<std::uint32_t>(
        1, std::min<std::uint32_t>(threads * SahBinning::kChunksPerThread,
                                   n / SahBinning::kMinChunk));
    chunkSize = (n + wanted - 1) / wanted;
    chunks.resize((n + chunkSize - 1) / chunkSize);
    parallelFor(chunks.size(), 1, [&](std::size_t lo, std::size_t hi) {
        for (std::size_t c = lo; c < hi; ++c) {
            chunks[c] = std::make_unique<BinGrid>();
            chunks[c]->reset(b.bins);
            const std::uint32_t begin = range.begin + std::uint32_t(c) * chunkSize;
            binRange(b, refs, begin, std::min(range.end, begin + chunkSize), *chunks[c]);
        }
    });
    for (const auto& c : chunks) grid.merge(*c, b.bins);
}

// The children of a chosen split, read off its axis's bins.
void fillChildren(const BinGrid& grid, const Range& range, Split& split) {
    std::uint32_t leftCount = 0;
    for (int i = 0; i < split.binner.bins; ++i) {
        Range& side = i <= split.bin ? split.left : split.right;
        side.bounds.grow(grid.box(split.axis, i));
        if (i <= split.bin) leftCount += grid.count(split.axis, i);
    }
    // The children's centroid bounds, which only steer their binning, are not tracked per bin
    // (that would cost a third of the binning loop): each child's box clipped to the parent's
    // centroid bounds, and on the split axis to the plane between the bins, is a close fit.
    const int a = split.axis;
    const float plane = split.binner.origin[a] + float(split.bin + 1) / split.binner.scale[a];
    for (Range* side : {&split.left, &split.right}) {
        side->centroids.lo = simd::vmax(side->bounds.lo, range.centroids.lo);
        side->centroids.hi = simd::vmin(side->bounds.hi, range.centroids.hi);
    }
    if (plane < split.left.centroids.hi[a] && plane >= split.left.centroids.lo[a])
        split.left.centroids.hi[a] = plane;
    if (plane > split.right.centroids.lo[a] && plane <= split.right.centroids.hi[a])
        split.right.centroids.lo[a] = plane;
    split.left.begin = range.begin;
    split.left.end = split.right.begin = range.begin + leftCount;
    split.right.end = range.end;
}

simd::I4 counts(const BinGrid& grid, int i) {
    return simd::I4{std::int32_t(grid.count(0, i)), std::int32_t(grid.count(1, i)),
                    std::int32_t(grid.count(2, i)), 0};
}

F4 select(simd::I4 mask, F4 a, F4 b) { return mask ? a : b; }

}  // namespace

// Bin counts ride in a float lane through vmin (BinGrid::addOne), and small integers read as
// floats are denormals: a thread that flushes denormals (DAZ, FPCR.FZ; nothing in Penumbra sets
// them, but an embedding program might) would zero every count and build a useless tree.
namespace {
bool denormalsSurviveMin() {
    volatile std::uint32_t one = 1;
    const F4 count{0.0f, 0.0f, 0.0f, std::bit_cast<float>(std::uint32_t(one))};
    return std::bit_cast<std::uint32_t>(simd::vmin(count, simd::kPosInf)[3]) == 1u;
}
}  // namespace

SahBinning::SahBinning(const BuildOptions& options)
    : bins_(std::clamp(options.bins, 2, kMaxBins)),
      leafSize_(std::uint32_t(std::max(options.maxLeafSize, 1))),
      ct_(options.traversalCost),
      ci_(options.intersectCost) {
    PN_CHECK(denormalsSurviveMin());
}

// Mid-sized nodes get kFewBins bins and the smallest binned ones one bin per primitive: most
// nodes are small, and there the bins' reset and sweep outweigh the binning itself.
int SahBinning::binCount(const Range& range) const {
    const std::uint32_t n = range.size();
    const std::uint32_t wanted =
        n <= kFewBinsNode ? std::min(kFewBins, std::uint32_t(bins_)) : std::uint32_t(bins_);
    return int(std::min(wanted, std::max(2u, n)));
}

// Every candidate plane of all three axes in two passes over the bins, the axes in the lanes
// of one vector. Costs are scaled by the node's area (no division), so flat or point-like nodes
// compare as 0 against 0 instead of producing NaN; candidates with an empty side, and axes
// without extent, cost infinity.
void SahBinning::sweep(const BinGrid& grid, const Binner& b, const Range& range,
                       Split& best) const {
    using simd::I4;
    const float nodeCost = ct_ * range.bounds.halfArea();
    const I4 zero{0, 0, 0, 0}, all{int(range.size()), int(range.size()), int(range.size()), -1};
    const I4 axisUsable = b.scale != F4{0, 0, 0, 0};
    F4 rightCost[kMaxBins];  // written before read
    Box4 x, y, z;
    I4 count = zero;
    for (int i = b.bins - 1; i > 0; --i) {
        x.grow(grid.box(0, i));
        y.grow(grid.box(1, i));
        z.grow(grid.box(2, i));
        count += counts(grid, i);
        rightCost[i] =
            select(count > zero, __builtin_convertvector(count, F4) * halfAreas(x, y, z), F4{});
    }
    x = y = z = Box4{};
    count = zero;
    F4 bestCost = simd::kPosInf;
    I4 bestBin = zero;
    for (int i = 0; i < b.bins - 1; ++i) {
        x.grow(grid.box(0, i));
        y.grow(grid.box(1, i));
        z.grow(grid.box(2, i));
        count += counts(grid, i);
        const F4 cost = nodeCost + ci_ * (__builtin_convertvector(count, F4) * halfAreas(x, y, z) +
                                          rightCost[i + 1]);
        const I4 better = (count > zero) & (count < all) & axisUsable & (cost < bestCost);
        bestCost = select(better, cost, bestCost);
        bestBin = better ? I4{i, i, i, i} : bestBin;
    }
    for (int a = 0; a < 3; ++a)  // lowest axis first on ties, as a scalar scan would choose
        if (bestCost[a] < best.cost) {
            best.axis = a;
            best.bin = bestBin[a];
            best.cost = bestCost[a];
        }
    // Every candidate may have been NaN (areas overflowing to inf); then take any valid split,
    // because a node above the leaf size must be split anyway.
    for (int a = 0; a < 3 && best.axis < 0; ++a) {
        std::uint32_t n = 0;
        for (int i = 0; i < b.bins - 1; ++i) {
            n += grid.count(a, i);
            if (n > 0 && n < range.size()) {
                best.axis = a;
                best.bin = i;
                break;
            }
        }
    }
}

Split SahBinning::find(const PrimRef* refs, const Range& range, unsigned threads) const {
    Split best;
    if (range.centroids.empty()) return best;
    const Binner b(range, binCount(range));
    if (b.scale[0] == 0 && b.scale[1] == 0 && b.scale[2] == 0)
        return best;  // all centroids coincide

    BinGrid grid;  // ~26 KiB of stack; this frame is gone before the recursion goes deeper
    grid.reset(b.bins);
    std::vector<std::unique_ptr<BinGrid>> chunks;
    std::uint32_t chunkSize = 0;
    if (threads > 1)
        binParallel(b, refs, range, threads, grid, chunks, chunkSize);
    else
        binRange(b, refs, range.begin, range.end, grid);

    sweep(grid, b, range, best);
    best.binner = b;
    if (best.axis < 0) return best;
    fillChildren(grid, range, best);
    if (chunks.size() > 1) {
        best.chunkSize = chunkSize;
        best.chunkLeft.resize(chunks.size());
        for (std::size_t c = 0; c < chunks.size(); ++c)
            for (int i = 0; i <= best.bin; ++i) best.chunkLeft[c] += chunks[c]->count(best.axis, i);
    }
    return best;
}

namespace {

// Branch-free: left primitives fill dst from index l up, right ones from index r - 1 down, and
// the side only selects the store address (by a mask, so no compiler turns it into a jump).
// "Index <= last" is decided on the unclamped bin coordinate f: the clamped, truncated index is
// <= last exactly when f < last + 1, NaN included (it clamps to bin 0), as binning computed it.
// Returns how many went left.
std::uint32_t partitionRange(const PrimRef* src, PrimRef* dst, std::uint32_t begin,
                             std::uint32_t end, std::uint32_t l, std::uint32_t r,
                             const Split& split) {
    const Binner& b = split.binner;
    const int axis = split.axis;
    const float origin = b.origin[axis], scale = b.scale[axis], bound = float(split.bin + 1);
    const std::uint32_t first = l;
    for (std::uint32_t i = begin; i < end; ++i) {
        const PrimRef p = src[i];
        const float f = (p.centroid()[axis] - origin) * scale;
        const std::uint32_t left = !(f >= bound);
        const std::uint32_t mask = 0u - left;
        dst[(l & mask) | ((r - 1) & ~mask)] = p;
        l += left;
        r -= 1 - left;
    }
    return l - first;
}

}  // namespace

// In parallel, chunk c's left primitives start after those of the chunks before it, and its
// right ones below theirs, which is where the serial pass puts them. The counts come from
// binning; should this pass ever disagree with them, the serial pass redoes the whole range.
std::uint32_t SahBinning::partition(const PrimRef* src, PrimRef* dst, const Range& range,
                                    const Split& split) const {
    const std::size_t chunks = split.chunkLeft.size();
    if (chunks > 1) {
        std::vector<std::uint32_t> leftBefore(chunks + 1, 0);
        for (std::size_t c = 0; c < chunks; ++c)
            leftBefore[c + 1] = leftBefore[c] + split.chunkLeft[c];
        std::atomic<bool> agree{leftBefore[chunks] <= range.size()};
        if (agree)
            parallelFor(chunks, 1, [&](std::size_t lo, std::size_t hi) {
                for (std::size_t c = lo; c < hi; ++c) {
                    const std::uint32_t offset = std::uint32_t(c) * split.chunkSize;
                    const std::uint32_t begin = range.begin + offset;
                    const std::uint32_t end = std::min(range.end, begin + split.chunkSize);
                    const std::uint32_t l = range.begin + leftBefore[c];
                    const std::uint32_t r = range.end - (offset - leftBefore[c]);
                    if (partitionRange(src, dst, begin, end, l, r, split) != split.chunkLeft[c])
                        agree = false;
                }
            });
        if (agree) return leftBefore[chunks];
    }
    return partitionRange(src, dst, range.begin, range.end, range.begin, range.end, split);
}

void SahBinning::medianSplit(PrimRef* refs, const Range& range, Range& left, Range& right) const {
    const std::uint32_t mid = range.begin + range.size() / 2;
    const F4 extent = range.centroids.hi - range.centroids.lo;
    const int axis =
        extent[0] >= extent[1] && extent[0] >= extent[2] ? 0 : (extent[1] >= extent[2] ? 1 : 2);
    if (extent[axis] > 0) {
        std::nth_element(refs + range.begin, refs + mid, refs + range.end,
                         [axis](const PrimRef& p, const PrimRef& q) {
                             return p.centroid()[axis] < q.centroid()[axis];
                         });
    }
    left = gather(refs, range.begin, mid);
    right = gather(refs, mid, range.end);
}

}  // namespace penumbra::bvh::sah
