// The compressed 8-wide BVH walk (--accel wide; shader WideNode, built by src/bvh/wide.cpp, and
// step for step the CPU reference in src/bvh/traverse_wide_cpu.cpp, except that child boxes are
// tested in the node's quantized frame here, which rounds differently). After Ylitie, Karras and
// Laine 2017: a node's eight quantized child boxes are tested together; the hit interior children
// become bits 24-31 of a node group, ordered so that the highest bit is the child nearest the
// ray's octant, and the hit leaves' primitives bits 0-23 of a primitive group. The stack holds
// node groups (childBase, remaining bits | the parent's interior mask), one per level at most.
// Flat scenes only: two-level scenes keep the binary walk. Included by bvh.glsl after Hit and
// hitPrimitive.
#ifndef PN_WIDE_BVH_GLSL
#define PN_WIDE_BVH_GLSL

// The wide nodes follow the binary ones (if uploaded) in the node buffer, five uvec4 each:
// (origin, exponentsMask) (childBase, primBase, meta[0], meta[1]) (loX, hiX) (loY, hiY) (loZ, hiZ).
layout(std430, set = 0, binding = PN_BINDING_NODES) readonly buffer WideNodeBuffer { uvec4 wideNodeWords[]; };

// Byte k (0-3) of a word: one slot's meta or quantized plane.
uint wideByte(uint word, uint k) { return bitfieldExtract(word, int(8u * k), 8); }

Hit traverseWide(vec3 o, vec3 d, float tMax, bool anyHit) {
    // Only reached with a wide tree of at least one node (frame.accel falls back to PN_ACCEL_BVH
    // without one); frame.nodeCount counts the binary nodes before it, 0 when they stay on the host.
    Hit hit = Hit(tMax, PN_NO_HIT, 0.0, 0.0, PN_NO_HIT);
    vec3 invD = safeInverse(d);
    // Slot s holds the child nearest to rays with sign bits s; XOR with the flipped octant puts
    // this ray's nearest child at the highest bit.
    uint octantFlip = 7u ^ ((d.x < 0.0 ? 1u : 0u) | (d.y < 0.0 ? 2u : 0u) | (d.z < 0.0 ? 4u : 0u));
    uint firstWord = frame.nodeCount * 4u;  // a binary walk's record (BvhPair) is four uvec4
    uvec2 stack[PN_BVH_STACK_SIZE];
    uint depth = 0u;
    uvec2 group = uvec2(0u, 0x80000000u);  // the root, as the only interior child of a node with mask 0
    while (true) {
        uvec2 prims;
        if (group.y > 0x00ffffffu) {
            uint bit = uint(findMSB(group.y));
            group.y &= ~(1u << bit);
            if (group.y > 0x00ffffffu) stack[depth++] = group;
            uint slot = (bit - 24u) ^ octantFlip;
            uint w = firstWord + 5u * (group.x + uint(bitCount(group.y & 0xffu & ((1u << slot) - 1u))));
            PN_COUNT_NODE();
            uvec4 n0 = wideNodeWords[w], n1 = wideNodeWords[w + 1u], n2 = wideNodeWords[w + 2u],
                  n3 = wideNodeWords[w + 3u], n4 = wideNodeWords[w + 4u];
            // The ray in the node's quantized frame, once per node (Ylitie et al. 2017, section 3.2):
            // plane q of axis k is at t = q * frameInvD[k] + frameT[k] (scale is a power of two, so
            // frameInvD is exact). Per axis, the ray's direction says which plane it enters through
            // (lo for a positive direction), so the words are picked once here, not per child.
            vec3 scale = uintBitsToFloat(uvec3(n0.w & 0xffu, (n0.w >> 8) & 0xffu, (n0.w >> 16) & 0xffu) << 23);
            vec3 frameInvD = scale * invD;
            vec3 frameT = (uintBitsToFloat(n0.xyz) - o) * invD;
            uvec4 planesX = d.x < 0.0 ? n2.zwxy : n2, planesY = d.y < 0.0 ? n3.zwxy : n3,
                  planesZ = d.z < 0.0 ? n4.zwxy : n4;  // (near lower slots, near upper, far lower, far upper)
            uint hits = 0u;
            for (uint s = 0u; s < 8u; ++s) {
                uint k = s & 3u;
                uint word = s >> 2;  // 0: slots 0-3 (in .x and .z), 1: slots 4-7 (.y and .w)
                uint meta = wideByte(n1[2u + word], k);
                if (meta == 0u) continue;
                vec3 tNear = vec3(wideByte(planesX[word], k), wideByte(planesY[word], k), wideByte(planesZ[word], k)) *
                                 frameInvD + frameT;
                vec3 tFar = vec3(wideByte(planesX[2u + word], k), wideByte(planesY[2u + word], k),
                                 wideByte(planesZ[2u + word], k)) * frameInvD + frameT;
                float enter = max(max(tNear.x, tNear.y), max(tNear.z, 0.0));
                float leave = min(min(tFar.x, tFar.y), min(tFar.z, hit.t));
                // Widened exits as in slabEntry. Unlike it, a plane's t here is rounded relative to
                // the node's corner, not to the plane: a box the ray only grazes within about 1e-7 of
                // the node's size can be culled (the paper's trade; the tests check hits against the
                // binary walk and brute force).
                if (enter > leave * PN_SLAB_EXIT_SCALE) continue;
                if ((meta & 0xf8u) == 0x38u)
                    hits |= 1u << (24u + (s ^ octantFlip));  // interior child
                else
                    hits |= (meta >> 5) << (meta & 31u);  // leaf: unary count at its offset
            }
            group = uvec2(n1.x, (hits & 0xff000000u) | (n0.w >> 24));
            prims = uvec2(n1.y, hits & 0x00ffffffu);
        } else {
            prims = group;
            group = uvec2(0u);
        }
        while (prims.y != 0u) {
            uint i = prims.x + uint(findLSB(prims.y));
            prims.y &= prims.y - 1u;
            PN_COUNT_TRIANGLE();
            float t, u, v;
            if (hitPrimitive(i, o, d, hit.t, anyHit, t, u, v)) {
                hit = Hit(t, i, u, v, PN_NO_HIT);
                if (anyHit) return hit;
            }
        }
        if (group.y <= 0x00ffffffu) {
            if (depth == 0u) break;
            group = stack[--depth];
        }
    }
    return hit;
}

#endif
