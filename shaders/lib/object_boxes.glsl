// --accel objects: one world-space box per object (shared/accel_layouts.h ObjectBox, built by
// src/render/object_boxes.cpp), every primitive of each box the ray enters tested by brute force,
// boxes in their stored order. The step before a BVH ("Casually Pathtracing with WebGPU"), kept as
// a comparison mode like brute force: `bench --accel objects` shows what the BVH gains over it.
// Included by bvh.glsl after Hit, hitPrimitive and bruteRange.
#ifndef PN_OBJECT_BOXES_GLSL
#define PN_OBJECT_BOXES_GLSL

Hit traverseObjects(vec3 o, vec3 d, float tMax, bool anyHit) {
    Hit hit = Hit(tMax, PN_NO_HIT, 0.0, 0.0, PN_NO_HIT);
    // Boxes exist only when built for this walk (render/object_boxes.h); an empty scene has none.
    uint boxCount = frame.triCount == 0u ? 0u : uint(objectBoxes.length());
    vec3 invD = safeInverse(d);
    for (uint k = 0u; k < boxCount; ++k) {
        ObjectBox box = objectBoxes[k];
        PN_COUNT_NODE();
        if (slabEntry(box.boundsMin, box.boundsMax, o, invD, hit.t) == PN_INFINITY) continue;
        if (box.listed != 0u) {
            for (uint e = box.first; e < box.first + box.count; ++e) {
                uint i = objectPrims[e];
                PN_COUNT_TRIANGLE();
                float t, u, v;
                if (hitPrimitive(i, o, d, hit.t, anyHit, t, u, v)) {
                    hit = Hit(t, i, u, v, box.instance);
                    if (anyHit) return hit;
                }
            }
        } else {
            uint n = box.instance;
            bruteRange(box.first, box.first + box.count, toInstancePoint(n, o), toInstanceVector(n, d), n, anyHit, hit);
            if (anyHit && hit.triangle != PN_NO_HIT) return hit;
        }
    }
    return hit;
}

#endif
