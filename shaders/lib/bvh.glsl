// Scene traversal: the BVH (explicit stack, near child first) and brute force, which is the
// oracle for tests and shows what the BVH buys. Include after scene_bindings.glsl.
#ifndef PN_BVH_GLSL
#define PN_BVH_GLSL

#include "lib/intersect.glsl"
#include "lib/textures.glsl"
#include "lib/sprite.glsl"

// Traversal statistics hooks: empty, except in heatmap.comp, which counts with them.
#ifndef PN_COUNT_NODE
#define PN_COUNT_NODE()
#endif
#ifndef PN_COUNT_TRIANGLE
#define PN_COUNT_TRIANGLE()
#endif
// Called with the leaf node whose primitive became the closest hit so far (heatmap.comp's leaf views).
#ifndef PN_NOTE_LEAF_HIT
#define PN_NOTE_LEAF_HIT(leaf, primitives)
#endif
// A hit on primitive i: a sphere, a sprite's opaque part, or a triangle that an alpha-tested
// material does not punch out.
// The flag is the only branch spheres add to the hot loop.
bool hitPrimitive(uint i, vec3 o, vec3 d, float tMax, out float t, out float u, out float v) {
    TriVerts tri = triVerts[i];
    if (PN_HAS(PN_FEATURE_SPHERES) && (tri.flags & PN_TRI_SPHERE) != 0u) {
        u = 0.0;
        v = 0.0;
        return intersectSphere(tri, o, d, tMax, t);
    }
    if (PN_HAS(PN_FEATURE_SPRITES) && (tri.flags & PN_TRI_SPRITE) != 0u) return hitSprite(i, tri, o, d, tMax, t, u, v);
    if (!intersectTriangle(tri, o, d, tMax, t, u, v)) return false;
    return !PN_HAS(PN_FEATURE_ALPHA_TEST) || (tri.flags & PN_TRI_ALPHA_TESTED) == 0u || !isAlphaHole(i, u, v);
}

struct Hit {
    float t;
    uint triangle;  // primitive slot (triangle or sphere); PN_NO_HIT on a miss
    float u;
    float v;
};

// anyHit: stop at the first hit below tMax (shadow rays) instead of finding the closest.
Hit traverseBvh(vec3 o, vec3 d, float tMax, bool anyHit) {
    Hit hit = Hit(tMax, PN_NO_HIT, 0.0, 0.0);
    if (frame.nodeCount == 0u) return hit;
    vec3 invD = safeInverse(d);
    if (slabEntry(nodes[0].boundsMin, nodes[0].boundsMax, o, invD, tMax) == PN_INFINITY) return hit;

    uint stack[PN_BVH_STACK_SIZE];
    uint depth = 0u;
    uint current = 0u;
    while (true) {
        BvhNode node = nodes[current];
        PN_COUNT_NODE();
        if (node.triCount > 0u) {
            for (uint i = node.firstOrRight; i < node.firstOrRight + node.triCount; ++i) {
                PN_COUNT_TRIANGLE();
                float t, u, v;
                if (hitPrimitive(i, o, d, hit.t, t, u, v)) {
                    hit = Hit(t, i, u, v);
                    PN_NOTE_LEAF_HIT(current, node.triCount);
                    if (anyHit) return hit;
                }
            }
            if (depth == 0u) break;
            current = stack[--depth];
            continue;
        }
        uint near = current + 1u;
        uint far = node.firstOrRight;
        float dNear = slabEntry(nodes[near].boundsMin, nodes[near].boundsMax, o, invD, hit.t);
        float dFar = slabEntry(nodes[far].boundsMin, nodes[far].boundsMax, o, invD, hit.t);
        if (dFar < dNear) {
            uint swapNode = near; near = far; far = swapNode;
            float swapDist = dNear; dNear = dFar; dFar = swapDist;
        }
        if (dNear == PN_INFINITY) {
            if (depth == 0u) break;
            current = stack[--depth];
        } else {
            current = near;
            if (dFar != PN_INFINITY) stack[depth++] = far;
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

// One ray through the chosen acceleration structure; anyHit for shadow rays.
Hit traceRay(vec3 o, vec3 d, float tMax, bool anyHit) {
    return PN_HAS(PN_FEATURE_BRUTE_FORCE) && frame.accel == PN_ACCEL_BRUTE ? traverseBrute(o, d, tMax, anyHit)
                                                                           : traverseBvh(o, d, tMax, anyHit);
}

Hit traceClosest(vec3 o, vec3 d, float tMax) { return traceRay(o, d, tMax, false); }

bool traceOccluded(vec3 o, vec3 d, float tMax) { return traceRay(o, d, tMax, true).triangle != PN_NO_HIT; }

#endif
