// The compressed 8-wide BVH walk (--accel wide; shader WideNode, built by src/bvh/wide.cpp, and
// step for step the CPU reference in src/bvh/traverse_wide_cpu.cpp). After Ylitie, Karras and
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
    uint firstWord = frame.nodeCount * 2u;  // a binary node is two uvec4
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
            vec3 origin = uintBitsToFloat(n0.xyz);
            vec3 scale = uintBitsToFloat(uvec3(n0.w & 0xffu, (n0.w >> 8) & 0xffu, (n0.w >> 16) & 0xffu) << 23);
            uint hits = 0u;
            for (uint s = 0u; s < 8u; ++s) {
                uint k = s & 3u;
                bool upper = s >= 4u;
                uint meta = wideByte(upper ? n1.w : n1.z, k);
                if (meta == 0u) continue;
                // origin + q * 2^e: the product is exact, so the box is the one the builder checked.
                vec3 lo = origin + vec3(wideByte(upper ? n2.y : n2.x, k), wideByte(upper ? n3.y : n3.x, k),
                                        wideByte(upper ? n4.y : n4.x, k)) * scale;
                vec3 hi = origin + vec3(wideByte(upper ? n2.w : n2.z, k), wideByte(upper ? n3.w : n3.z, k),
                                        wideByte(upper ? n4.w : n4.z, k)) * scale;
                if (slabEntry(lo, hi, o, invD, hit.t) == PN_INFINITY) continue;
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
            if (hitPrimitive(i, o, d, hit.t, t, u, v)) {
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
