// Escape indices for the stackless walk (--accel stackless): the binary nodes, threaded so that a
// walk needs no stack (shared/accel_layouts.h StacklessNode; the shader is
// shaders/lib/stackless_bvh.glsl), and the CPU reference of that walk for flat trees.
#pragma once

#include <span>
#include <vector>

#include "bvh/traverse_cpu.h"
#include "shared/types.h"
#include "shared/accel_layouts.h"

namespace penumbra::bvh {

// The threaded form of `nodes` (depth first, left child next, as the builder lays them out), same
// indices. `roots` are the trees in the array (a flat BVH: {0}; two levels: every bottom level's
// root and the top level's); each root's escape is PN_STACKLESS_END, and every node below a root
// gets the next node in depth-first order outside its subtree. Throws Error for a leaf of more
// than PN_STACKLESS_COUNT_MASK primitives or a first primitive that does not fit beside its count.
std::vector<shader::StacklessNode> threadNodes(std::span<const shader::BvhNode> nodes,
                                               std::span<const std::uint32_t> roots);

// The tree at `root` threaded again into `out` (threadNodes' result for the same array, same
// indices), its other trees left as they are: a top level rebuilt in place when instances move.
void threadTree(std::span<const shader::BvhNode> nodes, std::uint32_t root, std::span<shader::StacklessNode> out);

// The stackless walk over a flat tree (root 0), as the shader takes it: each box tested on
// arrival, left child first. closestHit's answers (the same t; ties may pick another primitive).
Hit closestHitStackless(std::span<const shader::StacklessNode> nodes, std::span<const shader::TriVerts> tris,
                        const Ray& ray, TraversalCounts* counts = nullptr);
bool anyHitStackless(std::span<const shader::StacklessNode> nodes, std::span<const shader::TriVerts> tris,
                     const Ray& ray);

}  // namespace penumbra::bvh
