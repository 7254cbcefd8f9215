// Refitting a BVH after its mesh deforms: the refitted tree (old shape, new boxes) must pass the
// structural checks and give exactly the hits of the deformed triangles that brute force and a
// tree rebuilt over them give.
#include <gtest/gtest.h>

#include <cmath>

#include "bvh/refit.h"
#include "bvh/triangle.h"
#include "bvh/traverse_cpu.h"
#include "bvh/validate.h"
#include "bvh_test_util.h"

namespace penumbra::bvh {
namespace {

// A smooth deformation that moves vertices by up to a quarter of the soup's size (far enough
// that the old boxes no longer hold the triangles).
Vec3 deform(Vec3 p) {
    return p + Vec3{0.25f * std::sin(5.0f * p.y), 0.2f * std::cos(4.0f * p.z + 1.0f), 0.15f * std::sin(3.0f * p.x)};
}

// The boxes refit takes: each triangle's, in the tree's leaf order.
std::vector<Aabb> leafBounds(const Bvh& tree, const std::vector<Triangle>& tris) {
    std::vector<Aabb> out;
    for (std::uint32_t original : tree.primOrder) out.push_back(sanitizedBounds(bounds(tris[original])));
    return out;
}

TEST(Refit, RefittedTreeGivesTheHitsOfARebuild) {
    const std::vector<Triangle> rest = test::randomSoup(3000, 11);
    Bvh tree = buildTriangles(rest);
    std::vector<Triangle> moved = rest;
    for (Triangle& t : moved) t = {deform(t.v0), deform(t.v1), deform(t.v2)};
    const std::vector<shader::TriVerts> leafTris = leafOrderTriVerts(tree, moved);
    refit(tree.nodes, 0, std::uint32_t(tree.nodes.size()), leafBounds(tree, moved));
    EXPECT_NO_THROW(validate(tree, test::boxesOf(moved)));
    const Bvh rebuilt = buildTriangles(moved);
    const std::vector<shader::TriVerts> rebuiltTris = leafOrderTriVerts(rebuilt, moved);
    std::size_t hits = 0;
    for (const Ray& ray : test::mixedRays(moved, 4000, 12)) {
        const Hit a = closestHit(tree.nodes, leafTris, ray), b = closestHit(rebuilt.nodes, rebuiltTris, ray);
        ASSERT_EQ(a.triangle == PN_NO_HIT, b.triangle == PN_NO_HIT);
        if (a.triangle == PN_NO_HIT) continue;
        ++hits;
        EXPECT_EQ(a.t, b.t);
        // The same original triangle, unless two tie at this t.
        if (tree.primOrder[a.triangle] != rebuilt.primOrder[b.triangle]) {
            EXPECT_TRUE(test::sameT(a.t, b.t));
        }
        EXPECT_EQ(anyHit(tree.nodes, leafTris, ray), true);
    }
    EXPECT_GT(hits, 1000u);
}

TEST(Refit, AnUndeformedMeshKeepsItsBoxes) {
    const std::vector<Triangle> tris = test::randomSoup(500, 3);
    Bvh tree = buildTriangles(tris);
    const Bvh original = tree;
    refit(tree.nodes, 0, std::uint32_t(tree.nodes.size()), leafBounds(tree, tris));
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        for (int a = 0; a < 3; ++a) {
            EXPECT_EQ(tree.nodes[i].boundsMin[a], original.nodes[i].boundsMin[a]) << "node " << i;
            EXPECT_EQ(tree.nodes[i].boundsMax[a], original.nodes[i].boundsMax[a]) << "node " << i;
        }
    }
}

}  // namespace
}  // namespace penumbra::bvh
