#version 460
// Test kernel: the unified light sampler's choices (lib/light_sampler.glsl) at given shading
// points (RayDesc: origin = point, direction = shading normal), for chi-square tests.
//   mode 0: PassPush.passIndex picks from each point; out[i] = (ref, pick pmf, lightPickPmf(ref), 0)
//   mode 1: out[i] = lightPickPmf(ref, point) for ref = i % lightRefCount, point = i / lightRefCount
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_LINEAR_GROUP) in;

#include "lib/scene_bindings.glsl"
#include "lib/rng.glsl"
#include "lib/bvh.glsl"
#include "lib/surface.glsl"
#include "lib/light_sampler.glsl"

layout(std430, set = 0, binding = PN_BINDING_SCRATCH) readonly buffer PointBuffer { RayDesc points[]; };
layout(std430, set = 0, binding = PN_BINDING_SCRATCH2) writeonly buffer OutBuffer { vec4 results[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.itemCount) return;
    if (push.mode == 0u) {
        RayDesc q = points[i / push.passIndex];
        uint rng = rngSeed(i, 0u, frame.seed);
        LightPick pick = pickLight(q.origin, q.direction, rngNext(rng), rng);
        float again = pick.ref == PN_NO_LIGHT ? 0.0 : lightPickPmf(pick.ref, q.origin, q.direction);
        results[i] = vec4(uintBitsToFloat(pick.ref), pick.pmf, again, 0.0);
    } else {
        RayDesc q = points[i / frame.lightRefCount];
        results[i] = vec4(lightPickPmf(i % frame.lightRefCount, q.origin, q.direction), 0.0, 0.0, 0.0);
    }
}
