#version 460
// BVH heat map: BVH nodes visited and triangles tested by each pixel's primary ray, and the depth
// and primitive count of the leaf that holds its hit. The same traversal code as the path tracer,
// compiled here with counting hooks, so trace.comp pays nothing for it.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

uint heatNodes = 0u;
uint heatTriangles = 0u;
#define PN_COUNT_NODE() ++heatNodes
#define PN_COUNT_TRIANGLE() ++heatTriangles
uint hitLeaf = 0u;
uint hitLeafPrimitives = 0u;  // 0: no hit (or brute force, which has no leaves)
#define PN_NOTE_LEAF_HIT(leaf, primitives) \
    {                                       \
        hitLeaf = (leaf);                   \
        hitLeafPrimitives = (primitives);   \
    }

#include "lib/scene_bindings.glsl"
#define PN_HAVE_FRAME
#include "lib/viewer_common.glsl"
#include "lib/bvh.glsl"

layout(std430, set = 0, binding = PN_BINDING_FILTER_OUT) writeonly buffer HeatOut { vec4 heat[]; };
layout(std430, set = 0, binding = PN_BINDING_SCRATCH) buffer HeatMax { HeatCounters heatMax; };

// Depth of node `target` (root: 1, as bvh::treeDepth and `penumbra info` count it, so 0 stays
// "no hit"). Nodes are depth-first: an interior node's left subtree fills the indices from the
// next one up to its right child, so one comparison per level descends.
uint nodeDepth(uint target) {
    uint n = 0u, depth = 1u;
    while (n != target && depth <= uint(PN_BVH_STACK_SIZE)) {
        BvhPair node = nodes[n];
        if (node.leafCount > 0u) break;  // not reachable for a valid tree
        n = target < node.right ? node.left : node.right;
        ++depth;
    }
    return depth;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (!insideImage(p)) return;
    Hit hit = traceClosest(frame.cameraPosition, viewDirection(vec2(p) + 0.5), PN_INFINITY);
    uint leafPrimitives = hit.triangle == PN_NO_HIT ? 0u : hitLeafPrimitives;
    uint leafDepth = leafPrimitives == 0u ? 0u : nodeDepth(hitLeaf);
    heat[pixelIndex(p)] = vec4(float(heatNodes), float(heatTriangles), float(leafDepth), float(leafPrimitives));
    atomicMax(heatMax.maxNodes, heatNodes);
    atomicMax(heatMax.maxTris, heatTriangles);
    atomicMax(heatMax.maxLeafDepth, leafDepth);
    atomicMax(heatMax.maxLeafTris, leafPrimitives);
}
