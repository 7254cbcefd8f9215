// The scene's geometry as the walks read it: BVH nodes (binary, paired, 8-wide), instances and
// the triangle arrays (hot vertices, cold attributes, texture coordinates).
// Valid GLSL and C++ (see types.h); each struct's size and offsets are checked beside it.
#ifndef PENUMBRA_SHADER_GEOMETRY_H
#define PENUMBRA_SHADER_GEOMETRY_H

#include "shared/prelude.h"

#ifdef __cplusplus
namespace penumbra::shader {
#endif

#define PN_BVH_STACK_SIZE 64  // traversal stack entries; > PN_BVH_MAX_DEPTH, which the builder guarantees
#define PN_BVH_MAX_DEPTH 60

// ---- triangle flags (TriVerts.flags, read during traversal) ----
#define PN_TRI_ALPHA_TESTED 1u  // its material is alpha tested: check the texture before accepting a hit
// The slot holds an analytic sphere, not a triangle: v0 = centre, e1.x = radius (e2 unused).
// Spheres share the triangles' arrays so a leaf stays one contiguous primitive range.
#define PN_TRI_SPHERE 2u
// The slot holds a sprite (lib/sprite.glsl): an upright card through the vertical axis at v0 that
// turns to face each ray's origin. e1 = (left, right, bottom), e2.x = top: its extent around v0
// in metres (x along the card, to the viewer's right); e2.y = the direction the thing faces, in
// radians counter-clockwise (seen from above) from +x toward -z; e2.z = its views (1 or 8).
#define PN_TRI_SPRITE 4u
// Never culled by PN_OPTION_CULL_BACKFACES: its material transmits (a path inside glass must
// find the back faces to leave it).
#define PN_TRI_KEEP_BACK 8u

#define PN_NO_HIT 0xffffffffu

// BVH node, 32 bytes. Nodes are stored depth-first, so an interior node's left child is the node
// right after it.
//   triCount == 0 (interior): firstOrRight = index of the right child
//   triCount  > 0 (leaf):     firstOrRight = index of the first triangle (triangles are stored in
//                             leaf order, so a leaf's triangles are contiguous)
PN_STRUCT(BvhNode) {
    vec3 boundsMin;     // 12
    uint firstOrRight;  //  4
    vec3 boundsMax;     // 12
    uint triCount;      //  4
};
#ifdef __cplusplus
static_assert(sizeof(BvhNode) == 32 && offsetof(BvhNode, firstOrRight) == 12 &&
              offsetof(BvhNode, boundsMax) == 16 && offsetof(BvhNode, triCount) == 28);
#endif

// What the GPU walk reads for binary node i (bvh/child_pairs.h), 64 bytes, same indices as the
// BvhNode array: an interior node's two children, boxes and indices side by side, so each step of
// the walk is one load of 64 contiguous bytes (Aila & Laine 2009) where BvhNodes took the node and
// then its two children from two places. A leaf's record holds its primitives.
//   leafCount == 0 (interior): left = i + 1, right = BvhNode.firstOrRight; their boxes
//   leafCount  > 0 (leaf):     left = its first primitive (top level: its instance); boxes unused
PN_STRUCT(BvhPair) {
    vec3 leftMin;
    uint left;
    vec3 leftMax;
    uint leafCount;
    vec3 rightMin;
    uint right;
    vec3 rightMax;
    uint pad0;
};
#ifdef __cplusplus
static_assert(sizeof(BvhPair) == 64 && offsetof(BvhPair, left) == 12 && offsetof(BvhPair, leafCount) == 28 &&
              offsetof(BvhPair, rightMin) == 32 && offsetof(BvhPair, right) == 44 && offsetof(BvhPair, rightMax) == 48);
#endif

// Compressed 8-wide BVH node (the CWBVH layout of Ylitie, Karras and Laine 2017), 80 bytes.
// Wide nodes are uploaded after the binary walk's records (BvhPair) in the same buffer (GLSL
// reads them as five uvec4 from uvec4 frame.nodeCount * 4 on), root first. Child slot i (0-7) has
// a box quantized to 8 bits per plane: lo = origin + q * 2^e, with the three exponents stored as
// float exponent bits so the shader builds 2^e with one shift. Its meta byte says what the slot
// holds:
//   0                          empty
//   001 11sss (0x38 | slot)    an interior child: node childBase + (interior slots below it)
//   ccc ooooo                  a leaf: primitives primBase + o, o + 1, ... with ccc = 1, 3 or 7
//                              (one, two or three primitives, unary); o < 24
// The builder assigns slots so that slot i holds the child nearest to a ray whose direction has
// sign bits i (bit k set: negative along axis k), which the traversal turns into near-first order.
PN_STRUCT(WideNode) {
    vec3 origin;        // 12: the node box's lower corner
    uint exponentsMask; //  4: biased exponents x | y << 8 | z << 16, interior-slot mask << 24
    uint childBase;     //  4: first interior child in the wide node array (they are contiguous)
    uint primBase;      //  4: first primitive slot of the leaves (TriVerts index)
    uint meta[2];       //  8: slot i in byte i % 4 of meta[i / 4]
    uint loX[2];        //  8: quantized lower x plane of slot i, byte i % 4 of loX[i / 4]
    uint hiX[2];        //  8
    uint loY[2];        //  8
    uint hiY[2];        //  8
    uint loZ[2];        //  8
    uint hiZ[2];        //  8
};
#ifdef __cplusplus
static_assert(sizeof(WideNode) == 80 && offsetof(WideNode, exponentsMask) == 12 && offsetof(WideNode, childBase) == 16 &&
              offsetof(WideNode, primBase) == 20 && offsetof(WideNode, meta) == 24 && offsetof(WideNode, loX) == 32 &&
              offsetof(WideNode, hiX) == 40 && offsetof(WideNode, loY) == 48 && offsetof(WideNode, loZ) == 64 &&
              offsetof(WideNode, hiZ) == 72);
#endif

// One placement of a bottom-level BVH in a two-level scene, 112 bytes. Bottom levels live in the
// node and triangle arrays like the single-level BVH, with absolute indices (interior nodes name
// their right child in the node array, leaves their first slot in TriVerts), so a bottom level is
// walked exactly as the flat BVH is, only in the instance's space. The top level's nodes follow
// every bottom level's (root at FrameUniforms.topRoot); its leaves hold one instance each
// (firstOrRight = instance index, triCount = 1).
PN_STRUCT(Instance) {
    vec4 objectToWorld[3];  // 48: rows of the 3x4 affine transform (row i: xyz = linear part, w = translation)
    vec4 worldToObject[3];  // 48: its inverse; normals go to world space by its transpose
    uint rootNode;          //  4: root of the bottom level in the node array, | PN_INSTANCE_IDENTITY
    uint firstPrimitive;    //  4: the bottom level's slots are [firstPrimitive, firstPrimitive + primitiveCount)
    uint primitiveCount;    //  4: (what --accel brute loops over)
    uint id;                //  4: the scene's instance number (stable across top-level rebuilds)
};
#ifdef __cplusplus
static_assert(sizeof(Instance) == 112 && offsetof(Instance, worldToObject) == 48 && offsetof(Instance, rootNode) == 96 &&
              offsetof(Instance, firstPrimitive) == 100 && offsetof(Instance, primitiveCount) == 104 &&
              offsetof(Instance, id) == 108);
#endif
// Set in Instance.rootNode when the transform is exactly the identity (the world's own geometry,
// a mesh placed where it was modelled): the walk enters it keeping the world ray, no transform.
#define PN_INSTANCE_IDENTITY 0x80000000u

// Hot triangle data, read on every traversal step: 48 bytes. Edges are precomputed for
// Moller-Trumbore (e1 = v1 - v0, e2 = v2 - v0).
PN_STRUCT(TriVerts) {
    vec3 v0;
    uint flags;    // PN_TRI_*
    vec3 e1;
    uint uvIndex;  // the triangle's TriUvs entry (0: all zero, as for a mesh without UVs); fills
                   // padding that the 16-byte loads of the walk carry anyway
    vec3 e2;
    float pad2;
};
#ifdef __cplusplus
static_assert(sizeof(TriVerts) == 48 && offsetof(TriVerts, flags) == 12 && offsetof(TriVerts, e1) == 16 &&
              offsetof(TriVerts, uvIndex) == 28 && offsetof(TriVerts, e2) == 32);
#endif

// Cold triangle data, read once for the closest hit: 24 bytes (std430 packs these at 24; the
// texture coordinates live in TriUvs, so that meshes without them pay nothing). Shading normals
// are packed (shared/unit_vector.h: unpackUnitVector).
PN_STRUCT4(TriAttribs) {
    uint materialId;  //  4
    uint lightIndex;  //  4: LightRef of this emitter, or PN_NO_LIGHT
    float area;       //  4: world-space area, for converting light pdfs
    uint n0;          //  4: per-vertex shading normals, octahedral (packUnitVector)
    uint n1;          //  4
    uint n2;          //  4
};
#ifdef __cplusplus
static_assert(sizeof(TriAttribs) == 24 && offsetof(TriAttribs, lightIndex) == 4 && offsetof(TriAttribs, area) == 8 &&
              offsetof(TriAttribs, n0) == 12 && offsetof(TriAttribs, n2) == 20);
#endif

// A triangle's texture coordinates at its three vertices, 24 bytes, at TriVerts.uvIndex. They stay
// full floats, since tiled surfaces (a Doom wall) run to coordinates in the hundreds, where half
// floats would miss texels. Triangles whose coordinates are all zero share entry 0.
PN_STRUCT8(TriUvs) {
    vec2 uv0;  //  8
    vec2 uv1;  //  8
    vec2 uv2;  //  8
};
#ifdef __cplusplus
static_assert(sizeof(TriUvs) == 24 && offsetof(TriUvs, uv1) == 8 && offsetof(TriUvs, uv2) == 16);
#endif

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
