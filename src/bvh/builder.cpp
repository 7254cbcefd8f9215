#include "bvh/builder.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <deque>
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

    // A share of the build run as one unit: the subtree from rootSlot less the subtrees it
    // handed on as tasks of their own. Task 0 is the root's.
    struct Task {
        std::uint32_t rootSlot = 0;
        std::uint32_t parent = 0;  // the task that handed this one on
        std::uint32_t nodes = 0;   // written by this task itself
        std::uint32_t total = 0;   // in its whole subtree, handed-on tasks included (compact())
    };

    std::uint32_t newTask(std::uint32_t rootSlot, std::uint32_t parent) {
        std::lock_guard lock(tasksMutex_);
        tasks_.push_back({rootSlot, parent, 0, 0});
        return std::uint32_t(tasks_.size() - 1);
    }
    void finishTask(std::uint32_t task, std::uint32_t nodes) {
        std::lock_guard lock(tasksMutex_);
        tasks_[task].nodes = nodes;
    }

    // Writes the subtree of `range` (its primitives in refs_[side]) depth-first from `slot` and
    // returns one past the last slot it may use; adds the nodes written to `written`. A subtree
    // over m primitives has at most 2m - 1 nodes, so when the right child is handed to another
    // thread its slot is known before the left subtree is built: slot + 2 * left size. Such
    // reservations leave gaps that compact() closes; without tasks the subtree is dense.
    // The node that hands on its right child says so (triCount kHandedOn, firstOrRight: the
    // child's task) until compact() links it.
    std::uint32_t subtree(const Range& range, int depth, int side, std::uint32_t slot,
                          TaskGroup* tasks, std::uint32_t task, std::uint32_t& written) {
        shader::BvhNode& node = slots_[slot];
        node = leaf(range);
        ++written;
        Range left, right;
        if (!split(range, depth, side, left, right)) {
            for (std::uint32_t i = range.begin; i < range.end; ++i)
                primOrder_[i] = refs_[side][i].id();
            return slot + 1;
        }

        node.triCount = 0;
        if (tasks && range.size() >= kParallelSubtrees) {
            const std::uint32_t rightSlot = slot + 2 * left.size();
            const std::uint32_t child = newTask(rightSlot, task);
            node.triCount = kHandedOn;
            node.firstOrRight = child;
            tasks->spawn([this, right, depth, side, rightSlot, tasks, child] {
                std::uint32_t nodes = 0;
                subtree(right, depth + 1, 1 - side, rightSlot, tasks, child, nodes);
                finishTask(child, nodes);
            });
            subtree(left, depth + 1, 1 - side, slot + 1, tasks, task, written);
            return slot + 2 * range.size() - 1;
        }
        const std::uint32_t rightSlot =
            subtree(left, depth + 1, 1 - side, slot + 1, tasks, task, written);
        node.firstOrRight = rightSlot;
        return subtree(right, depth + 1, 1 - side, rightSlot, tasks, task, written);
    }

    // Copies the nodes into `out` without the gaps, in depth-first order. Each task's subtree
    // size follows from the counts of the tasks (children are created after their parents), so
    // every task knows where its nodes go as soon as the task that handed it on has reached it,
    // and the tasks copy in parallel when `pool` is given.
    void compact(std::vector<shader::BvhNode>& out, TaskGroup* pool) {
        for (Task& t : tasks_) t.total = t.nodes;
        for (std::size_t id = tasks_.size(); id-- > 1;)
            tasks_[tasks_[id].parent].total += tasks_[id].total;
        reserveHuge(out, tasks_[0].total);
        if (tasks_.size() == 1) {
            // Nothing was handed on, so there are no gaps: the slots from 0 are the final array,
            // links included. A copy spares the output its zero-fill and the walk.
            out.assign(slots_, slots_ + tasks_[0].total);
            return;
        }
        if (pool) prefault(out.data(), tasks_[0].total * sizeof(shader::BvhNode));
        out.resize(tasks_[0].total);
        if (pool)
            pool->run([&] { place(0, 0, out.data(), pool); });
        else
            place(0, 0, out.data(), nullptr);
    }

private:
    static constexpr std::uint32_t kHandedOn = std::numeric_limits<std::uint32_t>::max();

    // Copies task `id`'s nodes to out[first...]: a walk from its root visits its slots in
    // increasing order, writes each node at the next index and links each right child to where
    // it lands; a handed-on child's whole subtree is skipped over and placed by its own task.
    void place(std::uint32_t id, std::uint32_t first, shader::BvhNode* out,
               TaskGroup* pool) const {
        struct Pending {
            std::uint32_t slot;    // or the task, when handedOn
            std::uint32_t parent;  // index whose right link points here, or none
            bool handedOn;
        };
        constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
        std::vector<Pending> stack{{tasks_[id].rootSlot, kNone, false}};
        std::uint32_t next = first;
        while (!stack.empty()) {
            const Pending p = stack.back();
            stack.pop_back();
            if (p.parent != kNone) out[p.parent].firstOrRight = next;
            if (p.handedOn) {
                const std::uint32_t child = p.slot, at = next;
                next += tasks_[child].total;
                if (pool)
                    pool->spawn([this, child, at, out, pool] { place(child, at, out, pool); });
                else
                    place(child, at, out, nullptr);
                continue;
            }
            shader::BvhNode node = slots_[p.slot];
            const std::uint32_t index = next++;
            if (node.triCount == kHandedOn || node.triCount == 0) {
                stack.push_back({node.firstOrRight, index, node.triCount == kHandedOn});
                stack.push_back({p.slot + 1, kNone, false});
                node.triCount = 0;
            }
            out[index] = node;
        }
        PN_CHECK(next - first == tasks_[id].total);
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
    std::mutex tasksMutex_;
    std::deque<Task> tasks_;  // a deque: references stay valid as tasks are added
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
    const std::uint32_t rootTask = builder.newTask(0, 0);
    auto buildRoot = [&](TaskGroup* tasks) {
        std::uint32_t nodes = 0;
        builder.subtree(root, 1, 0, 0, tasks, rootTask, nodes);
        builder.finishTask(rootTask, nodes);
    };
    if (count >= kParallelSubtrees && hardwareThreads() > 1) {
        TaskGroup tasks;
        tasks.run([&] { buildRoot(&tasks); });
        builder.compact(bvh.nodes, &tasks);
    } else {
        buildRoot(nullptr);
        builder.compact(bvh.nodes, nullptr);
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
