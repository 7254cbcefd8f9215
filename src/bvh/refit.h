// Refitting: after a mesh deforms (its vertices move, its triangles stay the same), the boxes of
// its BVH are recomputed bottom-up and the tree's shape is kept. Far cheaper than a rebuild; the
// tree may then be slower to traverse than a fresh one, but it gives exactly the same hits.
#pragma once

#include <cstdint>
#include <span>

#include "core/aabb.h"
#include "shared/types.h"

namespace penumbra::bvh {

// Recomputes the bounds of nodes [first, first + count), a depth-first tree (a bottom level with
// absolute indices, or a whole BVH with first = 0). primBounds holds the new box of every slot
// the leaves name, from slotBase on (slot s: primBounds[s - slotBase]; for triangles
// sanitizedBounds(bounds(tri)), as the builder uses). Children follow their parent in the array,
// so one backward pass sees every child before its parent.
void refit(std::span<shader::BvhNode> nodes, std::uint32_t first, std::uint32_t count,
           std::span<const Aabb> primBounds, std::uint32_t slotBase = 0);

}  // namespace penumbra::bvh
