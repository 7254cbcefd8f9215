// The GPU walk's form of a binary BVH (shader::BvhPair, shaders/shared/types.h): for every node,
// its two children's boxes and indices in one 64-byte record, so a step of the walk is one load.
// Same indices as the BvhNode array it is made from, so roots, instances and node numbers carry
// over unchanged; the BvhNode array stays the host's (picking, overlays, refits, the wide BVH).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "shared/types.h"

namespace penumbra::bvh {

// Records [first, first + out.size()) of `nodes`: every child an interior node names must lie in
// `nodes` (a whole tree, or a top level after its bottom levels with absolute indices).
void writeChildPairs(std::span<const shader::BvhNode> nodes, std::size_t first, std::span<shader::BvhPair> out);

std::vector<shader::BvhPair> childPairs(std::span<const shader::BvhNode> nodes);

}  // namespace penumbra::bvh
