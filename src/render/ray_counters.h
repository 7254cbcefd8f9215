// The trace kernels' ray and invalid-sample counters (shader::RayCounters): a host-visible buffer
// of PN_RAY_COUNTER_LANES lanes that the kernels add to, which the host sums and clears.
#pragma once

#include <cstdint>
#include <cstring>

#include "gpu/buffer.h"
#include "shared/types.h"

namespace penumbra {

struct RayCounts {
    std::uint64_t closestRays = 0, shadowRays = 0, invalidSamples = 0;
    // Counted only by kernels made with PN_OPTION_FRAME_STATS (zero otherwise).
    std::uint64_t primitivesTested = 0, closestHits = 0, shadowBlocked = 0;
};

inline constexpr VkDeviceSize kRayCounterBytes = sizeof(shader::RayCounters) * PN_RAY_COUNTER_LANES;

inline void clearRayCounters(gpu::Buffer& counters) { std::memset(counters.mapped(), 0, kRayCounterBytes); }

inline gpu::Buffer makeRayCounters(const gpu::Context& ctx) {
    gpu::Buffer counters(ctx, kRayCounterBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryKind::HostVisible);
    clearRayCounters(counters);
    return counters;
}

// What the kernels counted since the last clear (only after the work has finished).
inline RayCounts sumRayCounters(const gpu::Buffer& counters) {
    const auto* lanes = static_cast<const shader::RayCounters*>(counters.mapped());
    RayCounts sum;
    for (std::uint32_t i = 0; i < PN_RAY_COUNTER_LANES; ++i) {
        sum.closestRays += lanes[i].closestRays;
        sum.shadowRays += lanes[i].shadowRays;
        sum.invalidSamples += lanes[i].invalidSamples;
        sum.primitivesTested += lanes[i].primitivesTested;
        sum.closestHits += lanes[i].closestHits;
        sum.shadowBlocked += lanes[i].shadowBlocked;
    }
    return sum;
}

}  // namespace penumbra
