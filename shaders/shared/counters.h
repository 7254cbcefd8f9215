// Counters the trace pass writes (rays, invalid samples, frame statistics).
// Valid GLSL and C++ (see types.h); each struct's size and offsets are checked beside it.
#ifndef PENUMBRA_SHADER_COUNTERS_H
#define PENUMBRA_SHADER_COUNTERS_H

#include "shared/prelude.h"

#ifdef __cplusplus
namespace penumbra::shader {
#endif

// Counters written by the trace pass: rays only when PassPush.countRays is set. The buffer holds
// PN_RAY_COUNTER_LANES of them, 128 bytes apart; each workgroup adds to one lane, so that the
// atomics of a frame's hundred thousand subgroups do not all queue on one address (on an H200 one
// address cost Cornell's 1080p frame 0.15 ms). The host sums the lanes (render/ray_counters.h).
#define PN_RAY_COUNTER_LANES 64u
PN_STRUCT(RayCounters) {
    uint closestRays;
    uint shadowRays;
    uint invalidSamples;  // NaN or infinite path samples (always counted; dropped from the image)
    // PN_OPTION_FRAME_STATS only: primitives (triangles, spheres, sprites) tested by the walks,
    // closest-hit rays that hit something, shadow rays that found an occluder.
    uint primitivesTested;
    uint closestHits;
    uint shadowBlocked;
    uint pad[26];
};
#ifdef __cplusplus
static_assert(sizeof(RayCounters) == 128);
#endif

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
