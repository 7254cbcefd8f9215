#version 460
// GPU BVH build, step 6: boxes, SAH costs and the collapse into leaves, bottom-up, one tree level
// per dispatch: an interior node finishes in the first pass after both its children did. (Karras
// 2012 climbs from every leaf with an atomic counter per node, the second child to arrive going
// on; on lavapipe the climbing lanes went astray, so the levels are passes here. A node is only
// read once its pass is over, so no atomics or memory model subtleties are needed; the root is
// done after as many passes as the tree is deep.) Costs are the SAH's times the node's area: a
// subtree becomes one leaf when it holds at most maxLeaf primitives and testing them all costs no
// more than its best split.
#extension GL_GOOGLE_include_directive : require

#include "lib/lbvh.glsl"

// Finished in an earlier pass (one finished in this pass has donePass = pass + 1).
bool finishedBefore(uint node) { return donePass[node] != 0u && donePass[node] <= push.pass; }

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i + 1u >= push.count || donePass[i] != 0u) return;
    uint l = nodes[i].left, r = nodes[i].right;
    if (!finishedBefore(l) || !finishedBefore(r)) return;
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
    donePass[i] = push.pass + 1u;
}
