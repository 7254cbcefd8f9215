#include "bvh/builder.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "bvh/sah_binning.h"
#include "core/big_buffer.h"
#include "core/error.h"
#include "core/parallel.h"

namespace penumbra::bvh {
namespace {

using sah::PrimRef;
using sah::Range;
using sah::Split;

// At or above this many primitives a node's right subtree becomes a task another thread can
// take; below it, thread hand-over would cost more than the work.
constexpr std::uint32_t kParallelSubtrees = 4 * 1024;
// Nodes this large, and larger than one thread's share of the whole build, bin on every thread
// (near the root, where the other threads have nothing else to do yet).
constexpr std::uint32_t kParallelBinning = 64 * 1024;

// Faults in the pages of [data, data + bytes) on all threads (Linux MADV_POPULATE_WRITE, 2 MiB
// per call) before a serial pass first writes them: the kernel zeroes each fresh page on its
// first touch, which for a large output costs more than the writes themselves. Contents are not
// changed; failure (an old kernel) only means the serial pass pays for the faults. Measured
// (1M-triangle soup): H200 host, 16 threads 41.9 -> 38.3 ms with it, but two of its cores
// 188.5 -> 195.5 ms; on the 2-core dev machine, where fresh pages cost more, two threads gain
// (about 128 -> 123 ms, medians), so only a single thread skips it.
void prefault(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    if (hardwareThreads() < 2) return;
    constexpr std::uintptr_t kPage = 4096, kStep = std::uintptr_t(2) << 20;
    const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(data) / kPage * kPage;
    const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(data) + bytes;
    if (bytes < 2 * kStep) return;
    parallelFor((end - begin + kStep - 1) / kStep, 1, [&](std::size_t lo, std::size_t hi) {
        const std::uintptr_t from = begin + lo * kStep, to = std::min(end, begin + hi * kStep);
        madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
    });
#else
    (void)data;
    (void)bytes;
#endif
}

// Levels of balanced splits needed before every leaf holds at most leafSize primitives.
int levelsNeeded(std::uint32_t count, std::uint32_t leafSize) {
    std::uint64_t leaves = (std::uint64_t(count) + leafSize - 1) / leafSize;
    int levels = 0;
    while ((std::uint64_t(1) << levels) < leaves) ++levels;
    return levels;
}

class Builder {
public:
    // refs[0] holds the references; refs[1] is as large, for out-of-place partitions: a node
    // at depth d finds its primitives in refs[(d - 1) % 2]. primOrder must have one entry per
    // reference; leaves fill it.
    Builder(BigBuffer<PrimRef>* refs, std::uint32_t* primOrder, shader::BvhNode* slots,
            const BuildOptions& options)
        : refs_(refs),
          primOrder_(primOrder),
          slots_(slots),
          total_(std::uint32_t(refs[0].size())),
          threads_(hardwareThreads()),
          sah_(options) {}

    // The slots one task writes form runs of consecutive slots: a task writes in increasing slot
    // order and jumps only over the reservation of a subtree it handed on (which another task
    // fills, maybe not completely). compact() closes the gaps between the runs.
    struct Writer {
        std::uint32_t begin = 0, next = 0;  // the open run: [begin, next)
    };

    // Writes the subtree of `range` (its primitives in refs_[side]) depth-first from `slot` and
    // returns one past the last slot it may use. A subtree over m primitives has at most 2m - 1
    // nodes, so when the right child is handed to another thread its slot is known before the
    // left subtree is built: slot + 2 * left size. Every right link is written as the child's
    // slot; compact() maps slots to final indices.
    std::uint32_t subtree(const Range& range, int depth, int side, std::uint32_t slot,
                          TaskGroup* tasks, Writer& writer) {
        shader::BvhNode& node = write(writer, slot);
        node = leaf(range);
        Range left, right;
        if (!split(range, depth, side, left, right)) {
            for (std::uint32_t i = range.begin; i < range.end; ++i)
                primOrder_[i] = refs_[side][i].id();
            return slot + 1;
        }

        node.triCount = 0;
        if (tasks && range.size() >= kParallelSubtrees) {
            const std::uint32_t rightSlot = slot + 2 * left.size();
            node.firstOrRight = rightSlot;
            tasks->spawn([this, right, depth, side, rightSlot, tasks] {
                Writer child{rightSlot, rightSlot};
                subtree(right, depth + 1, 1 - side, rightSlot, tasks, child);
                closeRun(child);
            });
            subtree(left, depth + 1, 1 - side, slot + 1, tasks, writer);
            return slot + 2 * range.size() - 1;
        }
        const std::uint32_t rightSlot = child(left, depth + 1, 1 - side, slot + 1, tasks, writer);
        node.firstOrRight = rightSlot;
        return child(right, depth + 1, 1 - side, rightSlot, tasks, writer);
    }

    // subtree(), but a single primitive, which split() always leaves alone, is written here
    // without the call: most leaves of a fine tree hold one.
    std::uint32_t child(const Range& range, int depth, int side, std::uint32_t slot,
                        TaskGroup* tasks, Writer& writer) {
        if (range.size() != 1) return subtree(range, depth, side, slot, tasks, writer);
        write(writer, slot) = leaf(range);
        primOrder_[range.begin] = refs_[side][range.begin].id();
        return slot + 1;
    }

    // Builds the whole tree from slot 0 (on the group's threads when `tasks` is given).
    void buildAll(const Range& root, TaskGroup* tasks) {
        Writer writer;
        auto body = [&] {
            subtree(root, 1, 0, 0, tasks, writer);
            closeRun(writer);
        };
        if (tasks)
            tasks->run(body);
        else
            body();
    }

    // Copies the nodes into `out` without the gaps, in depth-first order (which is slot order:
    // a handed-on subtree's reservation lies after everything its left sibling may use). Each
    // run moves by one offset, so the copy is a parallel streaming pass; only right links that
    // cross a gap need a search for their run.
    void compact(std::vector<shader::BvhNode>& out, bool parallel) {
        std::sort(runs_.begin(), runs_.end(),
                  [](const Run& a, const Run& b) { return a.begin < b.begin; });
        std::uint32_t total = 0, end = 0;
        for (Run& r : runs_) {
            PN_CHECK(r.begin >= end);  // every slot written once
            end = r.end;
            r.dest = total;
            total += r.end - r.begin;
        }
        PN_CHECK(runs_.front().begin == 0);
        reserveHuge(out, total);
        if (runs_.size() == 1) {
            // Nothing was handed on, so there are no gaps: the slots from 0 are the final array,
            // links included. A copy spares the output its zero-fill.
            out.assign(slots_, slots_ + total);
            return;
        }
        if (parallel) prefault(out.data(), std::size_t(total) * sizeof(shader::BvhNode));
        out.resize(total);
        parallelFor(runs_.size(), 1, [&](std::size_t lo, std::size_t hi) {
            for (std::size_t r = lo; r < hi; ++r) copyRun(runs_[r], out.data());
        });
    }

private:
    struct Run {
        std::uint32_t begin = 0, end = 0;  // slots
        std::uint32_t dest = 0;            // final index of slot `begin`
    };

    shader::BvhNode& write(Writer& writer, std::uint32_t slot) {
        if (slot != writer.next) {
            closeRun(writer);
            writer.begin = slot;
        }
        writer.next = slot + 1;
        return slots_[slot];
    }
    void closeRun(const Writer& writer) {
        if (writer.next == writer.begin) return;
        std::lock_guard lock(runsMutex_);
        runs_.push_back({writer.begin, writer.next, 0});
    }

    // Final index of a written slot (runs_ sorted).
    std::uint32_t finalIndex(std::uint32_t slot) const {
        auto it = std::upper_bound(runs_.begin(), runs_.end(), slot,
                                   [](std::uint32_t s, const Run& r) { return s < r.begin; });
        PN_CHECK(it != runs_.begin() && slot < std::prev(it)->end);
        --it;
        return slot - it->begin + it->dest;
    }

    // Right links point forward, mostly into the same run (the exceptions span a reservation:
    // the node that handed a subtree on, and its ancestors in the same task).
    void copyRun(const Run& run, shader::BvhNode* out) const {
        const std::uint32_t shift = run.begin - run.dest;
        for (std::uint32_t i = run.begin; i < run.end; ++i) {
            shader::BvhNode node = slots_[i];
            const bool interior = node.triCount == 0;
            if (interior && node.firstOrRight >= run.end)
                node.firstOrRight = finalIndex(node.firstOrRight);
            else
                node.firstOrRight -= interior ? shift : 0;
            out[i - shift] = node;
        }
    }

    shader::BvhNode leaf(const Range& range) const {
        shader::BvhNode node{};
        node.boundsMin = simd::vec3(range.bounds.lo);
        node.boundsMax = simd::vec3(range.bounds.hi);
        node.firstOrRight = range.begin;
        node.triCount = range.size();
        return node;
    }

    // Chooses and applies the split of a node whose primitives are in refs_[side], leaving the
    // children's in refs_[1 - side]; false makes the node a leaf (and moves nothing).
    bool split(const Range& range, int depth, int side, Range& left, Range& right) {
        const std::uint32_t n = range.size(), leafSize = sah_.leafSize();
        if (n <= 1 || (n <= leafSize && depth >= PN_BVH_MAX_DEPTH)) return false;
        if (n <= sah::SahBinning::kSmallNode) {
            const float stop = n <= leafSize ? sah_.leafCost(range) : simd::kInf;
            if (sah_.splitSmall(refs_[side].data(), refs_[1 - side].data(), range, stop, left,
                                right)) {
                if (n <= leafSize || fitsDepth(depth, left, right)) return true;
            } else {
                if (n <= leafSize) return false;
                copyRange(range, side);
            }
            sah_.medianSplit(refs_[1 - side].data(), range, left, right);
            return true;
        }
        const bool wide = n >= kParallelBinning && std::uint64_t(n) * threads_ > total_;
        const Split best = sah_.find(refs_[side].data(), range, wide ? threads_ : 1);
        if (n <= leafSize) {
            // Small enough to stop: split only where the SAH says it pays.
            if (best.axis < 0 || !(best.cost < sah_.leafCost(range))) return false;
            return apply(best, range, side, left, right);
        }
        PrimRef* dst = refs_[1 - side].data();
        if (best.axis >= 0 && apply(best, range, side, left, right)) {
            // Spaced-out geometry (exponential spacing along a line) would peel off one
            // primitive per level: keep the SAH split only if balanced splits below it can still
            // keep every leaf within PN_BVH_MAX_DEPTH.
            if (fitsDepth(depth, left, right)) return true;
        } else {
            copyRange(range, side);
        }
        sah_.medianSplit(dst, range, left, right);
        return true;
    }

    void copyRange(const Range& range, int side) {
        std::copy(refs_[side].data() + range.begin, refs_[side].data() + range.end,
                  refs_[1 - side].data() + range.begin);
    }

    bool fitsDepth(int depth, const Range& left, const Range& right) const {
        return depth + 1 + levelsNeeded(left.size(), sah_.leafSize()) <= PN_BVH_MAX_DEPTH &&
               depth + 1 + levelsNeeded(right.size(), sah_.leafSize()) <= PN_BVH_MAX_DEPTH;
    }

    bool apply(const Split& best, const Range& range, int side, Range& left, Range& right) {
        PrimRef* dst = refs_[1 - side].data();
        const std::uint32_t leftCount = sah_.partition(refs_[side].data(), dst, range, best);
        if (leftCount == best.left.size()) {
            left = best.left;
            right = best.right;
        } else {
            left = sah::gather(dst, range.begin, range.begin + leftCount);
            right = sah::gather(dst, range.begin + leftCount, range.end);
        }
        return left.size() > 0 && right.size() > 0;
    }

    BigBuffer<PrimRef>* refs_;
    std::uint32_t* primOrder_;
    shader::BvhNode* slots_;  // 2n - 1
    std::uint32_t total_;
    unsigned threads_;
    sah::SahBinning sah_;
    std::mutex runsMutex_;
    std::vector<Run> runs_;
};

}  // namespace

namespace {

// sanitizedBounds(bounds(tri)) in vector form: a triangle with any coordinate that is not
// finite gets the point box at the origin.
PrimRef triangleRef(const Triangle& t, std::uint32_t id) {
    using simd::F4;
    const F4 a = simd::vec(t.v0), b = simd::vec(t.v1), c = simd::vec(t.v2);
    const F4 zero{0, 0, 0, 0};
    const simd::I4 finite = (a * 0.0f + b * 0.0f + c * 0.0f) == zero;  // inf * 0 and NaN give NaN
    PrimRef r;
    if (finite[0] && finite[1] && finite[2]) {
        r.lo = simd::vmin(simd::vmin(a, b), c);
        r.hi = simd::vmax(simd::vmax(a, b), c);
    } else {
        r.lo = r.hi = zero;
    }
    r.lo[3] = std::bit_cast<float>(id);
    return r;
}

// Shared by build and buildTriangles, so triangles go straight into references without an
// intermediate array of boxes (at a million triangles, fresh memory is a large part of the time).
template <typename RefOf>
Bvh buildFrom(std::size_t count, RefOf&& refOf, const BuildOptions& options) {
    Bvh bvh;
    if (count == 0) return bvh;
    if (count > (std::numeric_limits<std::uint32_t>::max() - 1) / 2)
        throw Error("BVH: too many primitives (" + std::to_string(count) + ")");

    BigBuffer<PrimRef> refs[2] = {BigBuffer<PrimRef>(count), BigBuffer<PrimRef>(count)};
    Range root;
    root.end = std::uint32_t(count);
    std::mutex merge;
    parallelFor(count, 16 * 1024, [&](std::size_t lo, std::size_t hi) {
        Range part;
        for (std::size_t i = lo; i < hi; ++i) {
            refs[0][i] = refOf(i);
            part.bounds.grow(refs[0][i].bottom(), refs[0][i].hi);
            part.centroids.grow(refs[0][i].centroid());
        }
        std::lock_guard lock(merge);
        root.bounds.grow(part.bounds);
        root.centroids.grow(part.centroids);
    });

    reserveHuge(bvh.primOrder, count);
    prefault(bvh.primOrder.data(), count * sizeof(std::uint32_t));
    bvh.primOrder.resize(count);
    // The tree is built in 2n - 1 slots, the most a binary tree over n leaves can need, left
    // uninitialised (the pages of the slots never written are never touched), and compact()
    // copies the nodes out without the gaps.
    BigBuffer<shader::BvhNode> slots(2 * count - 1);
    Builder builder(refs, bvh.primOrder.data(), slots.data(), options);
    if (count >= kParallelSubtrees && hardwareThreads() > 1) {
        TaskGroup tasks;
        builder.buildAll(root, &tasks);
        builder.compact(bvh.nodes, true);
    } else {
        builder.buildAll(root, nullptr);
        builder.compact(bvh.nodes, false);
    }
    return bvh;
}

}  // namespace

Bvh build(std::span<const Aabb> primBounds, const BuildOptions& options) {
    return buildFrom(
        primBounds.size(),
        [&](std::size_t i) {
            return PrimRef::make(sanitizedBounds(primBounds[i]), std::uint32_t(i));
        },
        options);
}

Bvh buildTriangles(std::span<const Triangle> tris, const BuildOptions& options) {
    return buildFrom(
        tris.size(), [&](std::size_t i) { return triangleRef(tris[i], std::uint32_t(i)); },
        options);
}

std::vector<shader::TriVerts> leafOrderTriVerts(const Bvh& bvh, std::span<const Triangle> tris) {
    PN_CHECK(bvh.primOrder.size() == tris.size());
    std::vector<shader::TriVerts> out(tris.size());
    for (std::size_t i = 0; i < tris.size(); ++i) out[i] = toTriVerts(tris[bvh.primOrder[i]]);
    return out;
}

}  // namespace penumbra::bvh
