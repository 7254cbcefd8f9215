// The nodes of a flattened BVH that lie at one depth (the root is depth 0), for the viewer's box
// overlay: the boxes at depth d partition the primitives the way the builder split them d times.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "shared/types.h"

namespace penumbra::bvh {

// Nodes at exactly `depth` in depth-first order, at most maxCount of them (the first ones found).
std::vector<shader::BvhNode> nodesAtDepth(std::span<const shader::BvhNode> nodes, std::size_t depth,
                                          std::size_t maxCount);

// The tree's depth: 0 for a lone root leaf; 0 for an empty array too.
std::size_t treeDepth(std::span<const shader::BvhNode> nodes);

}  // namespace penumbra::bvh
