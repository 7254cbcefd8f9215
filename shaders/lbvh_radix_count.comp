#version 460
// GPU BVH build, radix sort step 1 of 3 per pass: how many keys of each block have each digit.
// Stored digit-major (counts[digit * blockCount + block]) so that one exclusive scan over the
// array gives every (digit, block) its first output slot, blocks of a digit in block order: the
// order that keeps the sort stable.
#extension GL_GOOGLE_include_directive : require

#include "lib/lbvh.glsl"

shared uint sHistogram[PN_LBVH_RADIX];

void main() {
    uint lid = gl_LocalInvocationID.x, i = gl_GlobalInvocationID.x;
    if (lid < PN_LBVH_RADIX) sHistogram[lid] = 0u;
    barrier();
    if (i < push.count) {
        uint key = push.flip == 0u ? keysA[i] : keysB[i];
        atomicAdd(sHistogram[(key >> push.shift) & uint(PN_LBVH_RADIX - 1)], 1u);
    }
    barrier();
    if (lid < PN_LBVH_RADIX) counts[lid * push.blockCount + gl_WorkGroupID.x] = sHistogram[lid];
}
