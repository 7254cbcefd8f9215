// Structural checks of a BVH: cheap enough for tests and debug tools, too slow for every build.
#pragma once

#include <span>

#include "bvh/builder.h"
#include "core/aabb.h"

namespace penumbra::bvh {

// Throws Error naming the first broken rule: node indices in range and depth-first, every
// primitive in exactly one leaf, children inside their parent's box, primitive boxes (after
// sanitizedBounds) inside their leaf's box, depth <= PN_BVH_MAX_DEPTH.
void validate(const Bvh& bvh, std::span<const Aabb> primBounds);

}  // namespace penumbra::bvh
