#version 460
// GPU BVH build, step 5: boxes, SAH costs and the collapse into leaves, bottom-up (Karras 2012,
// section 4.3): each leaf's invocation climbs towards the root; at every interior node the first
// child to arrive stops and the second, which then knows both children are done, computes the
// node. Costs are the SAH's times the node's area: a subtree becomes one leaf when it holds at
// most maxLeaf primitives and testing them all costs no more than its best split.
#extension GL_GOOGLE_include_directive : require

#include "lib/lbvh.glsl"

void finishInterior(uint i) {
    uint l = nodes[i].left, r = nodes[i].right;
    vec3 lo = min(nodes[l].boundsMin, nodes[r].boundsMin), hi = max(nodes[l].boundsMax, nodes[r].boundsMax);
    float area = pnHalfArea(lo, hi);
    uint leaves = nodes[i].leaves;
    float leafCost = area * push.intersectCost * float(leaves);
    float splitCost = area * push.traversalCost + nodes[l].cost + nodes[r].cost;
    bool collapse = leaves <= push.maxLeaf && leafCost <= splitCost;
    nodes[i].boundsMin = lo;
    nodes[i].boundsMax = hi;
    nodes[i].cost = collapse ? leafCost : splitCost;
    nodes[i].emitNodes = collapse ? 1u : 1u + nodes[l].emitNodes + nodes[r].emitNodes;
    nodes[i].collapsed = collapse ? 1u : 0u;
}

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
    uint node = nodes[leaf].parent;
    while (node != PN_LBVH_NONE) {
        memoryBarrierBuffer();  // this child's writes before the arrival that publishes them
        if (atomicAdd(arrivals[node], 1u) == 0u) return;  // the sibling is not done: it will go on
        memoryBarrierBuffer();
        finishInterior(node);
        node = nodes[node].parent;
    }
}
