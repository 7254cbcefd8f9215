// Quality figures of a built BVH, for tests, benchmarks and `penumbra info`.
#pragma once

#include <cstddef>

#include "bvh/builder.h"

namespace penumbra::bvh {

struct BvhStats {
    std::size_t nodes = 0, leaves = 0;
    std::size_t maxDepth = 0;  // bvh::treeDepth: levels, root alone = 1 (bvh/depth_boxes.h)
    std::size_t maxLeafSize = 0;
    // (sum over interior nodes area*Ct + sum over leaves area*count*Ci) / rootArea; 0 for an empty
    // tree or one whose root box has no area (a point or a segment), where the ratio is
    // meaningless.
    double sahCost = 0;
    double avgLeafSize = 0;
};

BvhStats computeStats(const Bvh& bvh, const BuildOptions& options);

}  // namespace penumbra::bvh
