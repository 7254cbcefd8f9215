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

// One primitive per leaf; the same layout and guarantees as build() (depth-first nodes, leaves'
// firstOrRight index primOrder, depth <= PN_BVH_MAX_DEPTH: equal codes split at the median).
Bvh buildMorton(std::span<const Aabb> primBounds);

// Buffers a Morton build needs besides its output, kept between builds (a per-frame top level):
// once they have grown to the primitive count, a build allocates nothing.
struct MortonScratch {
    std::vector<Aabb> boxes;                   // sanitizedBounds of the input, its order
    std::vector<std::uint64_t> keys, keysTmp;  // (code << 32) | primitive index
};

// The same tree appended to `nodes` (its root at the old nodes.size(), interior firstOrRight
// absolute indices into `nodes`), each leaf's firstOrRight the primitive's index in primBounds
// itself (no primOrder indirection): what a two-level top level stores.
void appendMorton(std::span<const Aabb> primBounds, std::vector<shader::BvhNode>& nodes, MortonScratch& scratch);

}  // namespace penumbra::bvh
