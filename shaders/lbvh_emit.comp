#version 460
// GPU BVH build, step 7: the depth-first BvhNode array the walks read (bvh/builder.h), every node
// at once. A node's place is known from its path: going to a left child adds 1 (the child follows
// its parent), to a right child 1 plus the nodes of its left sibling's subtree. Nodes inside a
// collapsed subtree are not written; a collapsed node is a leaf over its sorted range.
#extension GL_GOOGLE_include_directive : require

#include "lib/lbvh.glsl"

shared uint sDepth, sEmitted;

void main() {
    uint lid = gl_LocalInvocationID.x, k = gl_GlobalInvocationID.x;
    if (lid == 0u) {
        sDepth = 0u;
        sEmitted = 0u;
    }
    barrier();
    // An unfinished root: the tree is deeper than the bounds passes (and the walks) allow.
    if (k == 0u && donePass[0] == 0u) atomicMax(state.maxDepth, 0xffffu);
    if (push.count >= 2u && k < 2u * push.count - 1u && donePass[0] != 0u) {
        uint place = 0u, depth = 1u;
        bool hidden = false;
        for (uint c = k, p = nodes[k].parent; p != PN_LBVH_NONE; c = p, p = nodes[p].parent) {
            if (nodes[p].collapsed != 0u) {
                hidden = true;
                break;
            }
            uint left = nodes[p].left;
            place += c == left ? 1u : 1u + nodes[left].emitNodes;
            ++depth;
        }
        if (!hidden) {
            LbvhNode node = nodes[k];
            BvhNode out_;
            out_.boundsMin = node.boundsMin;
            out_.boundsMax = node.boundsMax;
            if (node.collapsed != 0u) {
                out_.firstOrRight = node.first;
                out_.triCount = node.leaves;
                atomicMax(sDepth, depth);
            } else {
                out_.firstOrRight = place + 1u + nodes[node.left].emitNodes;
                out_.triCount = 0u;
            }
            outNodes[place] = out_;
            atomicAdd(sEmitted, 1u);
        }
    }
    barrier();
    if (lid == 0u) {
        atomicMax(state.maxDepth, sDepth);
        atomicAdd(state.emitted, sEmitted);
    }
}
