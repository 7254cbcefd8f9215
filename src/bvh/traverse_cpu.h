// The CPU reference traversal over exactly the node and triangle layout the GPU reads. The
// shaders are tested against it, so it favours clarity and well-defined edge cases over speed.
#pragma once

#include <cstdint>
#include <functional>
#include <span>

#include "core/aabb.h"
#include "shared/types.h"

namespace penumbra::bvh {

struct Hit {
    float t = 0;
    std::uint32_t triangle = PN_NO_HIT;  // primitive (triangle or sphere) index in leaf order
    float u = 0, v = 0;                  // barycentrics of v1 and v2
    std::uint32_t instance = PN_NO_HIT;  // two-level scenes (bvh/two_level.h): the instance hit
};

struct TraversalCounts {
    std::uint32_t nodesVisited = 0, trianglesTested = 0;
};

// Box exits are scaled by this before comparing with entries, so that rounding in the slab test
// never culls a box that the exact triangle test would hit (pbrt's 1 + 2*gamma(3)). The shader
// uses the same constant.
inline constexpr float kSlabExitScale = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

// Moller-Trumbore by Cramer's rule, two-sided; a hit needs t in (0, tMax). The geometric normal
// e1 x e2 is formed first so that triangles with repeated vertices give a determinant of exactly
// zero and never report a hit (the classic arrangement leaves a rounding residue there, and
// then returns an arbitrary t).
bool intersectTriangle(const shader::TriVerts& tri, const Ray& ray, float tMax, float& t, float& u,
                       float& v);

// A triangle or (PN_TRI_SPHERE) a sphere slot; u and v are 0 for spheres. Sprite slots are never
// hit (bvh/sprite.h).
bool intersectPrimitive(const shader::TriVerts& prim, const Ray& ray, float tMax, float& t, float& u,
                        float& v);

// Closest hit with t in (0, ray.tMax); on a miss, triangle is PN_NO_HIT and t is ray.tMax. An
// empty node array (a scene without primitives) never hits.
Hit closestHit(std::span<const shader::BvhNode> nodes, std::span<const shader::TriVerts> tris,
               const Ray& ray, TraversalCounts* counts = nullptr);
// True at the first hit with t in (0, ray.tMax); for shadow rays.
bool anyHit(std::span<const shader::BvhNode> nodes, std::span<const shader::TriVerts> tris,
            const Ray& ray, TraversalCounts* counts = nullptr);
// The same two, in the subtree rooted at node `root` of `nodes` (a bottom level of a two-level
// scene, whose indices are absolute).
Hit closestHitBelow(std::span<const shader::BvhNode> nodes, std::span<const shader::TriVerts> tris, std::uint32_t root,
                    const Ray& ray);
bool anyHitBelow(std::span<const shader::BvhNode> nodes, std::span<const shader::TriVerts> tris, std::uint32_t root,
                 const Ray& ray);

// The traversal itself: calls onLeaf(first, count) for each leaf of the subtree at `root` whose
// box the ray enters before tMax, near first; tMax is read again after every leaf (a closer hit
// prunes), and onLeaf returning true stops the walk.
using LeafVisitor = std::function<bool(std::uint32_t first, std::uint32_t count)>;
void forEachLeaf(std::span<const shader::BvhNode> nodes, std::uint32_t root, const Ray& ray, const float& tMax,
                 const LeafVisitor& onLeaf);

// Every triangle, in order; the oracle for the two above.
Hit closestHitBrute(std::span<const shader::TriVerts> tris, const Ray& ray);

}  // namespace penumbra::bvh
