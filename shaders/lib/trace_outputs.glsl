// Where the tracing kernels (trace.comp, wave_*.comp) put their results: the accumulation buffer
// (rgb = sum of radiance, a = sum of squared luminance, for variance estimates), the ray and
// invalid-sample counters, and the adaptive-sampling mask they obey. Include after
// shared/types.h and lib/scene_bindings.glsl.
#ifndef PN_TRACE_OUTPUTS_GLSL
#define PN_TRACE_OUTPUTS_GLSL

#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require

#include "shared/color.h"
#include "lib/pixel_estimate.glsl"

layout(std430, set = 0, binding = PN_BINDING_ACCUM) buffer AccumBuffer { vec4 accum[]; };
layout(std430, set = 0, binding = PN_BINDING_COUNTERS) buffer CounterBuffer { RayCounters counterLanes[PN_RAY_COUNTER_LANES]; };
layout(std430, set = 0, binding = PN_BINDING_ACTIVE_MASK) readonly buffer ActiveMask { uint activeMask[]; };
layout(std430, set = 0, binding = PN_BINDING_PIXEL_ESTIMATES) readonly buffer PixelEstimates { vec4 pixelEstimates[]; };

// Frame statistics (PN_OPTION_FRAME_STATS): this invocation's primitive tests, closest hits and
// blocked shadow rays, counted through lib/bvh.glsl's hooks (so this file comes before it) and
// added to the counters by countRays. Without the feature the hooks are empty branches the
// pipeline's specialisation removes.
uint pnPrimitivesTested = 0u;
uint pnClosestHits = 0u;
uint pnShadowBlocked = 0u;
#define PN_COUNT_TRIANGLE() if (PN_OPTION(PN_OPTION_FRAME_STATS)) ++pnPrimitivesTested
#define PN_COUNT_CLOSEST(hit) if (PN_OPTION(PN_OPTION_FRAME_STATS) && (hit).triangle != PN_NO_HIT) ++pnClosestHits
#define PN_COUNT_OCCLUDED(blocked) if (PN_OPTION(PN_OPTION_FRAME_STATS) && (blocked)) ++pnShadowBlocked

// The counter lane this workgroup adds to (see RayCounters).
uint counterLane() { return (gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x) % PN_RAY_COUNTER_LANES; }

// Adaptive sampling (render/adaptive.h): a pixel whose mask entry is 0 takes no samples in a
// masked pass (PN_TRACE_MASKED). Off-image pixels of a partial workgroup never do.
bool pixelSampled(uvec2 pixel) {
    if (pixel.x >= frame.width || pixel.y >= frame.height) return false;
    return (push.mode & PN_TRACE_MASKED) == 0u || activeMask[pixel.y * frame.width + pixel.x] != 0u;
}

// A pixel's sums for this pass into the accumulation buffer: added to what earlier passes left,
// or stored over it (PN_TRACE_REPLACE, which spares clearing the buffer before the pass).
void storePixelSums(uint index, vec4 sums) {
    if ((push.mode & PN_TRACE_REPLACE) != 0u)
        accum[index] = sums;
    else
        accum[index] += sums;
}

// What the pixel is worth per sample so far (lib/pixel_estimate.glsl), as earlier passes left it:
// the pixel estimates buffer where the caller keeps one (PN_TRACE_PIXEL_ESTIMATES: the viewer's
// history), else from the sums this pass adds to; none (0) in a pass that replaces the sums
// without estimates (they hold only the last pass's few samples).
vec3 pixelEstimate(uint pixelIndex) {
    if ((push.mode & PN_TRACE_PIXEL_ESTIMATES) != 0u) return pixelEstimates[pixelIndex].rgb;
    float samples = float(push.passIndex * frame.samplesPerPass);
    if ((push.mode & PN_TRACE_REPLACE) != 0u || samples == 0.0) return vec3(0.0);
    vec4 sums = accum[pixelIndex];
    return pixelEstimateFromMoments(sums.rgb / samples, sums.a / samples, samples);
}

// A finished sample into the pixel's sums. A NaN or inf sample would poison the pixel forever:
// it is dropped, and counted so that tests (and the render summary) see it.
void addSample(vec3 L, inout vec3 sum, inout float sumSquares) {
    if (any(isnan(L)) || any(isinf(L))) {
        L = vec3(0.0);
        atomicAdd(counterLanes[counterLane()].invalidSamples, 1u);
    }
    sum += L;
    float y = luminance(L);
    sumSquares += y * y;
}

// This invocation's traced rays into the counters (when the pass counts them), one atomic per
// subgroup, on its workgroup's lane. Every invocation of the subgroup must call it.
void countRays(uint closest, uint shadow) {
    if (push.countRays == 0u) return;
    uint closestSum = subgroupAdd(closest);
    uint shadowSum = subgroupAdd(shadow);
    if (subgroupElect()) {
        uint lane = counterLane();
        if (closestSum != 0u) atomicAdd(counterLanes[lane].closestRays, closestSum);
        if (shadowSum != 0u) atomicAdd(counterLanes[lane].shadowRays, shadowSum);
    }
    if (!PN_OPTION(PN_OPTION_FRAME_STATS)) return;
    uint tested = subgroupAdd(pnPrimitivesTested);
    uint hits = subgroupAdd(pnClosestHits);
    uint blocked = subgroupAdd(pnShadowBlocked);
    if (subgroupElect()) {
        uint lane = counterLane();
        if (tested != 0u) atomicAdd(counterLanes[lane].primitivesTested, tested);
        if (hits != 0u) atomicAdd(counterLanes[lane].closestHits, hits);
        if (blocked != 0u) atomicAdd(counterLanes[lane].shadowBlocked, blocked);
    }
}

#endif
