#include "render/bvh_build_compare.h"

#include <algorithm>
#include <vector>

#include "bvh/stats.h"
#include "render/gpu_bvh_build.h"

namespace penumbra {

BvhBuildComparison compareBvhBuilds(const gpu::Context& ctx, std::span<const Aabb> primBounds, int repeats) {
    BvhBuildComparison out;
    out.repeats = std::max(repeats, 1);
    const GpuBvhBuilder builder(ctx);
    std::vector<double> times;
    for (int r = 0; r < out.repeats; ++r) {
        GpuBvhBuild built = builder.build(primBounds);
        times.push_back(built.gpuMilliseconds);
        out.onGpu = built.onGpu;
        if (r == 0) out.gpuSahCost = bvh::computeStats(built.bvh, {}).sahCost;
    }
    std::nth_element(times.begin(), times.begin() + std::ptrdiff_t(times.size() / 2), times.end());
    out.gpuMilliseconds = times[times.size() / 2];
    out.cpuSahCost = bvh::computeStats(bvh::build(primBounds), {}).sahCost;
    return out;
}

}  // namespace penumbra
