#version 460
// GPU BVH build, radix sort step 2 of 3 per pass: the exclusive prefix sum of the digit counts,
// in place, by one group: each invocation sums a run of entries, the runs' sums are scanned in
// shared memory, then each run is written out from its start. 16 entries per block of 256 keys,
// so the 871k-triangle dragon scans 54k entries, 53 per invocation.
#extension GL_GOOGLE_include_directive : require

#include "shared/geometry.h"
#include "shared/lbvh.h"

layout(local_size_x = PN_LBVH_SCAN_GROUP) in;
layout(std430, set = 0, binding = PN_LBVH_BIND_COUNTS) buffer Counts { uint counts[]; };
layout(push_constant) uniform PushBlock { LbvhPush push; };

shared uint sSums[PN_LBVH_SCAN_GROUP];

void main() {
    uint lid = gl_LocalInvocationID.x;
    uint total = push.blockCount * uint(PN_LBVH_RADIX);
    uint run = (total + PN_LBVH_SCAN_GROUP - 1) / PN_LBVH_SCAN_GROUP;
    uint first = min(lid * run, total), last = min(first + run, total);
    uint sum = 0u;
    for (uint e = first; e < last; ++e) sum += counts[e];
    sSums[lid] = sum;
    barrier();
    // Hillis-Steele inclusive scan of the runs' sums.
    for (uint offset = 1u; offset < PN_LBVH_SCAN_GROUP; offset <<= 1) {
        uint add = lid >= offset ? sSums[lid - offset] : 0u;
        barrier();
        sSums[lid] += add;
        barrier();
    }
    uint running = sSums[lid] - sum;
    for (uint e = first; e < last; ++e) {
        uint c = counts[e];
        counts[e] = running;
        running += c;
    }
}
