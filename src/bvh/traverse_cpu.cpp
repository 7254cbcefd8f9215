#include "bvh/traverse_cpu.h"

#include <algorithm>
#include <limits>
#include <string>

#include "bvh/slab.h"
#include "bvh/sphere.h"
#include "bvh/sprite.h"
#include "core/error.h"

namespace penumbra::bvh {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

struct RaySetup : SlabRay {
    using SlabRay::SlabRay;
    float enter(const shader::BvhNode& node, float tMax) const { return SlabRay::enter(node.boundsMin, node.boundsMax, tMax); }
};

// Shared by closest and any hit: visits leaves near-first and prunes boxes beyond the current
// closest t. onLeaf returns true to stop the whole traversal.
template <typename OnLeaf>
void traverse(std::span<const shader::BvhNode> nodes, const Ray& ray, const float& tMax,
              TraversalCounts* counts, OnLeaf&& onLeaf, std::uint32_t root = 0) {
    if (nodes.empty()) return;
    const auto nodeCount = std::uint32_t(nodes.size());
    PN_CHECK(root < nodeCount);
    RaySetup setup(ray);
    if (setup.enter(nodes[root], tMax) == kInf) {
        if (counts) ++counts->nodesVisited;
        return;
    }
    // Far children wait with their entry distance, so a closer hit found meanwhile discards them
    // without another box test.
    std::uint32_t stack[PN_BVH_STACK_SIZE];
    float stackEntry[PN_BVH_STACK_SIZE];
    int sp = 0;
    std::uint32_t current = root;
    for (;;) {
        if (counts) ++counts->nodesVisited;
        const shader::BvhNode& node = nodes[current];
        if (node.triCount > 0) {
            if (onLeaf(node.firstOrRight, node.triCount)) return;
        } else {
            std::uint32_t left = current + 1, right = node.firstOrRight;
            PN_CHECK(left < nodeCount && right < nodeCount);
            float tLeft = setup.enter(nodes[left], tMax);
            float tRight = setup.enter(nodes[right], tMax);
            if (tLeft != kInf || tRight != kInf) {
                if (tRight < tLeft) {
                    std::swap(left, right);
                    std::swap(tLeft, tRight);
                }
                if (tRight != kInf) {
                    // A deeper stack than the builder can produce means a foreign, broken tree.
                    PN_CHECK(sp < PN_BVH_STACK_SIZE);
                    stack[sp] = right;
                    stackEntry[sp++] = tRight;
                }
                current = left;
                continue;
            }
        }
        for (;;) {
            if (sp == 0) return;
            --sp;
            if (stackEntry[sp] <= tMax * kSlabExitScale) break;
        }
        current = stack[sp];
    }
}

void checkLeafRange(std::uint32_t first, std::uint32_t count, std::size_t triCount) {
    if (std::uint64_t(first) + count > triCount)
        throw Error("BVH leaf references triangles [" + std::to_string(first) + ", " +
                    std::to_string(std::uint64_t(first) + count) + ") but only " +
                    std::to_string(triCount) + " exist");
}

}  // namespace

bool intersectTriangle(const shader::TriVerts& tri, const Ray& ray, float tMax, float& t, float& u,
                       float& v) {
    // Solve origin + t*dir = v0 + u*e1 + v*e2 by Cramer's rule; the determinant is -dir.n.
    Vec3 n = cross(tri.e1, tri.e2);
    float det = -dot(ray.direction, n);
    if (!(det != 0.0f) || !std::isfinite(det)) return false;  // parallel, degenerate, or NaN
    float inv = 1.0f / det;
    Vec3 s = ray.origin - tri.v0;
    Vec3 c = cross(s, ray.direction);
    float uu = dot(tri.e2, c) * inv;
    if (!(uu >= 0.0f && uu <= 1.0f)) return false;
    float vv = -dot(tri.e1, c) * inv;
    if (!(vv >= 0.0f && uu + vv <= 1.0f)) return false;
    float tt = dot(s, n) * inv;
    if (!(tt > 0.0f && tt < tMax)) return false;
    t = tt;
    u = uu;
    v = vv;
    return true;
}

bool intersectPrimitive(const shader::TriVerts& prim, const Ray& ray, float tMax, float& t, float& u,
                        float& v) {
    if (isSphere(prim)) {
        if (!intersectSphere(prim, ray, tMax, t)) return false;
        u = v = 0.0f;
        return true;
    }
    if (isSprite(prim)) return false;  // see bvh/sprite.h
    return intersectTriangle(prim, ray, tMax, t, u, v);
}

namespace {

Hit closestHitFrom(std::span<const shader::BvhNode> nodes, std::span<const shader::TriVerts> tris, std::uint32_t root,
                   const Ray& ray, TraversalCounts* counts) {
    Hit hit;
    hit.t = ray.tMax;
    traverse(nodes, ray, hit.t, counts, [&](std::uint32_t first, std::uint32_t count) {
        checkLeafRange(first, count, tris.size());
        for (std::uint32_t i = first; i < first + count; ++i) {
            if (counts) ++counts->trianglesTested;
            float t, u, v;
            if (intersectPrimitive(tris[i], ray, hit.t, t, u, v)) hit = {t, i, u, v};
        }
        return false;
    }, root);
    return hit;
}

bool anyHitFrom(std::span<const shader::BvhNode> nodes, std::span<const shader::TriVerts> tris, std::uint32_t root,
                const Ray& ray, TraversalCounts* counts) {
    bool found = false;
    const float tMax = ray.tMax;
    traverse(nodes, ray, tMax, counts, [&](std::uint32_t first, std::uint32_t count) {
        checkLeafRange(first, count, tris.size());
        for (std::uint32_t i = first; i < first + count; ++i) {
            if (counts) ++counts->trianglesTested;
            float t, u, v;
            if (intersectPrimitive(tris[i], ray, tMax, t, u, v)) return found = true;
        }
        return false;
    }, root);
    return found;
}

}  // namespace

Hit closestHit(std::span<const shader::BvhNode> nodes, std::span<const shader::TriVerts> tris,
               const Ray& ray, TraversalCounts* counts) {
    return closestHitFrom(nodes, tris, 0, ray, counts);
}

Hit closestHitBelow(std::span<const shader::BvhNode> nodes, std::span<const shader::TriVerts> tris, std::uint32_t root,
                    const Ray& ray) {
    return closestHitFrom(nodes, tris, root, ray, nullptr);
}

bool anyHitBelow(std::span<const shader::BvhNode> nodes, std::span<const shader::TriVerts> tris, std::uint32_t root,
                 const Ray& ray) {
    return anyHitFrom(nodes, tris, root, ray, nullptr);
}

void forEachLeaf(std::span<const shader::BvhNode> nodes, std::uint32_t root, const Ray& ray, const float& tMax,
                 const LeafVisitor& onLeaf) {
    traverse(nodes, ray, tMax, nullptr, onLeaf, root);
}

bool anyHit(std::span<const shader::BvhNode> nodes, std::span<const shader::TriVerts> tris,
            const Ray& ray, TraversalCounts* counts) {
    return anyHitFrom(nodes, tris, 0, ray, counts);
}

Hit closestHitBrute(std::span<const shader::TriVerts> tris, const Ray& ray) {
    Hit hit;
    hit.t = ray.tMax;
    for (std::uint32_t i = 0; i < tris.size(); ++i) {
        float t, u, v;
        if (intersectPrimitive(tris[i], ray, hit.t, t, u, v)) hit = {t, i, u, v};
    }
    return hit;
}

}  // namespace penumbra::bvh
