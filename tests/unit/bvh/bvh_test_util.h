// Scenes, rays and the brute-force comparison shared by the BVH tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "bvh/builder.h"
#include "bvh/traverse_cpu.h"
#include "bvh/triangle.h"

namespace penumbra::bvh::test {

inline Vec3 randomPoint(std::mt19937& rng, const Aabb& box) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    Vec3 e = box.extent();
    return box.lo + Vec3(u(rng) * e.x, u(rng) * e.y, u(rng) * e.z);
}

inline Vec3 randomDirection(std::mt19937& rng) {
    std::normal_distribution<float> n(0.0f, 1.0f);
    for (;;) {
        Vec3 d(n(rng), n(rng), n(rng));
        if (dot(d, d) > 1e-6f) return normalize(d);
    }
}

// Triangles with random corners around random centres in the unit cube; sizes shrink with the
// count so that the soup stays about as dense as a real mesh.
inline std::vector<Triangle> randomSoup(std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    Aabb unit{Vec3(0.0f), Vec3(1.0f)};
    float size = 0.5f / std::cbrt(float(std::max<std::size_t>(count, 1)));
    std::vector<Triangle> tris(count);
    for (auto& t : tris) {
        Vec3 c = randomPoint(rng, unit);
        t.v0 = c + Vec3(u(rng), u(rng), u(rng)) * size;
        t.v1 = c + Vec3(u(rng), u(rng), u(rng)) * size;
        t.v2 = c + Vec3(u(rng), u(rng), u(rng)) * size;
    }
    return tris;
}

inline Aabb boundsOf(const std::vector<Triangle>& tris) {
    Aabb box;
    for (const auto& t : tris) box.grow(sanitizedBounds(bounds(t)));
    return box;
}

inline Aabb boxOrUnit(const std::vector<Triangle>& tris) {
    Aabb box = boundsOf(tris);
    return box.empty() ? Aabb{Vec3(0.0f), Vec3(1.0f)} : box;
}

inline std::vector<Aabb> boxesOf(const std::vector<Triangle>& tris) {
    std::vector<Aabb> boxes;
    for (const auto& t : tris) boxes.push_back(bounds(t));
    return boxes;
}

// Rays of every kind the renderer makes: from outside aimed at a triangle (mostly hits), from
// inside the scene box in random directions, axis-parallel ones (zero direction components), and
// some with a finite tMax (shadow rays).
inline std::vector<Ray> mixedRays(const std::vector<Triangle>& tris, std::size_t count,
                                  std::uint32_t seed) {
    std::mt19937 rng(seed);
    Aabb box = boxOrUnit(tris);
    Vec3 pad = box.extent() * 0.5f + Vec3(0.1f);
    Aabb outer{box.lo - pad, box.hi + pad};
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Ray> rays;
    rays.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        Ray r;
        switch (i % 4) {
            case 0: {
                r.origin = randomPoint(rng, outer);
                const Triangle& t = tris[rng() % tris.size()];
                float a = u(rng), b = u(rng) * (1 - a);
                Vec3 target = t.v0 + (t.v1 - t.v0) * a + (t.v2 - t.v0) * b;
                r.direction = target - r.origin;
                break;
            }
            case 1:
                r.origin = randomPoint(rng, box);
                r.direction = randomDirection(rng);
                break;
            case 2: {
                r.origin = randomPoint(rng, outer);
                int axis = int(rng() % 3);
                r.direction = Vec3(0.0f);
                r.direction[axis] = (rng() & 1) ? 1.0f : -1.0f;
                if (rng() & 1) r.direction[(axis + 1) % 3] = -0.0f;  // negative zero component
                break;
            }
            default:
                r.origin = randomPoint(rng, box);
                r.direction = randomDirection(rng);
                r.tMax = u(rng) * maxComponent(box.extent());
                break;
        }
        rays.push_back(r);
    }
    return rays;
}

// A built scene: the BVH, its triangles in leaf order, and the original order for cross-checks.
struct Prepared {
    std::vector<Triangle> tris;
    Bvh bvh;
    std::vector<shader::TriVerts> leafTris;
    std::vector<shader::TriVerts> originalTris;
};

inline Prepared prepare(std::vector<Triangle> tris, const BuildOptions& options = {}) {
    Prepared p;
    p.tris = std::move(tris);
    p.bvh = buildTriangles(p.tris, options);
    p.leafTris = leafOrderTriVerts(p.bvh, p.tris);
    for (const auto& t : p.tris) p.originalTris.push_back(toTriVerts(t));
    return p;
}

inline bool sameT(float a, float b) {
    return std::abs(a - b) <= 1e-5f * std::max(1.0f, std::abs(b));
}

// BVH closest hit must equal brute force over the same leaf-order array and over the original
// order (through primOrder). Where triangles tie at one t (coplanar duplicates, shared edges)
// either may win, but the winner must really be hit at that t. anyHit must agree on occlusion.
inline void expectMatchesBrute(const Prepared& p, const Ray& ray, std::size_t rayIndex) {
    Hit bvh = closestHit(p.bvh.nodes, p.leafTris, ray);
    Hit brute = closestHitBrute(p.leafTris, ray);
    Hit original = closestHitBrute(p.originalTris, ray);
    SCOPED_TRACE(::testing::Message()
                 << "ray " << rayIndex << " origin (" << ray.origin.x << ", " << ray.origin.y
                 << ", " << ray.origin.z << ") dir (" << ray.direction.x << ", " << ray.direction.y
                 << ", " << ray.direction.z << ") tMax " << ray.tMax);
    ASSERT_EQ(bvh.triangle == PN_NO_HIT, brute.triangle == PN_NO_HIT);
    ASSERT_EQ(brute.triangle == PN_NO_HIT, original.triangle == PN_NO_HIT);
    EXPECT_EQ(anyHit(p.bvh.nodes, p.leafTris, ray), brute.triangle != PN_NO_HIT);
    if (brute.triangle == PN_NO_HIT) return;
    EXPECT_TRUE(sameT(bvh.t, brute.t)) << bvh.t << " vs " << brute.t;
    EXPECT_TRUE(sameT(original.t, brute.t)) << original.t << " vs " << brute.t;
    for (std::uint32_t leafIndex : {bvh.triangle, brute.triangle}) {
        float t, u, v;
        ASSERT_TRUE(intersectTriangle(p.leafTris[leafIndex], ray, ray.tMax, t, u, v));
        EXPECT_TRUE(sameT(t, brute.t)) << "triangle " << leafIndex << " hit at " << t;
    }
    if (bvh.triangle == brute.triangle) {
        EXPECT_EQ(bvh.u, brute.u);
        EXPECT_EQ(bvh.v, brute.v);
    }
    float t, u, v;
    ASSERT_TRUE(
        intersectTriangle(p.originalTris[p.bvh.primOrder[bvh.triangle]], ray, ray.tMax, t, u, v));
    EXPECT_TRUE(sameT(t, original.t));
}

inline void expectAllMatch(const Prepared& p, const std::vector<Ray>& rays) {
    for (std::size_t i = 0; i < rays.size(); ++i) {
        expectMatchesBrute(p, rays[i], i);
        if (::testing::Test::HasFailure()) return;  // one ray's story is enough
    }
}

}  // namespace penumbra::bvh::test
