// Measures ray throughput by kind (primary, shadow, diffuse bounce), each in its own timed
// dispatch, and the time of a whole path-traced frame.
#pragma once

#include <cstdint>
#include <span>

#include "render/renderer.h"

namespace penumbra {

// The walk's work per ray of one kind, counted by raybench_count.comp for the very rays timed.
struct TraversalWork {
    std::uint64_t rays = 0;
    double nodesPerRay = 0;       // binary walk: node pairs (both children's boxes); wide walk: 8-wide nodes
    double primitivesPerRay = 0;  // triangles, spheres and sprites tested
    // Node steps over the steps a warp's lanes wait through: each 32-lane warp (rows 0-3 and 4-7 of
    // an 8x8 group, as NVIDIA's warps are laid out) runs until its longest walk ends.
    double laneUse = 0;
};

// Work per ray from raybench_count.comp's words (PN_RAY_WORK_BITS layout; 0: no ray), one per
// pixel of a width x height image traced in PN_TRACE_GROUP_X x PN_TRACE_GROUP_Y groups.
TraversalWork traversalWork(std::span<const std::uint32_t> words, std::uint32_t width, std::uint32_t height);

struct RayBenchResult {
    std::uint64_t primaryRays = 0, shadowRays = 0, diffuseRays = 0;
    double primaryMs = 0, shadowMs = 0, diffuseMs = 0;  // medians over the repeats
    double frameMs = 0;                                 // median: 1 spp, settings' bounces, NEE
    std::uint64_t frameRays = 0;                        // closest + shadow rays in one frame
    // One more frame, untimed, with the kernels counting (Renderer::setFrameStatistics): what
    // the viewer's panel shows as frame statistics.
    struct FrameStatistics {
        std::uint64_t closestRays = 0, closestHits = 0, shadowRays = 0, shadowBlocked = 0, primitivesTested = 0;
    } frameStats;
    TraversalWork primaryWork, shadowWork, diffuseWork;
    int repeats = 0;
};

// `renderer` must have been made with the resolution and bounces to measure.
RayBenchResult runRayBench(const gpu::Context& ctx, Renderer& renderer, int repeats);

}  // namespace penumbra
