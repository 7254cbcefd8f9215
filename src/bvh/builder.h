// Binned-SAH BVH construction, producing the flattened depth-first node array the GPU walks.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bvh/triangle.h"
#include "core/aabb.h"
#include "shared/types.h"

namespace penumbra::bvh {

struct BuildOptions {
    int bins = 16;               // SAH candidates per axis; clamped to [2, kMaxBins]
    int maxLeafSize = 4;         // no leaf ever holds more (clamped to >= 1)
    float traversalCost = 1.0f;  // Ct: cost of visiting an interior node, relative to...
    float intersectCost = 1.0f;  // Ci: ...the cost of one primitive test
};

inline constexpr int kMaxBins = 128;

struct Bvh {
    // Depth-first; see shader::BvhNode. Empty when there are no primitives: traversal treats an
    // empty array as "no hit", because a node with count 0 would mean an interior node.
    std::vector<shader::BvhNode> nodes;
    // primOrder[i] = original index of the i-th primitive in leaf order. Always a permutation of
    // all input indices, including primitives with unusable bounds (see sanitizedBounds).
    std::vector<std::uint32_t> primOrder;
};

// Bounds the builder uses for one primitive. Boxes that are empty or not finite (NaN or inf
// coordinates) become a point at the origin: such a primitive is kept (so primOrder stays a
// permutation and triangle counts match), but it cannot inflate the tree or poison the SAH, and
// the triangle test never reports a hit on non-finite vertices anyway.
inline Aabb sanitizedBounds(const Aabb& box) {
    if (box.empty() || !isFinite(box.lo) || !isFinite(box.hi)) return Aabb{Vec3(0.0f), Vec3(0.0f)};
    return box;
}

// Leaves never exceed maxLeafSize and no leaf is deeper than PN_BVH_MAX_DEPTH (root = depth 1):
// where SAH splits would go too deep, the builder switches to balanced median splits.
Bvh build(std::span<const Aabb> primBounds, const BuildOptions& options = {});
Bvh buildTriangles(std::span<const Triangle> tris, const BuildOptions& options = {});

// TriVerts in leaf order, ready for upload next to bvh.nodes.
std::vector<shader::TriVerts> leafOrderTriVerts(const Bvh& bvh, std::span<const Triangle> tris);

}  // namespace penumbra::bvh
