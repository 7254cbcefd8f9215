// A linear BVH (Karras 2012's idea, built top-down here): primitives sorted along a 30-bit Morton
// curve of their centres, each node split where the highest bit of the codes changes. O(n) after
// a radix sort, with no cost evaluation, so it builds several times faster than binned SAH, at a
// worse tree (a higher SAH cost). The top level of a two-level BVH over many instances uses it,
// where rebuilding every frame matters more than the last few percent of traversal.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bvh/builder.h"
#include "core/aabb.h"

namespace penumbra::bvh {

// From 2 * kMortonParallelGrain primitives on, a build runs on TBB's worker pool (boxes and keys
// in chunks of this size, the radix sort per chunk, subtrees at least this large side by side);
// the result is the one-thread build's to the bit (chunks never depend on the thread count).
// BuildThreads::One keeps it on the calling thread (tests compare the two).
inline constexpr std::size_t kMortonParallelGrain = 1024;
enum class BuildThreads { Pool, One };

// One primitive per leaf; the same layout and guarantees as build() (depth-first nodes, leaves'
// firstOrRight index primOrder, depth <= PN_BVH_MAX_DEPTH: equal codes split at the median).
Bvh buildMorton(std::span<const Aabb> primBounds, BuildThreads threads = BuildThreads::Pool);

// Buffers a Morton build needs besides its output, kept between builds (a per-frame top level):
// once they have grown to the primitive count, a build allocates nothing.
struct MortonScratch {
    std::vector<Aabb> boxes;                   // sanitizedBounds of the input, its order
    std::vector<std::uint64_t> keys, keysTmp;  // (code << 32) | primitive index
    std::vector<std::uint32_t> chunkStarts;    // the parallel radix sort's per-chunk digit slots
};

// The same tree appended to `nodes` (its root at the old nodes.size(), interior firstOrRight
// absolute indices into `nodes`), each leaf's firstOrRight the primitive's index in primBounds
// itself (no primOrder indirection): what a two-level top level stores.
void appendMorton(std::span<const Aabb> primBounds, std::vector<shader::BvhNode>& nodes, MortonScratch& scratch,
                  BuildThreads threads = BuildThreads::Pool);

}  // namespace penumbra::bvh
