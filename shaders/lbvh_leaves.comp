#version 460
// GPU BVH build, step 5: the leaves' records, one per sorted primitive (stored after the n - 1
// interior nodes): its box, its SAH cost times its area, done before the first bounds pass.
#extension GL_GOOGLE_include_directive : require

#include "lib/lbvh.glsl"

void main() {
    uint j = gl_GlobalInvocationID.x, n = push.count;
    if (j >= n) return;
    uint leaf = n - 1u + j;
    BvhNode box = boxes[valuesA[j]];
    nodes[leaf].boundsMin = box.boundsMin;
    nodes[leaf].boundsMax = box.boundsMax;
    nodes[leaf].left = PN_LBVH_NONE;
    nodes[leaf].right = PN_LBVH_NONE;
    nodes[leaf].first = j;
    nodes[leaf].leaves = 1u;
    nodes[leaf].emitNodes = 1u;
    nodes[leaf].cost = pnHalfArea(box.boundsMin, box.boundsMax) * push.intersectCost;
    nodes[leaf].collapsed = 1u;
    donePass[leaf] = 1u;
}
