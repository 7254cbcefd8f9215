#version 460
// GPU BVH build, step 2: each primitive's Morton code (shared/morton.h, the CPU Morton build's
// formula) and its index, the key and value the radix sort orders.
#extension GL_GOOGLE_include_directive : require

#include "lib/lbvh.glsl"
#include "shared/morton.h"

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    vec3 lo = vec3(pnFloatFromOrdered(state.centreMin[0]), pnFloatFromOrdered(state.centreMin[1]),
                   pnFloatFromOrdered(state.centreMin[2]));
    vec3 hi = vec3(pnFloatFromOrdered(state.centreMax[0]), pnFloatFromOrdered(state.centreMax[1]),
                   pnFloatFromOrdered(state.centreMax[2]));
    vec3 extent = hi - lo;
    float size = max(extent.x, max(extent.y, extent.z));
    float scale = size > 0.0 ? float(PN_MORTON_CELLS) / size : 0.0;
    vec3 c = (boxes[i].boundsMin + boxes[i].boundsMax) * 0.5;
    keysA[i] = pnMortonCode(c - lo, scale);
    valuesA[i] = i;
}
