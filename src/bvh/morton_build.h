// A linear BVH (Karras 2012's idea, built top-down here): primitives sorted along a 30-bit Morton
// curve of their centres, each node split where the highest bit of the codes changes. O(n) after
// a radix sort, with no cost evaluation, so it builds several times faster than binned SAH, at a
// worse tree (a higher SAH cost). The top level of a two-level BVH over many instances uses it,
// where rebuilding every frame matters more than the last few percent of traversal.
#pragma once

#include <span>

#include "bvh/builder.h"
#include "core/aabb.h"

namespace penumbra::bvh {

// One primitive per leaf; the same layout and guarantees as build() (depth-first nodes, leaves'
// firstOrRight index primOrder, depth <= PN_BVH_MAX_DEPTH: equal codes split at the median).
Bvh buildMorton(std::span<const Aabb> primBounds);

}  // namespace penumbra::bvh
