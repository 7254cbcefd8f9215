#version 460
// GPU BVH build, step 1: the bounds of the primitives' centres, which the Morton codes quantise.
// Each group reduces its share in shared memory first, so the global atomics are one per group.
#extension GL_GOOGLE_include_directive : require

#include "lib/lbvh.glsl"

shared uint sLo[3], sHi[3];

void main() {
    uint lid = gl_LocalInvocationID.x, i = gl_GlobalInvocationID.x;
    if (lid < 3) {
        sLo[lid] = 0xffffffffu;
        sHi[lid] = 0u;
    }
    barrier();
    if (i < push.count) {
        vec3 c = (boxes[i].boundsMin + boxes[i].boundsMax) * 0.5;
        for (int a = 0; a < 3; ++a) {
            atomicMin(sLo[a], pnOrderedFromFloat(c[a]));
            atomicMax(sHi[a], pnOrderedFromFloat(c[a]));
        }
    }
    barrier();
    if (lid < 3) {
        atomicMin(state.centreMin[lid], sLo[lid]);
        atomicMax(state.centreMax[lid], sHi[lid]);
    }
}
