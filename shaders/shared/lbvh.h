// The GPU BVH build's records (shaders/lbvh_*.comp, render/gpu_bvh_build.cpp): Morton codes, a
// radix sort, Karras 2012's hierarchy emitted in parallel, bounds bottom-up a level per pass, then the depth-first
// BvhNode array every walk reads. Valid GLSL and C++; sizes and offsets are checked beside each
// struct.
#ifndef PENUMBRA_SHADER_LBVH_H
#define PENUMBRA_SHADER_LBVH_H

#include "shared/prelude.h"

#ifdef __cplusplus
namespace penumbra::shader {
#endif

// ---- workgroup sizes and the sort's digits ----
#define PN_LBVH_GROUP 256        // threads per group of every build kernel
#define PN_LBVH_RADIX_BITS 4     // bits per sort pass: 16 digits, split in shared memory 1 bit at a time
#define PN_LBVH_RADIX (1 << PN_LBVH_RADIX_BITS)
#define PN_LBVH_RADIX_PASSES 8   // 32 bits of key (the codes use 30); even, so the keys end where they began
#define PN_LBVH_SCAN_GROUP 1024  // the one group that scans the digit counts
#define PN_LBVH_MAX_LEAF 4       // primitives a collapsed leaf may hold (bvh::BuildOptions' default)
// Bounds passes, one tree level each: a tree the walks may take (PN_BVH_MAX_DEPTH levels) has its
// root done by the last; a deeper one is left unfinished, which the emit pass reports.
#define PN_LBVH_BOUNDS_PASSES PN_BVH_MAX_DEPTH

// ---- binding indices (one descriptor set; each kernel declares the ones it uses) ----
#define PN_LBVH_BIND_BOXES 0     // BvhNode per primitive: its sanitized box (count unused), input order
#define PN_LBVH_BIND_STATE 1     // LbvhState
#define PN_LBVH_BIND_KEYS_A 2    // uint per primitive: Morton code (sorted in place through KEYS_B)
#define PN_LBVH_BIND_VALUES_A 3  // uint per primitive: its input index, carried with the key
#define PN_LBVH_BIND_KEYS_B 4
#define PN_LBVH_BIND_VALUES_B 5
#define PN_LBVH_BIND_COUNTS 6    // uint per (digit, block), digit-major: counts, then their exclusive sums
#define PN_LBVH_BIND_NODES 7     // LbvhNode per node: n - 1 interior (root 0), then n leaves
#define PN_LBVH_BIND_OUTPUT 8    // BvhNode per emitted node, depth-first (bvh/builder.h's layout)
// uint per node: the bounds pass that finished it plus 1 (leaves 1; 0: not yet). Apart from
// LbvhNode because every bounds pass reads it for every node: 4 bytes each, not a 64-byte record.
#define PN_LBVH_BIND_DONE 9

// One push constant block for every kernel; fields a kernel does not use are ignored.
PN_STRUCT(LbvhPush) {
    uint count;       // primitives (n)
    uint shift;       // the sort pass's lowest key bit
    uint blockCount;  // the sort's blocks of PN_LBVH_GROUP keys
    uint flip;        // 0: the pass reads A and writes B; 1: the reverse
    float traversalCost;  // Ct and Ci: the SAH weights the collapse compares (bvh::BuildOptions)
    float intersectCost;
    uint maxLeaf;     // at most PN_LBVH_MAX_LEAF
    uint pass;        // the bounds pass (1, 2, ...; lbvh_bounds.comp)
};
#ifdef __cplusplus
static_assert(sizeof(LbvhPush) == 32 && offsetof(LbvhPush, traversalCost) == 16 && offsetof(LbvhPush, maxLeaf) == 24);
#endif

// Build-wide values. The centres' bounds are floats mapped to uints whose order is theirs
// (pnOrderedFromFloat), so atomicMin/atomicMax can reduce them.
PN_STRUCT(LbvhState) {
    uint centreMin[3];
    uint maxDepth;    // levels of the emitted tree (root alone = 1), atomicMax over its leaves
    uint centreMax[3];
    uint emitted;     // nodes the emit pass wrote
};
#ifdef __cplusplus
static_assert(sizeof(LbvhState) == 32 && offsetof(LbvhState, maxDepth) == 12 && offsetof(LbvhState, emitted) == 28);
#endif

// A node of the Karras tree. Interior node i (0 <= i < n - 1) covers sorted primitives
// [first, first + leaves); its children are indices into the same array, a leaf j at n - 1 + j.
PN_STRUCT(LbvhNode) {
    vec3 boundsMin;   // 12: written bottom-up
    uint parent;      //  4: PN_LBVH_NONE for the root
    vec3 boundsMax;   // 12
    uint left;        //  4: interior only
    uint right;       //  4: interior only
    uint first;       //  4: the first sorted primitive below
    uint leaves;      //  4: sorted primitives below
    uint emitNodes;   //  4: nodes its subtree takes in the output (1 when collapsed into a leaf)
    float cost;       //  4: the subtree's SAH cost times its root area (the cheaper of leaf and split)
    uint collapsed;   //  4: 1 when the subtree becomes one leaf of `leaves` primitives
    uint pad0, pad1;  //  8
};
#ifdef __cplusplus
static_assert(sizeof(LbvhNode) == 64 && offsetof(LbvhNode, left) == 28 && offsetof(LbvhNode, cost) == 48 &&
              offsetof(LbvhNode, collapsed) == 52);
#endif

#define PN_LBVH_NONE 0xffffffffu

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif

#endif
