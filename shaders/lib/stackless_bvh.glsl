// The stackless walk of the binary BVH (--accel stackless; shared/accel_layouts.h StacklessNode,
// threaded by src/bvh/stackless.cpp, step for step the CPU reference closestHitStackless there).
// Each node's box is tested when the walk reaches it: on a hit an interior node goes on to its
// left child (the next node), a leaf tests its primitives; on a miss, and after a leaf, the walk
// jumps to the node's escape index. No stack: children are taken left first whatever the ray's
// direction, which is what the walk gives up for it. Two-level scenes: a top-level leaf enters its
// instance's bottom level, remembering the leaf's escape and the world ray in two registers'
// worth of state; the bottom level's end (PN_STACKLESS_END) resumes the top level there.
// Included by bvh.glsl after Hit, hitPrimitive and toInstancePoint.
#ifndef PN_STACKLESS_BVH_GLSL
#define PN_STACKLESS_BVH_GLSL

Hit traverseStackless(vec3 worldO, vec3 worldD, float tMax, bool anyHit) {
    Hit hit = Hit(tMax, PN_NO_HIT, 0.0, 0.0, PN_NO_HIT);
    if (frame.nodeCount == 0u) return hit;
    bool twoLevel = PN_HAS(PN_FEATURE_INSTANCES) && frame.instanceCount != 0u;
    uint current = PN_HAS(PN_FEATURE_INSTANCES) ? frame.topRoot : 0u;  // flat: node 0 or the rest tree
    uint resume = PN_STACKLESS_END;  // the top level's next node once the instance is done
    uint instance = PN_NO_HIT;       // the instance whose bottom level is being walked
    vec3 o = worldO, d = worldD;
    vec3 invD = safeInverse(d);
    while (true) {
        if (current == PN_STACKLESS_END) {
            if (instance == PN_NO_HIT) break;
            // The bottom level is done: back to the top level, in world space.
            instance = PN_NO_HIT;
            o = worldO;
            d = worldD;
            invD = safeInverse(d);
            current = resume;
            continue;
        }
        StacklessNode node = stacklessNodes[current];
        PN_COUNT_NODE();
        if (slabEntry(node.boundsMin, node.boundsMax, o, invD, hit.t) == PN_INFINITY) {
            current = node.escape;
            continue;
        }
        if (node.leaf == 0u) {
            current += 1u;
            continue;
        }
        uint first = node.leaf >> PN_STACKLESS_COUNT_BITS;
        uint end = first + (node.leaf & PN_STACKLESS_COUNT_MASK);
        if (twoLevel && instance == PN_NO_HIT) {
            instance = first;
            resume = node.escape;
            uint root = instances[instance].rootNode;
            // An identity instance keeps the world ray, as in traverseBvh.
            if ((root & PN_INSTANCE_IDENTITY) == 0u) {
                o = toInstancePoint(instance, o);
                d = toInstanceVector(instance, d);
                invD = safeInverse(d);
            }
            current = root & ~PN_INSTANCE_IDENTITY;
            continue;
        }
        for (uint i = first; i < end; ++i) {
            PN_COUNT_TRIANGLE();
            float t, u, v;
            if (hitPrimitive(i, o, d, hit.t, anyHit, t, u, v)) {
                hit = Hit(t, i, u, v, instance);
                PN_NOTE_LEAF_HIT(current, end - first);
                if (anyHit) return hit;
            }
        }
        current = node.escape;
    }
    return hit;
}

#endif
