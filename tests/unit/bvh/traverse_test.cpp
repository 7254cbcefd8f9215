// The CPU reference traversal against brute force on every kind of geometry and ray.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "bvh/stats.h"
#include "bvh/traverse_cpu.h"
#include "bvh_test_util.h"
#include "median_split.h"

namespace penumbra::bvh {
namespace {

using test::expectAllMatch;
using test::mixedRays;
using test::prepare;
using test::Prepared;
using test::randomSoup;

// Two triangles covering the axis-aligned square with corners a and b in the plane axis = c.
void addQuad(std::vector<Triangle>& out, int axis, float c, float a0, float a1, float b0,
             float b1) {
    auto p = [&](float s, float t) {
        Vec3 v;
        v[axis] = c;
        v[(axis + 1) % 3] = s;
        v[(axis + 2) % 3] = t;
        return v;
    };
    out.push_back({p(a0, b0), p(a1, b0), p(a1, b1)});
    out.push_back({p(a0, b0), p(a1, b1), p(a0, b1)});
}

void addBox(std::vector<Triangle>& out, Vec3 lo, Vec3 hi) {
    for (int axis = 0; axis < 3; ++axis) {
        int s = (axis + 1) % 3, t = (axis + 2) % 3;
        for (float c : {lo[axis], hi[axis]}) addQuad(out, axis, c, lo[s], hi[s], lo[t], hi[t]);
    }
}

TEST(BvhTraverse, IntersectTriangleBasics) {
    shader::TriVerts tri = toTriVerts({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    float t, u, v;
    Ray down{{0.25f, 0.25f, 2.0f}, {0, 0, -1}};
    ASSERT_TRUE(intersectTriangle(tri, down, 10.0f, t, u, v));
    EXPECT_FLOAT_EQ(t, 2.0f);
    EXPECT_FLOAT_EQ(u, 0.25f);
    EXPECT_FLOAT_EQ(v, 0.25f);
    Ray up{{0.25f, 0.25f, -2.0f}, {0, 0, 2}};  // two-sided, t in units of the direction
    ASSERT_TRUE(intersectTriangle(tri, up, 10.0f, t, u, v));
    EXPECT_FLOAT_EQ(t, 1.0f);
    EXPECT_FALSE(intersectTriangle(tri, down, 2.0f, t, u, v));  // t must be < tMax
    Ray behind{{0.25f, 0.25f, -2.0f}, {0, 0, -1}};
    EXPECT_FALSE(intersectTriangle(tri, behind, 10.0f, t, u, v));  // t must be > 0
    Ray onPlane{{0.25f, 0.25f, 0.0f}, {0, 0, -1}};
    EXPECT_FALSE(intersectTriangle(tri, onPlane, 10.0f, t, u, v));
    Ray grazing{{-1.0f, 0.25f, 0.0f}, {1, 0, 0}};
    EXPECT_FALSE(intersectTriangle(tri, grazing, 10.0f, t, u, v));
    Ray outside{{0.75f, 0.75f, 2.0f}, {0, 0, -1}};
    EXPECT_FALSE(intersectTriangle(tri, outside, 10.0f, t, u, v));
    // Repeated vertices: zero area, never a hit, whatever the ray.
    shader::TriVerts degenerate =
        toTriVerts({{0.3f, 0.7f, 0.1f}, {1.3f, 0.2f, 0.9f}, {1.3f, 0.2f, 0.9f}});
    Ray at{{0.0f, 0.0f, 0.0f}, Vec3(0.8f, 0.45f, 0.5f) - Vec3(0.0f)};
    EXPECT_FALSE(intersectTriangle(degenerate, at, 10.0f, t, u, v));
}

TEST(BvhTraverse, EmptyTreeNeverHits) {
    Prepared p = prepare({});
    Ray r{{0, 0, 0}, {1, 0, 0}};
    EXPECT_EQ(closestHit(p.bvh.nodes, p.leafTris, r).triangle, PN_NO_HIT);
    EXPECT_FALSE(anyHit(p.bvh.nodes, p.leafTris, r));
    EXPECT_EQ(closestHitBrute(p.leafTris, r).triangle, PN_NO_HIT);
}

TEST(BvhTraverse, RandomSoupsMatchBruteForce) {
    for (std::uint32_t seed : {1u, 2u, 3u, 4u}) {
        for (std::size_t n : {1u, 2u, 7u, 64u, 500u, 5000u}) {
            SCOPED_TRACE(::testing::Message() << "seed " << seed << " n " << n);
            Prepared p = prepare(randomSoup(n, seed));
            expectAllMatch(p, mixedRays(p.tris, n >= 5000 ? 1500 : 3000, seed * 7 + 1));
            if (HasFailure()) return;
        }
    }
}

TEST(BvhTraverse, OtherBuildOptionsMatchBruteForce) {
    auto tris = randomSoup(2000, 21);
    for (BuildOptions o : {BuildOptions{2, 1, 1, 1}, BuildOptions{64, 16, 1, 1}}) {
        Prepared p = prepare(tris, o);
        expectAllMatch(p, mixedRays(p.tris, 2000, 22));
    }
}

TEST(BvhTraverse, MedianSplitTreeMatchesBruteForce) {
    // The traversal must not depend on anything the SAH builder happens to guarantee.
    Prepared p = prepare(randomSoup(3000, 31));
    p.bvh = test::buildMedianSplit(test::boxesOf(p.tris), 3);
    p.leafTris = leafOrderTriVerts(p.bvh, p.tris);
    expectAllMatch(p, mixedRays(p.tris, 2000, 32));
}

TEST(BvhTraverse, DegenerateTrianglesMatchBruteForce) {
    auto tris = randomSoup(1500, 41);
    std::mt19937 rng(42);
    for (std::size_t i = 0; i < tris.size(); i += 3) {
        switch (rng() % 4) {
            case 0:
                tris[i].v1 = tris[i].v0;
                break;  // repeated vertex
            case 1:
                tris[i].v1 = tris[i].v2 = tris[i].v0;
                break;  // a point
            case 2:
                tris[i].v2 = (tris[i].v0 + tris[i].v1) * 0.5f;
                break;  // collinear
            default:
                tris[i].v2 = tris[i].v1;
                break;
        }
    }
    Prepared p = prepare(tris);
    expectAllMatch(p, mixedRays(p.tris, 4000, 43));
}

TEST(BvhTraverse, CoplanarGridWithDuplicatesMatchesBruteForce) {
    // A 40x40 grid of quads in z = 0.5, every quad twice (exact ties), plus rays straight down
    // onto grid vertices and edges, where neighbouring triangles tie too.
    std::vector<Triangle> tris;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j)
            for (int copy = 0; copy < 2; ++copy)
                addQuad(tris, 2, 0.5f, i * 0.025f, (i + 1) * 0.025f, j * 0.025f, (j + 1) * 0.025f);
    Prepared p = prepare(tris);
    auto rays = mixedRays(p.tris, 3000, 51);
    for (int i = 0; i <= 40; i += 3)
        for (int j = 0; j <= 40; j += 2) {
            Vec3 o(i * 0.025f, j * 0.025f + (j % 4 ? 0.0125f : 0.0f), 2.0f);
            rays.push_back({o, {0, 0, -1}});
            rays.push_back({o, {0.0f, -0.0f, -3.0f}});
            rays.push_back({Vec3(o.x, o.y, 0.5f), {1, 0, 0}});  // in the plane: parallel, no hit
        }
    expectAllMatch(p, rays);
}

TEST(BvhTraverse, AxisAlignedBoxesWithFaceParallelRays) {
    // Cubes of axis-aligned quads; node boxes then have faces exactly on triangle planes, and
    // rays parallel to an axis that run exactly along those faces make the slab test divide
    // 0 by 0. The BVH must agree with brute force on every one of them.
    std::vector<Triangle> tris;
    for (int x = 0; x < 5; ++x)
        for (int y = 0; y < 5; ++y)
            for (int z = 0; z < 3; ++z)
                if ((x + y + z) % 2 == 0)
                    addBox(tris, Vec3(x, y, z), Vec3(x + 1.0f, y + 1.0f, z + 1.0f));
    Prepared p = prepare(tris);
    auto rays = mixedRays(p.tris, 3000, 61);
    for (int a = 0; a < 3; ++a)
        for (float sign : {1.0f, -1.0f})
            for (int i = -1; i <= 6; ++i)
                for (int j = -1; j <= 6; ++j)
                    for (float frac : {0.0f, 0.5f}) {
                        Vec3 o, d(0.0f);
                        o[a] = sign > 0 ? -2.0f : 8.0f;
                        o[(a + 1) % 3] = float(i) + frac;
                        o[(a + 2) % 3] = float(j);  // always on a face plane of some box
                        d[a] = sign;
                        rays.push_back({o, d});
                        o[a] = 2.5f;  // starting inside the geometry, still on the face plane
                        rays.push_back({o, d});
                    }
    expectAllMatch(p, rays);
}

TEST(BvhTraverse, RaysStartingInsideBoxes) {
    std::vector<Triangle> tris;
    addBox(tris, Vec3(-1.0f), Vec3(1.0f));
    addBox(tris, Vec3(-0.5f), Vec3(0.5f));
    auto soup = randomSoup(800, 71);
    tris.insert(tris.end(), soup.begin(), soup.end());
    Prepared p = prepare(tris);
    std::mt19937 rng(72);
    std::vector<Ray> rays;
    for (int i = 0; i < 4000; ++i) {
        Ray r{test::randomPoint(rng, {Vec3(-0.9f), Vec3(0.9f)}), test::randomDirection(rng)};
        rays.push_back(r);
    }
    expectAllMatch(p, rays);
    // Every ray from inside the closed outer box must hit something.
    for (const Ray& r : rays) ASSERT_NE(closestHit(p.bvh.nodes, p.leafTris, r).triangle, PN_NO_HIT);
}

TEST(BvhTraverse, ExponentialSpacingTreeMatchesBruteForce) {
    std::vector<Triangle> tris;
    float x = 1.0f;
    for (int i = 0; i < 70; ++i, x *= 3.0f) tris.push_back({{x, 0, 0}, {x, 1, 0}, {x, 0, 1}});
    Prepared p = prepare(tris, BuildOptions{2, 1, 1, 1});  // the depth-capped tree
    ASSERT_EQ(computeStats(p.bvh, {}).maxDepth, std::size_t(PN_BVH_MAX_DEPTH));
    std::vector<Ray> rays;
    std::mt19937 rng(81);
    std::uniform_real_distribution<float> u(0.0f, 0.5f);
    float xi = 1.0f;
    for (int i = 0; i < 70; ++i, xi *= 3.0f) {
        rays.push_back({{xi * 0.99f, u(rng), u(rng)}, {1, 0, 0}});
        rays.push_back({{xi * 1.01f, u(rng), u(rng)}, {-1, 0, 0}});
        rays.push_back({{0.0f, u(rng), u(rng)}, {xi, u(rng) * 0.1f, 0.0f}});
    }
    expectAllMatch(p, rays);
}

TEST(BvhTraverse, NonFiniteInputNeverHangs) {
    constexpr float nan = std::numeric_limits<float>::quiet_NaN();
    constexpr float inf = std::numeric_limits<float>::infinity();
    auto tris = randomSoup(300, 91);
    for (std::size_t i = 0; i < tris.size(); i += 5) tris[i].v1.y = (i % 2) ? nan : inf;
    Prepared p = prepare(tris);
    expectAllMatch(p, mixedRays(p.tris, 2000, 92));
    // Broken rays: no hits where the answer is undefined, and above all no crash or hang.
    for (Ray r : {Ray{{nan, 0, 0}, {1, 0, 0}}, Ray{{0, 0, 0}, {nan, nan, nan}},
                  Ray{{0, 0, 0}, {0, 0, 0}}, Ray{{-inf, 0.5f, 0.5f}, {1, 0, 0}}}) {
        closestHit(p.bvh.nodes, p.leafTris, r);
        anyHit(p.bvh.nodes, p.leafTris, r);
    }
}

TEST(BvhTraverse, CountsShowCulling) {
    Prepared p = prepare(randomSoup(5000, 101));
    TraversalCounts counts;
    auto rays = mixedRays(p.tris, 1000, 102);
    for (const Ray& r : rays) closestHit(p.bvh.nodes, p.leafTris, r, &counts);
    // Far fewer tests than brute force's 5000 per ray.
    EXPECT_LT(counts.trianglesTested / rays.size(), 200u);
    EXPECT_GT(counts.nodesVisited, rays.size());
}

}  // namespace
}  // namespace penumbra::bvh
