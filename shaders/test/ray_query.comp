#version 460
// Test kernel: traces a batch of given rays with the real traversal code and reports, per ray,
// the closest hit and whether any-hit found an occluder below tMax.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_LINEAR_GROUP) in;

#include "lib/scene_bindings.glsl"
#include "lib/bvh.glsl"

layout(std430, set = 0, binding = PN_BINDING_SCRATCH) readonly buffer RayBuffer { RayDesc rays[]; };
// Two records per ray: [2i] the closest hit, [2i+1].triangle = 1 if occluded else 0.
layout(std430, set = 0, binding = PN_BINDING_SCRATCH2) writeonly buffer HitBuffer { HitRecord hits[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.itemCount) return;
    RayDesc r = rays[i];
    Hit h = traceClosest(r.origin, r.direction, r.tMax);
    hits[2 * i] = HitRecord(h.t, h.triangle, h.u, h.v);
    hits[2 * i + 1] = HitRecord(0.0, traceOccluded(r.origin, r.direction, r.tMax) ? 1u : 0u, 0.0, 0.0);
}
