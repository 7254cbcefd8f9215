// The CPU reference walk of the compressed wide BVH (bvh/wide.h), step for step what
// shaders/lib/wide_bvh.glsl does: node groups (a node's hit interior children as bits ordered
// near first for the ray's octant) on a stack, primitive groups tested as they come.
#pragma once

#include <span>

#include "bvh/traverse_cpu.h"
#include "shared/types.h"

namespace penumbra::bvh {

// Closest hit with t in (0, ray.tMax), as closestHit for the binary tree; `tris` in the order
// collapseToWide left. An empty node array never hits.
Hit closestHitWide(std::span<const shader::WideNode> nodes, std::span<const shader::TriVerts> tris,
                   const Ray& ray, TraversalCounts* counts = nullptr);
// True at the first hit with t in (0, ray.tMax).
bool anyHitWide(std::span<const shader::WideNode> nodes, std::span<const shader::TriVerts> tris,
                const Ray& ray, TraversalCounts* counts = nullptr);

}  // namespace penumbra::bvh
