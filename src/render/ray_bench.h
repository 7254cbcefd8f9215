// Measures ray throughput by kind (primary, shadow, diffuse bounce), each in its own timed
// dispatch, and the time of a whole path-traced frame.
#pragma once

#include "render/renderer.h"

namespace penumbra {

struct RayBenchResult {
    std::uint64_t primaryRays = 0, shadowRays = 0, diffuseRays = 0;
    double primaryMs = 0, shadowMs = 0, diffuseMs = 0;  // medians over the repeats
    double frameMs = 0;                                 // median: 1 spp, settings' bounces, NEE
    std::uint64_t frameRays = 0;                        // closest + shadow rays in one frame
    int repeats = 0;
};

// `renderer` must have been made with the resolution and bounces to measure.
RayBenchResult runRayBench(const gpu::Context& ctx, Renderer& renderer, int repeats);

}  // namespace penumbra
