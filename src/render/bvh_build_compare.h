// The GPU's BVH build against the CPU's on the same primitives (bench and info --bvh-build gpu):
// the GPU's build time by its timestamps, and both trees' SAH costs (bvh/stats.h).
#pragma once

#include <span>

#include "core/aabb.h"
#include "gpu/context.h"

namespace penumbra {

struct BvhBuildComparison {
    double gpuMilliseconds = -1;  // median over the repeats (-1: the device has no timestamps)
    double gpuSahCost = 0, cpuSahCost = 0;
    bool onGpu = true;  // false: the GPU's tree was too deep and the CPU built it (a warning said so)
    int repeats = 0;
};

// Builds `repeats` times on the GPU (the first is timed too: no warm-up is left out) and once on
// the CPU (binned SAH, default options).
BvhBuildComparison compareBvhBuilds(const gpu::Context& ctx, std::span<const Aabb> primBounds, int repeats);

}  // namespace penumbra
