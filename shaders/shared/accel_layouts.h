// The walks' own records beyond the binary BVH (shared/types.h BvhPair) and the wide one: the
// stackless walk's threaded nodes and the per-object boxes of `--accel objects`, with the
// walk numbers they are chosen by. Valid GLSL and C++; include after shared/types.h (it uses its
// prelude: PN_STRUCT, vec3, uint).
#ifndef PENUMBRA_SHADER_ACCEL_LAYOUTS_H
#define PENUMBRA_SHADER_ACCEL_LAYOUTS_H

#ifdef __cplusplus
namespace penumbra::shader {
#endif

// ---- walks: FrameUniforms.accel and the tracing kernels' specialization constant 1 (pnWalk,
// lib/scene_bindings.glsl) name a walk by these numbers. The first three are in shared/types.h
// (PN_ACCEL_BVH 0, PN_ACCEL_BRUTE 1, PN_ACCEL_WIDE 2); render/walks.h names each for the host. ----
#define PN_ACCEL_OBJECTS 3u    // one box per object, brute force inside each box the ray enters
#define PN_ACCEL_STACKLESS 4u  // the binary BVH walked through escape indices (StacklessNode)
// pnWalk's default: the kernel carries every walk and reads FrameUniforms.accel each ray (test
// kernels, the heat map, arrays not built by buildSceneArrays).
#define PN_WALK_ANY 0xffffffffu

// ---- their bindings in the scene descriptor set (after shared/types.h's last, 38) ----
#define PN_BINDING_STACKLESS_NODES 39  // StacklessNode per binary node (--accel stackless; else one dummy)
#define PN_BINDING_OBJECT_BOXES 40     // ObjectBox per object (--accel objects; else one dummy)
#define PN_BINDING_OBJECT_PRIMS 41     // uint per entry: primitive slots of the flat scenes' objects

// A binary BVH node threaded for a walk without a stack (Smits 1998, "Efficiency issues for ray
// tracing"; the LiU path tracer's escape indices), 32 bytes, same index as the BvhNode. Nodes are
// depth first, so the successor on a hit of an interior node is the next node; on a miss, and
// after a leaf, the walk goes to `escape`: the next node in depth-first order that is not below
// this one (the right sibling of the nearest ancestor that is a left child), or PN_STACKLESS_END.
//   leaf == 0: interior
//   leaf  > 0: primitives [leaf >> PN_STACKLESS_COUNT_BITS, + (leaf & PN_STACKLESS_COUNT_MASK));
//              a top-level leaf: that instance, count 1
#define PN_STACKLESS_END 0xffffffffu
#define PN_STACKLESS_COUNT_BITS 5u
#define PN_STACKLESS_COUNT_MASK 31u  // leaves of up to 31 primitives (the builder's default is 4)
PN_STRUCT(StacklessNode) {
    vec3 boundsMin;  // 12
    uint escape;     //  4: where to go on a miss or after a leaf
    vec3 boundsMax;  // 12
    uint leaf;       //  4: 0, or first << 5 | count
};

// One object's box for --accel objects (the step before a BVH in "Casually Pathtracing with
// WebGPU"), 48 bytes, world space.
//   listed != 0: a scene object (a mesh, a sphere) of a flat scene or of an identity instance;
//                its primitive slots are objectPrims[first, first + count), tested with the world ray
//   listed == 0: a moved instance of a two-level scene; slots [first, first + count) tested in its space
// instance: what a hit reports as Hit.instance (PN_NO_HIT in flat scenes).
PN_STRUCT(ObjectBox) {
    vec3 boundsMin;  // 12
    uint first;      //  4
    vec3 boundsMax;  // 12
    uint count;      //  4
    uint instance;   //  4
    uint listed;     //  4
    uint pad0;       //  8: padding to 16-byte alignment
    uint pad1;
};

#ifdef __cplusplus
static_assert(sizeof(StacklessNode) == 32 && offsetof(StacklessNode, escape) == 12 &&
              offsetof(StacklessNode, boundsMax) == 16 && offsetof(StacklessNode, leaf) == 28);
static_assert(sizeof(ObjectBox) == 48 && offsetof(ObjectBox, first) == 12 && offsetof(ObjectBox, boundsMax) == 16 &&
              offsetof(ObjectBox, count) == 28 && offsetof(ObjectBox, instance) == 32 &&
              offsetof(ObjectBox, listed) == 36);
static_assert(PN_STACKLESS_COUNT_MASK == (1u << PN_STACKLESS_COUNT_BITS) - 1u);
static_assert(PN_ACCEL_OBJECTS != PN_ACCEL_BVH && PN_ACCEL_OBJECTS != PN_ACCEL_BRUTE && PN_ACCEL_OBJECTS != PN_ACCEL_WIDE &&
              PN_ACCEL_STACKLESS > PN_ACCEL_OBJECTS);
static_assert(PN_BINDING_STACKLESS_NODES > PN_BINDING_PIXEL_ESTIMATES, "after shared/types.h's bindings");
}  // namespace penumbra::shader
#endif
#endif
