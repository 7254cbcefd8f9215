// Scene traversal: the BVH (explicit stack, near child first) and brute force, which is the
// oracle for tests and shows what the BVH buys; the wide, stackless and per-object walks are in
// their own files, included below. Include after scene_bindings.glsl.
#ifndef PN_BVH_GLSL
#define PN_BVH_GLSL

#include "lib/intersect.glsl"
#include "shared/view_limits.h"
#include "lib/textures.glsl"
#include "lib/sprite.glsl"

// Traversal statistics hooks: empty, except in heatmap.comp and raybench_count.comp, which count with them.
#ifndef PN_COUNT_NODE
#define PN_COUNT_NODE()
#endif
#ifndef PN_COUNT_TRIANGLE
#define PN_COUNT_TRIANGLE()
#endif
// Called with each closest hit and each any-hit answer (trace kernels' frame statistics).
#ifndef PN_COUNT_CLOSEST
#define PN_COUNT_CLOSEST(hit)
#endif
#ifndef PN_COUNT_OCCLUDED
#define PN_COUNT_OCCLUDED(blocked)
#endif
// Called with the leaf node whose primitive became the closest hit so far (heatmap.comp's leaf views).
#ifndef PN_NOTE_LEAF_HIT
#define PN_NOTE_LEAF_HIT(leaf, primitives)
#endif
// A hit on primitive i: a sphere, a sprite's opaque part, or a triangle that an alpha-tested
// material does not punch out (and, culling back faces on a closest-hit walk, that faces the ray).
// The flag is the only branch spheres add to the hot loop.
bool hitPrimitive(uint i, vec3 o, vec3 d, float tMax, bool anyHit, out float t, out float u, out float v) {
    TriVerts tri = triVerts[i];
    // Before the flags' other uses: a culled triangle costs one cross and one dot product.
    if (PN_OPTION(PN_OPTION_CULL_BACKFACES) && !anyHit && (tri.flags & (PN_TRI_KEEP_BACK | PN_TRI_SPHERE | PN_TRI_SPRITE)) == 0u &&
        facesAway(tri, d)) {
        t = 0.0;
        u = 0.0;
        v = 0.0;
        return false;
    }
    if (PN_HAS(PN_FEATURE_SPHERES) && (tri.flags & PN_TRI_SPHERE) != 0u) {
        u = 0.0;
        v = 0.0;
        return intersectSphere(tri, o, d, tMax, t);
    }
    if (PN_HAS(PN_FEATURE_SPRITES) && (tri.flags & PN_TRI_SPRITE) != 0u) return hitSprite(i, tri, o, d, tMax, t, u, v);
    if (!intersectTriangle(tri, o, d, tMax, t, u, v)) return false;
    return !PN_HAS(PN_FEATURE_ALPHA_TEST) || (tri.flags & PN_TRI_ALPHA_TESTED) == 0u || !isAlphaHole(i, tri, u, v);
}

struct Hit {
    float t;        // along the world ray (instance rays keep its parameter: directions are not normalised)
    uint triangle;  // primitive slot (triangle or sphere); PN_NO_HIT on a miss
    float u;
    float v;
    uint instance;  // two-level scenes: the instance hit (index into instances[]); PN_NO_HIT otherwise
};

// A world point or direction in an instance's object space.
vec3 toInstancePoint(uint instance, vec3 p) {
    vec4 h = vec4(p, 1.0);
    return vec3(dot(instances[instance].worldToObject[0], h), dot(instances[instance].worldToObject[1], h),
                dot(instances[instance].worldToObject[2], h));
}
vec3 toInstanceVector(uint instance, vec3 v) {
    return vec3(dot(instances[instance].worldToObject[0].xyz, v), dot(instances[instance].worldToObject[1].xyz, v),
                dot(instances[instance].worldToObject[2].xyz, v));
}

// Two-level walks push a marker on entering an instance, so popping it means the bottom level is
// done. Node indices never reach these values (PN_INSTANCE_IDENTITY is their top bit).
#define PN_LEAVE_IDENTITY_INSTANCE 0xffffffffu  // nothing to restore: the walk kept the world ray
#define PN_LEAVE_MOVED_INSTANCE 0xfffffffeu     // the world ray is the six entries below it
// Two-level kernels need room for a top level's pending nodes, the world ray and a marker, then a
// bottom level's; flat ones keep the smaller stack (a specialisation constant picks).
#define PN_BVH_WALK_STACK_SIZE (PN_HAS(PN_FEATURE_INSTANCES) ? 2 * PN_BVH_STACK_SIZE : PN_BVH_STACK_SIZE)

// anyHit: stop at the first hit below tMax (shadow rays) instead of finding the closest.
// With instances (frame.instanceCount > 0) the walk starts in the top level; a top-level leaf is
// one instance, entered by moving the ray into its space and continuing at its bottom level's
// root on the same stack, above a marker; popping the marker ends the bottom level. The world ray
// is saved on the stack (bit for bit) under a moved instance's marker rather than kept in
// registers through the whole walk: the loop then carries one ray and the instance, the state a
// flat walk carries plus one register. Without instances, a flat walk from frame.topRoot: node 0 in
// flat scenes, the rest tree in a two-level scene at rest (render/rest_tree.h). Each step reads
// one record (BvhPair): a leaf's primitives, or both children's boxes, tested here, so the walk
// goes on into a child whose box it already knows it enters (the root's own box is never tested:
// its children's are).
Hit traverseBvh(vec3 worldO, vec3 worldD, float tMax, bool anyHit) {
    Hit hit = Hit(tMax, PN_NO_HIT, 0.0, 0.0, PN_NO_HIT);
    if (frame.nodeCount == 0u) return hit;
    bool twoLevel = PN_HAS(PN_FEATURE_INSTANCES) && frame.instanceCount != 0u;
    uint current = PN_HAS(PN_FEATURE_INSTANCES) ? frame.topRoot : 0u;
    vec3 o = worldO, d = worldD;
    vec3 invD = safeInverse(d);
    uint stack[PN_BVH_WALK_STACK_SIZE];
    uint depth = 0u;
    uint instance = PN_NO_HIT;  // the instance whose bottom level is being walked
    while (true) {
        BvhPair node = nodes[current];
        PN_COUNT_NODE();
        if (node.leafCount > 0u) {
            if (twoLevel && instance == PN_NO_HIT) {
                instance = node.left;
                uint root = instances[instance].rootNode;
                // An identity instance (the world's own geometry, a mesh left where it was
                // modelled) is walked with the world ray: no transform in, none back out.
                if ((root & PN_INSTANCE_IDENTITY) == 0u) {
                    stack[depth++] = floatBitsToUint(o.x);
                    stack[depth++] = floatBitsToUint(o.y);
                    stack[depth++] = floatBitsToUint(o.z);
                    stack[depth++] = floatBitsToUint(d.x);
                    stack[depth++] = floatBitsToUint(d.y);
                    stack[depth++] = floatBitsToUint(d.z);
                    stack[depth++] = PN_LEAVE_MOVED_INSTANCE;
                    o = toInstancePoint(instance, o);
                    d = toInstanceVector(instance, d);
                    invD = safeInverse(d);
                } else {
                    stack[depth++] = PN_LEAVE_IDENTITY_INSTANCE;
                }
                current = root & ~PN_INSTANCE_IDENTITY;
                continue;
            }
            for (uint i = node.left; i < node.left + node.leafCount; ++i) {
                PN_COUNT_TRIANGLE();
                float t, u, v;
                if (hitPrimitive(i, o, d, hit.t, anyHit, t, u, v)) {
                    hit = Hit(t, i, u, v, instance);
                    PN_NOTE_LEAF_HIT(current, node.leafCount);
                    if (anyHit) return hit;
                }
            }
        } else {
            uint near = node.left;
            uint far = node.right;
            float dNear = slabEntry(node.leftMin, node.leftMax, o, invD, hit.t);
            float dFar = slabEntry(node.rightMin, node.rightMax, o, invD, hit.t);
            if (dFar < dNear) {
                uint swapNode = near; near = far; far = swapNode;
                float swapDist = dNear; dNear = dFar; dFar = swapDist;
            }
            if (dNear != PN_INFINITY) {
                current = near;
                if (dFar != PN_INFINITY) stack[depth++] = far;
                continue;
            }
        }
        if (depth == 0u) break;
        current = stack[--depth];
        if (PN_HAS(PN_FEATURE_INSTANCES) && current >= PN_LEAVE_MOVED_INSTANCE) {
            // The bottom level is done: back to the top level, in world space.
            instance = PN_NO_HIT;
            if (current == PN_LEAVE_MOVED_INSTANCE) {
                depth -= 6u;
                o = uintBitsToFloat(uvec3(stack[depth], stack[depth + 1u], stack[depth + 2u]));
                d = uintBitsToFloat(uvec3(stack[depth + 3u], stack[depth + 4u], stack[depth + 5u]));
                invD = safeInverse(d);
            }
            if (depth == 0u) break;
            current = stack[--depth];
        }
    }
    return hit;
}

// Primitives [first, end) for the brute-force oracle, in the space the ray is given in.
void bruteRange(uint first, uint end, vec3 o, vec3 d, uint instance, bool anyHit, inout Hit hit) {
    for (uint i = first; i < end; ++i) {
        PN_COUNT_TRIANGLE();
        float t, u, v;
        if (hitPrimitive(i, o, d, hit.t, anyHit, t, u, v)) {
            hit = Hit(t, i, u, v, instance);
            if (anyHit) return;
        }
    }
}

Hit traverseBrute(vec3 o, vec3 d, float tMax, bool anyHit) {
    Hit hit = Hit(tMax, PN_NO_HIT, 0.0, 0.0, PN_NO_HIT);
    if (frame.instanceCount == 0u) {
        bruteRange(0u, frame.triCount, o, d, PN_NO_HIT, anyHit, hit);
        return hit;
    }
    for (uint k = 0u; k < frame.instanceCount; ++k) {
        uint first = instances[k].firstPrimitive;
        bruteRange(first, first + instances[k].primitiveCount, toInstancePoint(k, o), toInstanceVector(k, d), k, anyHit, hit);
        if (anyHit && hit.triangle != PN_NO_HIT) break;
    }
    return hit;
}

#include "lib/wide_bvh.glsl"
#include "lib/stackless_bvh.glsl"
#include "lib/object_boxes.glsl"

// One ray through the chosen acceleration structure; anyHit for shadow rays.
Hit traceRay(vec3 o, vec3 d, float tMax, bool anyHit) {
    // The render distance: nothing beyond it is hit (shared/view_limits.h).
    if (frame.renderDistance > 0.0)
        tMax = min(tMax, renderDistanceExit(o.x - frame.cameraPosition.x, o.z - frame.cameraPosition.z, d.x, d.z,
                                            frame.renderDistance));
    if (PN_WALK_IS(PN_ACCEL_WIDE)) return traverseWide(o, d, tMax, anyHit);
    if (PN_WALK_IS(PN_ACCEL_BRUTE)) return traverseBrute(o, d, tMax, anyHit);
    if (PN_WALK_IS(PN_ACCEL_STACKLESS)) return traverseStackless(o, d, tMax, anyHit);
    if (PN_WALK_IS(PN_ACCEL_OBJECTS)) return traverseObjects(o, d, tMax, anyHit);
    return traverseBvh(o, d, tMax, anyHit);
}

Hit traceClosest(vec3 o, vec3 d, float tMax) {
    Hit hit = traceRay(o, d, tMax, false);
    PN_COUNT_CLOSEST(hit);
    return hit;
}

bool traceOccluded(vec3 o, vec3 d, float tMax) {
    bool blocked = traceRay(o, d, tMax, true).triangle != PN_NO_HIT;
    PN_COUNT_OCCLUDED(blocked);
    return blocked;
}

#endif
