// The compressed wide BVH: its quantized boxes contain everything below them, every primitive
// sits in exactly one leaf, and its reference walk finds the same closest hits as the binary
// walk and brute force.
#include "bvh/wide.h"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <cstring>
#include <random>
#include <string>

#include "bvh/sphere.h"
#include "bvh/stats.h"
#include "bvh/traverse_wide_cpu.h"
#include "bvh_test_util.h"
#include "core/error.h"
#include "scene/io/obj.h"
#include "../io/io_test_util.h"

namespace penumbra::bvh {
namespace {

using test::mixedRays;
using test::randomSoup;
using test::sameT;

// Primitives (triangles and spheres) in the order the builder numbered them, and their boxes.
struct Primitives {
    std::vector<shader::TriVerts> verts;
    std::vector<Aabb> boxes;
    std::vector<Triangle>
        triangles;  // for the ray generator: triangles, and spheres' centres as points
};

Primitives fromTriangles(const std::vector<Triangle>& tris) {
    Primitives p;
    for (const Triangle& t : tris) {
        p.verts.push_back(toTriVerts(t));
        p.boxes.push_back(bounds(t));
        p.triangles.push_back(t);
    }
    return p;
}

void addSpheres(Primitives& p, std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 c(u(rng), u(rng), u(rng));
        const float r = 0.02f + 0.1f * u(rng);
        p.verts.push_back(toSphereVerts(c, r));
        p.boxes.push_back(sphereBounds(c, r));
        p.triangles.push_back({c, c + Vec3(r, 0, 0), c + Vec3(0, r, 0)});
    }
}

// Both trees over one primitive order, as buildSceneArrays makes them.
struct Trees {
    Bvh binary;
    WideBvh wide;
    std::vector<shader::TriVerts> leafPrims;  // in the order both trees index
    std::vector<Aabb> leafBoxes;
};

Trees buildBoth(const Primitives& p, const BuildOptions& options = {}) {
    Trees t;
    t.binary = build(p.boxes, options);
    t.wide = collapseToWide(t.binary);
    for (std::uint32_t i : t.binary.primOrder) {
        t.leafPrims.push_back(p.verts[i]);
        t.leafBoxes.push_back(sanitizedBounds(p.boxes[i]));
    }
    return t;
}

bool contains(const Aabb& outer, const Aabb& inner) {
    for (int a = 0; a < 3; ++a)
        if (!(outer.lo[a] <= inner.lo[a] && inner.hi[a] <= outer.hi[a])) return false;
    return true;
}

// Walks the wide tree: every primitive below a slot lies in its decoded box, each primitive is
// in exactly one leaf, and the tree is a tree (every node reached once, depth as reported).
void checkStructure(const Trees& t) {
    const auto& nodes = t.wide.nodes;
    if (t.leafPrims.empty()) {
        EXPECT_TRUE(nodes.empty());
        return;
    }
    ASSERT_FALSE(nodes.empty());
    std::vector<int> primSeen(t.leafPrims.size()), nodeSeen(nodes.size());
    std::uint32_t deepest = 0;
    // Returns the box of everything below node `index`.
    auto visit = [&](auto&& self, std::uint32_t index, std::uint32_t depth) -> Aabb {
        EXPECT_LT(index, nodes.size());
        if (index >= nodes.size()) return Aabb{};
        ++nodeSeen[index];
        deepest = std::max(deepest, depth);
        const shader::WideNode& node = nodes[index];
        Aabb all;
        std::uint32_t interior = 0;
        for (int s = 0; s < kWideArity; ++s) {
            const std::uint32_t meta = wideMeta(node, s);
            if (wideSlotEmpty(meta)) continue;
            const Aabb slot = wideSlotBounds(node, s);
            Aabb below;
            if (wideSlotInterior(meta)) {
                EXPECT_EQ(meta & 7u, std::uint32_t(s));
                interior |= 1u << s;
                below = self(self, wideChildIndex(node, s), depth + 1);
            } else {
                EXPECT_LT(wideLeafOffset(meta) + wideLeafCount(meta), 25u);
                for (std::uint32_t k = 0; k < wideLeafCount(meta); ++k) {
                    const std::uint32_t prim = node.primBase + wideLeafOffset(meta) + k;
                    EXPECT_LT(prim, t.leafPrims.size());
                    if (prim >= t.leafPrims.size()) continue;
                    ++primSeen[prim];
                    below.grow(t.leafBoxes[prim]);
                }
            }
            EXPECT_TRUE(contains(slot, below))
                << "node " << index << " slot " << s << ": decoded (" << slot.lo.x << " "
                << slot.lo.y << " " << slot.lo.z << ")-(" << slot.hi.x << " " << slot.hi.y << " "
                << slot.hi.z << ") misses (" << below.lo.x << " " << below.lo.y << " " << below.lo.z
                << ")-(" << below.hi.x << " " << below.hi.y << " " << below.hi.z << ")";
            all.grow(below);
        }
        EXPECT_EQ(node.exponentsMask >> 24, interior) << "node " << index;
        return all;
    };
    visit(visit, 0, 1);
    for (std::size_t i = 0; i < primSeen.size(); ++i)
        ASSERT_EQ(primSeen[i], 1) << "primitive " << i;
    for (std::size_t i = 0; i < nodeSeen.size(); ++i)
        ASSERT_EQ(nodeSeen[i], 1) << "wide node " << i;
    EXPECT_EQ(deepest, t.wide.maxDepth);
    EXPECT_LE(std::size_t(t.wide.maxDepth), computeStats(t.binary, {}).maxDepth);
}

// Wide, binary and brute force agree on the closest t (ties may pick either primitive, but the
// winner must be hit there), and on occlusion.
void expectSameHits(const Trees& t, const std::vector<Ray>& rays) {
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Ray& ray = rays[i];
        SCOPED_TRACE(::testing::Message() << "ray " << i);
        const Hit wide = closestHitWide(t.wide.nodes, t.leafPrims, ray);
        const Hit binary = closestHit(t.binary.nodes, t.leafPrims, ray);
        const Hit brute = closestHitBrute(t.leafPrims, ray);
        ASSERT_EQ(wide.triangle == PN_NO_HIT, brute.triangle == PN_NO_HIT);
        ASSERT_EQ(binary.triangle == PN_NO_HIT, brute.triangle == PN_NO_HIT);
        EXPECT_EQ(anyHitWide(t.wide.nodes, t.leafPrims, ray), brute.triangle != PN_NO_HIT);
        if (brute.triangle == PN_NO_HIT) continue;
        EXPECT_TRUE(sameT(wide.t, brute.t)) << wide.t << " vs " << brute.t;
        EXPECT_TRUE(sameT(binary.t, brute.t)) << binary.t << " vs " << brute.t;
        float tt, u, v;
        ASSERT_TRUE(intersectPrimitive(t.leafPrims[wide.triangle], ray, ray.tMax, tt, u, v));
        EXPECT_EQ(tt, wide.t);
        if (wide.triangle == binary.triangle) {
            EXPECT_EQ(wide.t, binary.t);
        }
        if (::testing::Test::HasFailure()) return;
    }
}

// Random trees of every leaf size, scale and offset; the walk must agree on them too.
TEST(WideBvh, QuantizedBoxesContainTheirChildrenOnRandomTrees) {
    std::mt19937 rng(11);
    for (int round = 0; round < 40; ++round) {
        const std::size_t count = std::size_t(1) + rng() % (round < 20 ? 40 : 3000);
        std::vector<Triangle> tris = randomSoup(count, std::uint32_t(rng()));
        // Far from the origin, very small, very large, or flat along an axis: where rounding bites.
        const float scale = std::array<float, 5>{1.0f, 1e-4f, 3e4f, 1.0f, 0.37f}[round % 5];
        const Vec3 offset = round % 3 == 0 ? Vec3(1e5f, -3e3f, 17.0f) : Vec3(0.0f);
        const int flatAxis = round % 7 == 6 ? int(rng() % 3) : -1;
        for (Triangle& t : tris)
            for (Vec3* v : {&t.v0, &t.v1, &t.v2}) {
                *v = *v * scale + offset;
                if (flatAxis >= 0) (*v)[flatAxis] = offset[flatAxis] + 0.5f;
            }
        BuildOptions options;
        options.maxLeafSize = 1 + int(rng() % kWideMaxBinaryLeaf);
        SCOPED_TRACE(::testing::Message() << "round " << round << ", " << count
                                          << " triangles, leaves of up to " << options.maxLeafSize);
        Primitives p = fromTriangles(tris);
        Trees t = buildBoth(p, options);
        checkStructure(t);
        expectSameHits(t, mixedRays(tris, 100, std::uint32_t(round)));
        if (::testing::Test::HasFailure()) return;
    }
}

TEST(WideBvh, EmptyAndTinyTrees) {
    Bvh empty;
    EXPECT_TRUE(collapseToWide(empty).nodes.empty());
    EXPECT_EQ(closestHitWide({}, {}, Ray{{0, 0, 0}, {0, 0, 1}}).triangle, PN_NO_HIT);
    for (std::size_t n : {1, 2, 3, 4, 5, 25}) {
        const std::vector<Triangle> tris = randomSoup(n, std::uint32_t(n));
        Trees t = buildBoth(fromTriangles(tris));
        checkStructure(t);
        expectSameHits(t, mixedRays(tris, 200, 5));
    }
}

TEST(WideBvh, SameHitsAsBinaryAndBruteOnSoups) {
    for (std::size_t n : {100, 2000, 20000}) {
        SCOPED_TRACE(::testing::Message() << n << " triangles");
        const std::vector<Triangle> tris = randomSoup(n, std::uint32_t(n + 1));
        Trees t = buildBoth(fromTriangles(tris));
        expectSameHits(t, mixedRays(tris, 3000, std::uint32_t(n)));
    }
}

// A scanned surface of 69,666 small triangles: a deeper, denser tree than any soup above.
TEST(WideBvh, SameHitsAsBinaryAndBruteOnTheBunny) {
    const std::filesystem::path path = "/usr/share/glmark2/models/bunny.obj";
    PENUMBRA_REQUIRE_ASSET(path);
    const Scene scene = loadObj(path);
    std::vector<Triangle> tris;
    for (const Mesh& m : scene.meshes)
        for (std::size_t k = 0; k + 2 < m.indices.size(); k += 3)
            tris.push_back({m.positions[m.indices[k]], m.positions[m.indices[k + 1]], m.positions[m.indices[k + 2]]});
    ASSERT_EQ(tris.size(), 69666u);
    Trees t = buildBoth(fromTriangles(tris));
    checkStructure(t);
    expectSameHits(t, mixedRays(tris, 1200, 17));
}

TEST(WideBvh, SameHitsWithSpheres) {
    Primitives p = fromTriangles(randomSoup(300, 3));
    addSpheres(p, 60, 4);
    Trees t = buildBoth(p);
    checkStructure(t);
    expectSameHits(t, mixedRays(p.triangles, 3000, 6));
}

TEST(WideBvh, BinaryTreeStaysValidAfterReordering) {
    // The collapse renumbers primitives; the binary tree's leaves must follow them.
    const std::vector<Triangle> tris = randomSoup(5000, 8);
    Trees t = buildBoth(fromTriangles(tris));
    for (std::size_t i = 0; i < t.leafPrims.size(); ++i) {
        const shader::TriVerts original = toTriVerts(tris[t.binary.primOrder[i]]);
        ASSERT_EQ(t.leafPrims[i].v0.x, original.v0.x);
    }
    for (const shader::BvhNode& n : t.binary.nodes) {
        if (n.triCount == 0) continue;
        for (std::uint32_t k = n.firstOrRight; k < n.firstOrRight + n.triCount; ++k)
            ASSERT_TRUE(contains(Aabb{n.boundsMin, n.boundsMax}, t.leafBoxes[k]));
    }
}

TEST(WideBvh, WalkCullsAndVisitsFewNodes) {
    // Rays into a dense soup: the walk touches a small part of the tree and loads about a third
    // of the binary walk's nodes. It tests more primitives (all of a node's hit leaves at once,
    // where the binary walk's near-first leaf order prunes: 2.1x here), within a bound.
    const std::vector<Triangle> tris = randomSoup(20000, 10);
    Trees t = buildBoth(fromTriangles(tris));
    TraversalCounts wide, binary;
    const std::vector<Ray> rays = mixedRays(tris, 2000, 11);
    for (const Ray& r : rays) {
        closestHitWide(t.wide.nodes, t.leafPrims, r, &wide);
        closestHit(t.binary.nodes, t.leafPrims, r, &binary);
    }
    EXPECT_LT(wide.nodesVisited, rays.size() * t.wide.nodes.size() / 50);
    EXPECT_LT(wide.nodesVisited, binary.nodesVisited / 2);  // eight children per visit
    EXPECT_LT(wide.trianglesTested, binary.trianglesTested * 3);
}

// Tasks only change who collapses which subtree: nodes, depth and both primitive orders must be
// exactly the serial collapse's, down to the byte, whatever the task size.
TEST(WideBvh, ParallelCollapseIsIdenticalToSerial) {
    std::mt19937 rng(12);
    for (std::size_t count : {1, 7, 2000, 30000}) {
        BuildOptions options;
        options.maxLeafSize = 1 + int(rng() % kWideMaxBinaryLeaf);
        const Bvh tree = buildTriangles(randomSoup(count, std::uint32_t(count)), options);
        Bvh serial = tree;
        const WideBvh expected = collapseToWide(serial, CollapseOptions{0});
        for (std::uint32_t taskPrimitives : {1u, 64u, 4096u}) {
            SCOPED_TRACE(::testing::Message() << count << " triangles, leaves of up to " << options.maxLeafSize
                                              << ", tasks from " << taskPrimitives << " primitives");
            Bvh parallel = tree;
            const WideBvh wide = collapseToWide(parallel, CollapseOptions{taskPrimitives});
            ASSERT_EQ(wide.nodes.size(), expected.nodes.size());
            EXPECT_EQ(std::memcmp(wide.nodes.data(), expected.nodes.data(), wide.nodes.size() * sizeof(shader::WideNode)), 0);
            EXPECT_EQ(wide.maxDepth, expected.maxDepth);
            EXPECT_EQ(parallel.primOrder, serial.primOrder);
            ASSERT_EQ(parallel.nodes.size(), serial.nodes.size());
            EXPECT_EQ(std::memcmp(parallel.nodes.data(), serial.nodes.data(), serial.nodes.size() * sizeof(shader::BvhNode)), 0);
        }
    }
}

TEST(WideBvh, RejectsLeavesTooBigToSpread) {
    BuildOptions options;
    options.maxLeafSize = 32;
    options.traversalCost = 1000.0f;  // make the SAH prefer big leaves
    Bvh tree = buildTriangles(randomSoup(64, 9), options);
    bool big = false;
    for (const shader::BvhNode& n : tree.nodes)
        big |= n.triCount > std::uint32_t(kWideMaxBinaryLeaf);
    if (!big) GTEST_SKIP() << "the builder made no leaf over " << kWideMaxBinaryLeaf;
    Bvh copy = tree;
    EXPECT_THROW(collapseToWide(tree), Error);
    EXPECT_THROW(collapseToWide(copy, CollapseOptions{1}), Error);  // thrown in a task
}

}  // namespace
}  // namespace penumbra::bvh
