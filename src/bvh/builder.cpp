#include "bvh/builder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <utility>

#include "core/error.h"
#include "core/parallel.h"

namespace penumbra::bvh {
namespace {

// 32 bytes, so the partition passes move whole cache-line halves and never chase indices.
struct PrimRef {
    Vec3 lo;
    std::uint32_t id;
    Vec3 hi;
    std::uint32_t pad;

    Vec3 centroid() const { return lo * 0.5f + hi * 0.5f; }  // halves first: no overflow
};

struct Range {
    std::uint32_t begin = 0, end = 0;
    Aabb bounds, centroids;

    std::uint32_t size() const { return end - begin; }
};

// Trivially constructible, so a node's bins cost nothing until reset() touches the ones in use.
struct Bin {
    float lo[3], hi[3];
    std::uint32_t count;

    void reset() {
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::numeric_limits<float>::infinity();
            hi[a] = -std::numeric_limits<float>::infinity();
        }
        count = 0;
    }
    void grow(const Vec3& l, const Vec3& h, std::uint32_t n) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], l[a]);
            hi[a] = std::max(hi[a], h[a]);
        }
        count += n;
    }
    Aabb box() const { return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
};

struct Split {
    int axis = -1;
    int bin = 0;  // primitives in bins <= bin go left
    float cost = std::numeric_limits<float>::infinity();
};

// Below this many primitives a node is binned on one thread and its subtrees are not forked:
// thread start-up would cost more than the work.
constexpr std::uint32_t kParallelBinning = 64 * 1024;
constexpr std::uint32_t kParallelSubtrees = 4 * 1024;

// triCount of a node slot that no node was written to (see Builder::buildNode).
constexpr std::uint32_t kUnusedSlot = 0xffffffffu;

// Levels of balanced splits needed before every leaf holds at most leafSize primitives.
int levelsNeeded(std::uint32_t count, std::uint32_t leafSize) {
    std::uint64_t leaves = (std::uint64_t(count) + leafSize - 1) / leafSize;
    int levels = 0;
    while ((std::uint64_t(1) << levels) < leaves) ++levels;
    return levels;
}

class Builder {
public:
    Builder(PrimRef* refs, std::vector<shader::BvhNode>& nodes, const BuildOptions& options)
        : refs_(refs),
          nodes_(nodes),
          bins_(std::clamp(options.bins, 2, kMaxBins)),
          leafSize_(std::uint32_t(std::max(options.maxLeafSize, 1))),
          ct_(options.traversalCost),
          ci_(options.intersectCost) {}

    // Writes the subtree of `range` into slots [slot, slot + 2 * size - 1): a subtree over m
    // primitives has at most 2m - 1 nodes, so the right child's slot is known before the left
    // subtree is built, and both can be built at once in one shared array. Unused slots keep
    // kUnusedSlot and interior links point at slots until compact() closes the gaps.
    void buildNode(const Range& range, int depth, int budget, std::uint32_t slot) {
        nodes_[slot] = leaf(range);
        std::uint32_t n = range.size();
        if (n <= 1 || (n <= leafSize_ && depth >= PN_BVH_MAX_DEPTH)) return;

        Split split = findSplit(range, budget);
        Range left, right;
        if (n <= leafSize_) {
            // Small enough to stop: split only where the SAH says it pays.
            float leafCost = ci_ * float(n) * range.bounds.halfArea();
            if (split.axis < 0 || !(split.cost < leafCost)) return;
            partitionByBin(range, split, left, right);
        } else if (split.axis >= 0 && fitsDepth(split, range, depth, left, right)) {
            // partitioned by fitsDepth
        } else {
            medianSplit(range, left, right);
        }

        std::uint32_t rightSlot = slot + 2 * left.size();
        nodes_[slot].triCount = 0;
        nodes_[slot].firstOrRight = rightSlot;
        if (budget > 1 && n >= kParallelSubtrees) {
            int leftBudget = budget / 2, rightBudget = budget - leftBudget;
            parallelFor(2, 1, [&](std::size_t b, std::size_t e) {
                for (std::size_t i = b; i < e; ++i) {
                    if (i == 0)
                        buildNode(left, depth + 1, leftBudget, slot + 1);
                    else
                        buildNode(right, depth + 1, rightBudget, rightSlot);
                }
            });
        } else {
            buildNode(left, depth + 1, 1, slot + 1);
            buildNode(right, depth + 1, 1, rightSlot);
        }
    }

    // Squeezes out unused slots. Slots are in depth-first order already, so one forward pass
    // suffices; right links are patched when their target is reached, and since right children
    // come in last-opened-first order a stack of open parents is enough.
    void compact() {
        struct Open {
            std::uint32_t rightSlot, parent;
        };
        std::vector<Open> open;
        std::uint32_t written = 0;
        for (std::uint32_t s = 0; s < nodes_.size(); ++s) {
            shader::BvhNode node = nodes_[s];
            if (node.triCount == kUnusedSlot) continue;
            if (!open.empty() && open.back().rightSlot == s) {
                nodes_[open.back().parent].firstOrRight = written;
                open.pop_back();
            }
            if (node.triCount == 0) open.push_back({node.firstOrRight, written});
            nodes_[written++] = node;
        }
        PN_CHECK(open.empty());
        nodes_.resize(written);
        if (written < nodes_.capacity() / 2) nodes_.shrink_to_fit();
    }

private:
    shader::BvhNode leaf(const Range& range) const {
        shader::BvhNode node{};
        node.boundsMin = range.bounds.lo;
        node.boundsMax = range.bounds.hi;
        node.firstOrRight = range.begin;
        node.triCount = range.size();
        return node;
    }

    // Maps centroids to bins; axes without extent (or with one too small or too large for a
    // finite scale) get scale 0, which puts everything in bin 0 and so offers no split.
    struct Binner {
        Vec3 origin, scale;
        int bins;
        int index(const Vec3& c, int axis) const {
            float f = (c[axis] - origin[axis]) * scale[axis];
            // max(0, NaN) is 0 with std::max's argument order, so the cast is always defined.
            return int(std::min(float(bins - 1), std::max(0.0f, f)));
        }
    };

    // Small nodes get one bin per primitive: as many candidates as sixteen bins would give
    // them in practice, at a fraction of the sweep cost, and most nodes are small.
    int binCount(const Range& range) const {
        return int(std::min<std::uint32_t>(std::uint32_t(bins_), std::max(2u, range.size())));
    }

    Binner binner(const Range& range) const {
        int bins = binCount(range);
        Binner b{range.centroids.lo, Vec3(0.0f), bins};
        Vec3 extent = range.centroids.extent();
        for (int a = 0; a < 3; ++a) {
            float s = float(bins) / extent[a];
            b.scale[a] = (extent[a] > 0 && std::isfinite(s)) ? s : 0.0f;
        }
        return b;
    }

    struct BinGrid {
        Bin bins[3][kMaxBins];
        void reset(int count) {
            for (auto& axis : bins)
                for (int i = 0; i < count; ++i) axis[i].reset();
        }
    };

    void binRange(const Binner& b, std::uint32_t begin, std::uint32_t end, BinGrid& grid) const {
        for (std::uint32_t i = begin; i < end; ++i) {
            const PrimRef& r = refs_[i];
            Vec3 c = r.centroid();
            for (int a = 0; a < 3; ++a) grid.bins[a][b.index(c, a)].grow(r.lo, r.hi, 1);
        }
    }

    Split findSplit(const Range& range, int budget) const {
        Split best;
        if (range.centroids.empty()) return best;
        Binner b = binner(range);
        if (b.scale == Vec3(0.0f)) return best;  // all centroids coincide

        BinGrid grid;  // ~11 KiB of stack; this frame is gone before the recursion goes deeper
        grid.reset(b.bins);
        if (budget > 1 && range.size() >= kParallelBinning) {
            std::mutex merge;
            parallelFor(range.size(), kParallelBinning / 4, [&](std::size_t lo, std::size_t hi) {
                auto local = std::make_unique<BinGrid>();
                local->reset(b.bins);
                binRange(b, range.begin + std::uint32_t(lo), range.begin + std::uint32_t(hi),
                         *local);
                std::lock_guard lock(merge);
                for (int a = 0; a < 3; ++a)
                    for (int i = 0; i < b.bins; ++i) {
                        const Bin& src = local->bins[a][i];
                        grid.bins[a][i].grow({src.lo[0], src.lo[1], src.lo[2]},
                                             {src.hi[0], src.hi[1], src.hi[2]}, src.count);
                    }
            });
        } else {
            binRange(b, range.begin, range.end, grid);
        }

        // Costs are scaled by the node's area (no division), so flat or point-like nodes compare
        // as 0 against 0 instead of producing NaN.
        std::array<float, kMaxBins> rightCost;  // written before read
        for (int a = 0; a < 3; ++a) {
            if (b.scale[a] == 0) continue;
            const Bin* bins = grid.bins[a];
            Aabb box;
            std::uint32_t count = 0;
            for (int i = b.bins - 1; i > 0; --i) {
                if (bins[i].count) box.grow(bins[i].box());
                count += bins[i].count;
                rightCost[i] = float(count) * box.halfArea();
            }
            box = Aabb{};
            count = 0;
            for (int i = 0; i < b.bins - 1; ++i) {
                if (bins[i].count) box.grow(bins[i].box());
                count += bins[i].count;
                if (count == 0 || count == range.size()) continue;
                float cost = ct_ * range.bounds.halfArea() +
                             ci_ * (float(count) * box.halfArea() + rightCost[i + 1]);
                if (cost < best.cost) best = {a, i, cost};
            }
        }
        // Every candidate may have been NaN (areas overflowing to inf); then take any valid
        // split, because a node above the leaf size must be split anyway.
        if (best.axis < 0) {
            for (int a = 0; a < 3 && best.axis < 0; ++a) {
                std::uint32_t count = 0;
                for (int i = 0; i < b.bins - 1; ++i) {
                    count += grid.bins[a][i].count;
                    if (count > 0 && count < range.size()) {
                        best = {a, i, std::numeric_limits<float>::infinity()};
                        break;
                    }
                }
            }
        }
        return best;
    }

    // Hoare partition that also gathers both children's boxes, so no extra pass is needed.
    void partitionByBin(const Range& range, const Split& split, Range& left, Range& right) const {
        Binner b = binner(range);
        left = right = Range{};
        auto goesLeft = [&](const PrimRef& r) {
            return b.index(r.centroid(), split.axis) <= split.bin;
        };
        auto add = [](Range& side, const PrimRef& r) {
            side.bounds.lo = min(side.bounds.lo, r.lo);
            side.bounds.hi = max(side.bounds.hi, r.hi);
            side.centroids.grow(r.centroid());
        };
        std::uint32_t i = range.begin, j = range.end;
        for (;;) {
            while (i < j && goesLeft(refs_[i])) add(left, refs_[i++]);
            while (i < j && !goesLeft(refs_[j - 1])) add(right, refs_[--j]);
            if (i >= j) break;
            add(right, refs_[i]);
            add(left, refs_[j - 1]);
            std::swap(refs_[i++], refs_[--j]);
        }
        left.begin = range.begin;
        left.end = right.begin = i;
        right.end = range.end;
        PN_CHECK(left.size() > 0 && right.size() > 0);
    }

    // Takes the SAH split only if balanced splits below it could still keep every leaf within
    // PN_BVH_MAX_DEPTH; spaced-out geometry (exponential spacing along a line) otherwise peels
    // off one primitive per level.
    bool fitsDepth(const Split& split, const Range& range, int depth, Range& left, Range& right) {
        partitionByBin(range, split, left, right);
        bool fits = depth + 1 + levelsNeeded(left.size(), leafSize_) <= PN_BVH_MAX_DEPTH &&
                    depth + 1 + levelsNeeded(right.size(), leafSize_) <= PN_BVH_MAX_DEPTH;
        return fits;
    }

    // Halves the range by count: along the widest centroid axis, or by index when all centroids
    // coincide. Each half needs one level fewer, which is what makes the depth bound hold.
    void medianSplit(const Range& range, Range& left, Range& right) {
        std::uint32_t mid = range.begin + range.size() / 2;
        Vec3 extent = range.centroids.extent();
        int axis =
            extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        if (extent[axis] > 0) {
            std::nth_element(refs_ + range.begin, refs_ + mid, refs_ + range.end,
                             [axis](const PrimRef& a, const PrimRef& b) {
                                 return a.centroid()[axis] < b.centroid()[axis];
                             });
        }
        left = right = Range{};
        left.begin = range.begin;
        left.end = right.begin = mid;
        right.end = range.end;
        for (Range* side : {&left, &right})
            for (std::uint32_t i = side->begin; i < side->end; ++i) {
                side->bounds.lo = min(side->bounds.lo, refs_[i].lo);
                side->bounds.hi = max(side->bounds.hi, refs_[i].hi);
                side->centroids.grow(refs_[i].centroid());
            }
    }

    PrimRef* refs_;
    std::vector<shader::BvhNode>& nodes_;
    int bins_;
    std::uint32_t leafSize_;
    float ct_, ci_;
};

}  // namespace

Aabb sanitizedBounds(const Aabb& box) {
    if (box.empty() || !isFinite(box.lo) || !isFinite(box.hi)) return Aabb{Vec3(0.0f), Vec3(0.0f)};
    return box;
}

namespace {

// Shared by build and buildTriangles, so triangles go straight into references without an
// intermediate array of boxes (at a million triangles, fresh memory is a large part of the time).
template <typename BoundsOf>
Bvh buildFrom(std::size_t count, BoundsOf&& boundsOf, const BuildOptions& options) {
    Bvh bvh;
    if (count == 0) return bvh;
    if (count > (std::numeric_limits<std::uint32_t>::max() - 1) / 2)
        throw Error("BVH: too many primitives (" + std::to_string(count) + ")");

    // Uninitialised on purpose (PrimRef is an aggregate, so the bytes become objects when first
    // written): zeroing 32 MB on one thread first would cost more than the first two levels.
    std::unique_ptr<std::byte[]> refStorage(new std::byte[count * sizeof(PrimRef)]);
    auto* refs = std::launder(reinterpret_cast<PrimRef*>(refStorage.get()));
    // A binary tree over n non-empty leaves has at most 2n - 1 nodes. Filling the slots here
    // also takes the page faults on every thread rather than on whichever builds the subtree.
    bvh.nodes.resize(2 * count - 1);
    Range root;
    root.end = std::uint32_t(count);
    std::mutex merge;
    parallelFor(count, 16 * 1024, [&](std::size_t lo, std::size_t hi) {
        Aabb bounds, centroids;
        for (std::size_t i = lo; i < hi; ++i) {
            Aabb box = sanitizedBounds(boundsOf(i));
            refs[i] = {box.lo, std::uint32_t(i), box.hi, 0};
            bounds.grow(box);
            centroids.grow(refs[i].centroid());
        }
        for (std::size_t i = 2 * lo; i < std::min(2 * hi, 2 * count - 1); ++i)
            bvh.nodes[i].triCount = kUnusedSlot;
        std::lock_guard lock(merge);
        root.bounds.grow(bounds);
        root.centroids.grow(centroids);
    });

    Builder builder(refs, bvh.nodes, options);
    builder.buildNode(root, 1, int(2 * hardwareThreads()), 0);
    builder.compact();

    bvh.primOrder.resize(count);
    for (std::size_t i = 0; i < count; ++i) bvh.primOrder[i] = refs[i].id;
    return bvh;
}

}  // namespace

Bvh build(std::span<const Aabb> primBounds, const BuildOptions& options) {
    return buildFrom(
        primBounds.size(), [&](std::size_t i) { return primBounds[i]; }, options);
}

Bvh buildTriangles(std::span<const Triangle> tris, const BuildOptions& options) {
    return buildFrom(
        tris.size(), [&](std::size_t i) { return bounds(tris[i]); }, options);
}

std::vector<shader::TriVerts> leafOrderTriVerts(const Bvh& bvh, std::span<const Triangle> tris) {
    PN_CHECK(bvh.primOrder.size() == tris.size());
    std::vector<shader::TriVerts> out(tris.size());
    for (std::size_t i = 0; i < tris.size(); ++i) out[i] = toTriVerts(tris[bvh.primOrder[i]]);
    return out;
}

}  // namespace penumbra::bvh
