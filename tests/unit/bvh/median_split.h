// A deliberately naive builder (object median along the widest axis, no SAH) in the same node
// format: the baseline that the binned SAH must beat, and a second tree shape for traversal.
#pragma once

#include <span>

#include "bvh/builder.h"

namespace penumbra::bvh::test {

Bvh buildMedianSplit(std::span<const Aabb> primBounds, int maxLeafSize);

}  // namespace penumbra::bvh::test
