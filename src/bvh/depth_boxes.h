// Depth in a flattened BVH, the one convention every part of Penumbra uses: the root lies at
// depth 1, so a tree's depth is its number of levels (a lone root leaf: 1; no nodes: 0), the way
// PN_BVH_MAX_DEPTH, the builder, bvh::validate and the wide tree count it. `penumbra info`
// (BvhStats::maxDepth) and the viewer (its box overlay's depth slider) both report treeDepth.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "shared/types.h"

namespace penumbra::bvh {

// Nodes at exactly `depth` (root: 1) in depth-first order, at most maxCount of them (the first
// ones found): for the viewer's box overlay, the boxes at depth d partition the primitives the
// way the builder split them d - 1 times. Depth 0 and depths past the tree's hold no nodes.
std::vector<shader::BvhNode> nodesAtDepth(std::span<const shader::BvhNode> nodes, std::size_t depth,
                                          std::size_t maxCount);

// The depth of the deepest node (root: 1), so the tree's number of levels; 0 for no nodes.
std::size_t treeDepth(std::span<const shader::BvhNode> nodes);

}  // namespace penumbra::bvh
