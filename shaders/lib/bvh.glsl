// Scene traversal: the BVH (explicit stack, near child first) and brute force, which is the
// oracle for tests and shows what the BVH buys. Include after scene_bindings.glsl.
#ifndef PN_BVH_GLSL
#define PN_BVH_GLSL

#include "lib/intersect.glsl"
#include "lib/textures.glsl"

// Traversal statistics hooks: empty, except in heatmap.comp, which counts with them.
#ifndef PN_COUNT_NODE
#define PN_COUNT_NODE()
#endif
#ifndef PN_COUNT_TRIANGLE
#define PN_COUNT_TRIANGLE()
#endif
// A hit on primitive i: a sphere, or a triangle that an alpha-tested material does not punch out.
// The flag is the only branch spheres add to the hot loop.
bool hitPrimitive(uint i, vec3 o, vec3 d, float tMax, out float t, out float u, out float v) {
    TriVerts tri = triVerts[i];
    if (PN_HAS(PN_FEATURE_SPHERES) && (tri.flags & PN_TRI_SPHERE) != 0u) {
        u = 0.0;
        v = 0.0;
        return intersectSphere(tri, o, d, tMax, t);
    }
    if (!intersectTriangle(tri, o, d, tMax, t, u, v)) return false;
    return !PN_HAS(PN_FEATURE_ALPHA_TEST) || (tri.flags & PN_TRI_ALPHA_TESTED) == 0u || !isAlphaHole(i, u, v);
}

struct Hit {
    float t;
    uint triangle;  // primitive slot (triangle or sphere); PN_NO_HIT on a miss
    float u;
    float v;
};

// Tests the primitives of one leaf, shortening hit.t; true when anyHit found one.
bool intersectLeaf(uint first, uint count, vec3 o, vec3 d, bool anyHit, inout Hit hit) {
    for (uint i = first; i < first + count; ++i) {
        PN_COUNT_TRIANGLE();
        float t, u, v;
        if (hitPrimitive(i, o, d, hit.t, t, u, v)) {
            hit = Hit(t, i, u, v);
            if (anyHit) return true;
        }
    }
    return false;
}

// Walks the node pairs (shared/types.h, BvhNodePair): one fetch gives both children's boxes; a
// leaf child is tested at once (its hits shorten the ray before the other child is entered), an
// interior one is visited nearest first, the farther pushed. anyHit: stop at the first hit below
// tMax (shadow rays) instead of finding the closest.
Hit traverseBvh(vec3 o, vec3 d, float tMax, bool anyHit) {
    Hit hit = Hit(tMax, PN_NO_HIT, 0.0, 0.0);
    if (frame.nodeCount == 0u) return hit;
    vec3 invD = safeInverse(d);
    uint stack[PN_BVH_STACK_SIZE];
    uint depth = 0u;
    uint current = 0u;
    while (true) {
        BvhNodePair node = nodes[current];
        PN_COUNT_NODE();
        float tLeft = slabEntry(node.leftMin, node.leftMax, o, invD, hit.t);
        float tRight = slabEntry(node.rightMin, node.rightMax, o, invD, hit.t);
        if (tLeft != PN_INFINITY && node.leftCount > 0u) {
            if (intersectLeaf(node.leftIndex, node.leftCount, o, d, anyHit, hit)) return hit;
            tLeft = PN_INFINITY;
        }
        if (tRight > hit.t) tRight = PN_INFINITY;  // the left leaf's hit came first
        if (tRight != PN_INFINITY && node.rightCount > 0u) {
            if (intersectLeaf(node.rightIndex, node.rightCount, o, d, anyHit, hit)) return hit;
            tRight = PN_INFINITY;
        }
        if (tLeft != PN_INFINITY && tRight != PN_INFINITY) {
            bool leftFirst = tLeft <= tRight;
            stack[depth++] = leftFirst ? node.rightIndex : node.leftIndex;
            current = leftFirst ? node.leftIndex : node.rightIndex;
        } else if (tLeft != PN_INFINITY) {
            current = node.leftIndex;
        } else if (tRight != PN_INFINITY) {
            current = node.rightIndex;
        } else {
            if (depth == 0u) break;
            current = stack[--depth];
        }
    }
    return hit;
}

Hit traverseBrute(vec3 o, vec3 d, float tMax, bool anyHit) {
    Hit hit = Hit(tMax, PN_NO_HIT, 0.0, 0.0);
    for (uint i = 0u; i < frame.triCount; ++i) {
        float t, u, v;
        if (hitPrimitive(i, o, d, hit.t, t, u, v)) {
            hit = Hit(t, i, u, v);
            if (anyHit) return hit;
        }
    }
    return hit;
}

Hit traceClosest(vec3 o, vec3 d, float tMax) {
    return PN_HAS(PN_FEATURE_BRUTE_FORCE) && frame.accel == PN_ACCEL_BRUTE ? traverseBrute(o, d, tMax, false)
                                                                           : traverseBvh(o, d, tMax, false);
}

bool traceOccluded(vec3 o, vec3 d, float tMax) {
    Hit h = PN_HAS(PN_FEATURE_BRUTE_FORCE) && frame.accel == PN_ACCEL_BRUTE ? traverseBrute(o, d, tMax, true)
                                                                            : traverseBvh(o, d, tMax, true);
    return h.triangle != PN_NO_HIT;
}

#endif
