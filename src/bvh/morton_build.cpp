#include "bvh/morton_build.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <utility>

#include "core/error.h"
#include "core/parallel.h"
#include "shared/morton.h"

namespace penumbra::bvh {
namespace {

constexpr int kPasses = 3, kRadixBits = 10;
constexpr std::uint32_t kRadix = 1u << kRadixBits;
// Work per parallel task (keys, boxes, a subtree's primitives): below it one thread does all, so
// small builds never pay for tasks. Chunk boundaries depend on this alone, never on the thread
// count (the sort's chunks may: its result is unique), so a parallel build is the serial one to
// the bit.
constexpr std::size_t kParallelGrain = kMortonParallelGrain;

std::uint32_t codeOf(std::uint64_t key) { return std::uint32_t(key >> 32); }
std::uint32_t indexOf(std::uint64_t key) { return std::uint32_t(key); }

// Sorts keys by their code (the high 32 bits; 30 used): three 10-bit counting passes, their
// histograms counted in one read. Stable, so equal codes keep index order.
void radixSortSerial(std::vector<std::uint64_t>& keys, std::vector<std::uint64_t>& tmp) {
    constexpr std::uint32_t kMask = kRadix - 1;
    std::array<std::array<std::uint32_t, kRadix>, kPasses> start{};
    for (std::uint64_t k : keys)
        for (int p = 0; p < kPasses; ++p) ++start[p][(codeOf(k) >> (p * kRadixBits)) & kMask];
    tmp.resize(keys.size());
    for (int p = 0; p < kPasses; ++p) {
        std::uint32_t sum = 0;
        for (std::uint32_t& s : start[p]) sum += std::exchange(s, sum);
        for (std::uint64_t k : keys) tmp[start[p][(codeOf(k) >> (p * kRadixBits)) & kMask]++] = k;
        keys.swap(tmp);
    }
}

// The same sort over chunks of the keys: per pass, each chunk's histogram is counted in
// parallel, a digit's slots go to the chunks in chunk order, and each chunk scatters its own keys
// in order. A stable sort's result is unique, so it is the serial sort's for any chunking: one
// chunk per worker (at least kParallelGrain keys each) keeps the serial prefix sum small.
void radixSortParallel(std::vector<std::uint64_t>& keys, MortonScratch& scratch) {
    constexpr std::uint32_t kMask = kRadix - 1;
    const std::size_t n = keys.size();
    const std::size_t workers = hardwareThreads();
    std::size_t chunks = std::min((n + kParallelGrain - 1) / kParallelGrain, workers);
    const std::size_t chunkSize = (n + chunks - 1) / chunks;
    chunks = (n + chunkSize - 1) / chunkSize;  // rounding up the size may leave fewer
    std::vector<std::uint64_t>& tmp = scratch.keysTmp;
    std::vector<std::uint32_t>& start = scratch.chunkStarts;  // [chunk][digit]
    tmp.resize(n);
    start.resize(chunks * kRadix);
    for (int p = 0; p < kPasses; ++p) {
        const int shift = p * kRadixBits;
        parallelChunks(n, chunkSize, [&](std::size_t c, std::size_t first, std::size_t last) {
            std::uint32_t* h = &start[c * kRadix];
            std::fill(h, h + kRadix, 0u);
            for (std::size_t i = first; i < last; ++i) ++h[(codeOf(keys[i]) >> shift) & kMask];
        });
        std::uint32_t sum = 0;
        for (std::uint32_t d = 0; d < kRadix; ++d)
            for (std::size_t c = 0; c < chunks; ++c) sum += std::exchange(start[c * kRadix + d], sum);
        parallelChunks(n, chunkSize, [&](std::size_t c, std::size_t first, std::size_t last) {
            std::uint32_t* h = &start[c * kRadix];
            for (std::size_t i = first; i < last; ++i) {
                const std::uint64_t k = keys[i];
                tmp[h[(codeOf(k) >> shift) & kMask]++] = k;
            }
        });
        keys.swap(tmp);
    }
}

struct CentreBounds {
    Vec3 lo{std::numeric_limits<float>::infinity()}, hi{-std::numeric_limits<float>::infinity()};
};

// Sanitizes boxes [first, last) into scratch.boxes and grows `into` by their centres. min and
// max are exact, so chunks joined in any order give the serial bounds.
void sanitizeRange(std::span<const Aabb> primBounds, std::vector<Aabb>& boxes, std::size_t first, std::size_t last,
                   CentreBounds& into) {
    for (std::size_t i = first; i < last; ++i) {
        const Aabb s = sanitizedBounds(primBounds[i]);
        boxes[i] = s;
        const Vec3 c = (s.lo + s.hi) * 0.5f;
        into.lo = min(into.lo, c);
        into.hi = max(into.hi, c);
    }
}

// The sanitized boxes, their centres' bounds, then each primitive's key.
void computeKeys(std::span<const Aabb> primBounds, MortonScratch& scratch, bool parallel) {
    const std::size_t n = primBounds.size();
    scratch.boxes.resize(n);
    CentreBounds centres;
    if (parallel) {
        std::vector<CentreBounds> perChunk((n + kParallelGrain - 1) / kParallelGrain);
        parallelChunks(n, kParallelGrain, [&](std::size_t c, std::size_t first, std::size_t last) {
            sanitizeRange(primBounds, scratch.boxes, first, last, perChunk[c]);
        });
        for (const CentreBounds& b : perChunk) centres = {min(centres.lo, b.lo), max(centres.hi, b.hi)};
    } else {
        sanitizeRange(primBounds, scratch.boxes, 0, n, centres);
    }
    const Vec3 lo = centres.lo, hi = centres.hi;
    // Cubic cells: shared/morton.h says why; the GPU build (shaders/lbvh_morton.comp) uses the same.
    const float size = maxComponent(hi - lo);
    const float scale = size > 0 ? float(PN_MORTON_CELLS) / size : 0.0f;
    scratch.keys.resize(n);
    auto codeRange = [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
            const Aabb& s = scratch.boxes[i];
            const Vec3 c = (s.lo + s.hi) * 0.5f - lo;
            const std::uint32_t code = shader::pnMortonCode(c, scale);
            scratch.keys[i] = (std::uint64_t(code) << 32) | std::uint64_t(i);
        }
    };
    if (parallel)
        parallelFor(n, kParallelGrain, codeRange);
    else
        codeRange(0, n);
}

struct Builder {
    const std::vector<Aabb>& boxes;          // sanitized, original order
    const std::vector<std::uint64_t>& keys;  // sorted
    shader::BvhNode* nodes;                  // room for 2n - 1 nodes
    std::uint32_t base;                      // the index of nodes[0] in the output array
    bool leafHoldsPrimitive;  // leaf firstOrRight: the primitive's index (else its sorted position)
    bool parallel;

    // Where [first, last) splits: after the last code that has the range's highest differing
    // bit clear; the middle when all codes are equal or the tree must not grow deeper.
    std::size_t split(std::size_t first, std::size_t last, int depth) const {
        const std::uint32_t a = codeOf(keys[first]), b = codeOf(keys[last - 1]);
        const int levelsNeeded = std::bit_width(last - first);  // for median splits from here
        if (a == b || depth + levelsNeeded >= PN_BVH_MAX_DEPTH) return first + (last - first) / 2;
        const std::uint32_t bit = std::uint32_t(1) << (31 - std::countl_zero(a ^ b));
        // The first code in the range with `bit` set (codes are sorted and agree above it).
        const auto it = std::partition_point(keys.begin() + std::ptrdiff_t(first), keys.begin() + std::ptrdiff_t(last),
                                             [&](std::uint64_t k) { return (codeOf(k) & bit) == 0; });
        return std::size_t(it - keys.begin());
    }

    void leaf(std::size_t position, std::uint32_t slot) const {
        const std::uint32_t prim = indexOf(keys[position]);
        const Aabb& box = boxes[prim];
        nodes[slot] = {box.lo, leafHoldsPrimitive ? prim : static_cast<std::uint32_t>(position), box.hi, 1u};
    }

    // Emits the subtree over sorted range [first, last) depth-first from `slot` on. A subtree
    // over m primitives takes exactly 2m - 1 slots, so the right child's slot is known before
    // the left subtree is built: large subtrees are built in parallel into the slots a serial
    // build gives them. Half the nodes are leaves, written here without a call of their own.
    void emit(std::size_t first, std::size_t last, int depth, std::uint32_t slot) const {
        if (last - first == 1) return leaf(first, slot);
        const std::size_t mid = split(first, last, depth);
        const std::uint32_t left = slot + 1, right = slot + 2 * std::uint32_t(mid - first);
        auto emitLeft = [&] { mid - first == 1 ? leaf(first, left) : emit(first, mid, depth + 1, left); };
        auto emitRight = [&] { last - mid == 1 ? leaf(mid, right) : emit(mid, last, depth + 1, right); };
        if (parallel && std::min(mid - first, last - mid) >= kParallelGrain) {
            parallelInvoke(emitLeft, emitRight);
        } else {
            emitLeft();
            emitRight();
        }
        const shader::BvhNode &l = nodes[left], &r = nodes[right];
        nodes[slot] = {min(l.boundsMin, r.boundsMin), base + right, max(l.boundsMax, r.boundsMax), 0u};
    }
};

void buildInto(std::span<const Aabb> primBounds, std::vector<shader::BvhNode>& nodes, MortonScratch& scratch,
               bool leafHoldsPrimitive, BuildThreads threads) {
    const std::size_t n = primBounds.size();
    if (n == 0) return;
    const bool parallel = threads == BuildThreads::Pool && n >= 2 * kParallelGrain;
    computeKeys(primBounds, scratch, parallel);
    if (parallel) radixSortParallel(scratch.keys, scratch);
    else radixSortSerial(scratch.keys, scratch.keysTmp);
    const std::size_t base = nodes.size();
    nodes.resize(base + 2 * n - 1);
    const Builder builder{scratch.boxes, scratch.keys, nodes.data() + base, static_cast<std::uint32_t>(base),
                          leafHoldsPrimitive, parallel};
    builder.emit(0, n, 1, 0);
}

}  // namespace

Bvh buildMorton(std::span<const Aabb> primBounds, BuildThreads threads) {
    Bvh bvh;
    MortonScratch scratch;
    buildInto(primBounds, bvh.nodes, scratch, false, threads);
    bvh.primOrder.reserve(scratch.keys.size());
    for (std::uint64_t k : scratch.keys) bvh.primOrder.push_back(indexOf(k));
    return bvh;
}

void appendMorton(std::span<const Aabb> primBounds, std::vector<shader::BvhNode>& nodes, MortonScratch& scratch,
                  BuildThreads threads) {
    buildInto(primBounds, nodes, scratch, true, threads);
}

}  // namespace penumbra::bvh
