// The GPU's form of the binary BVH: each interior node as one BvhNodePair holding both
// children's bounds (shared/types.h), so traversal makes one fetch per step instead of three.
#pragma once

#include <span>
#include <vector>

#include "shared/types.h"

namespace penumbra::bvh {

// nodes: a depth-first binary BVH (Bvh::nodes). Empty in, empty out. A tree that is one leaf
// becomes one pair whose two children are that leaf.
std::vector<shader::BvhNodePair> toNodePairs(std::span<const shader::BvhNode> nodes);

}  // namespace penumbra::bvh
