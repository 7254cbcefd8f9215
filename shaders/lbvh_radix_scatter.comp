#version 460
// GPU BVH build, radix sort step 3 of 3 per pass: each block sorts its keys by the pass's digit in
// shared memory, one bit at a time (a stable split per bit: Harris, Sengupta and Owens, GPU Gems
// 3 ch. 39), so a key's place among its block's keys of the same digit is its position minus the
// digit's first position; the scanned counts give the digit's first slot in the output for this
// block. Stable throughout, so equal Morton codes keep their input order, as std::stable_sort.
#extension GL_GOOGLE_include_directive : require

#include "lib/lbvh.glsl"

shared uint sKey[PN_LBVH_GROUP], sValue[PN_LBVH_GROUP], sScan[PN_LBVH_GROUP];
shared uint sDigitStart[PN_LBVH_RADIX];

uint digitOf(uint key) { return (key >> push.shift) & uint(PN_LBVH_RADIX - 1); }

// Inclusive Hillis-Steele scan of sScan.
void scanShared(uint lid) {
    for (uint offset = 1u; offset < PN_LBVH_GROUP; offset <<= 1) {
        uint add = lid >= offset ? sScan[lid - offset] : 0u;
        barrier();
        sScan[lid] += add;
        barrier();
    }
}

void main() {
    uint lid = gl_LocalInvocationID.x, i = gl_GlobalInvocationID.x;
    bool real = i < push.count;
    // Padding sorts last (all ones) and is never written out.
    uint key = real ? (push.flip == 0u ? keysA[i] : keysB[i]) : 0xffffffffu;
    uint value = real ? (push.flip == 0u ? valuesA[i] : valuesB[i]) : PN_LBVH_NONE;
    for (uint bit = 0u; bit < uint(PN_LBVH_RADIX_BITS); ++bit) {
        uint isSet = (digitOf(key) >> bit) & 1u;
        sScan[lid] = 1u - isSet;
        barrier();
        scanShared(lid);
        uint clearBefore = sScan[lid] - (1u - isSet);
        uint clearTotal = sScan[PN_LBVH_GROUP - 1];
        uint to = isSet == 0u ? clearBefore : clearTotal + (lid - clearBefore);
        sKey[to] = key;
        sValue[to] = value;
        barrier();
        key = sKey[lid];
        value = sValue[lid];
        barrier();
    }
    uint digit = digitOf(key);
    sScan[lid] = digit;
    barrier();
    if (lid == 0u || sScan[lid - 1u] != digit) sDigitStart[digit] = lid;
    barrier();
    if (value == PN_LBVH_NONE) return;
    uint to = counts[digit * push.blockCount + gl_WorkGroupID.x] + (lid - sDigitStart[digit]);
    if (push.flip == 0u) {
        keysB[to] = key;
        valuesB[to] = value;
    } else {
        keysA[to] = key;
        valuesA[to] = value;
    }
}
