// The stackless walk (--accel stackless, lib/stackless_bvh.glsl) and the per-object boxes (--accel
// objects, lib/object_boxes.glsl) against the binary BVH walk on the GPU: the same closest hits
// (primitive, instance and distance; the primitive may differ only where two tie) and the same
// any-hit answers, on random soups of several meshes, a two-level scene, the bunny and a WAD map.
// (cornell_test.cpp renders the Cornell box through every walk.)
#include <filesystem>
#include <random>

#include "../unit/instanced_world.h"
#include "../unit/io/io_test_util.h"
#include "bvh/traverse_cpu.h"
#include "box_rays.h"
#include "gpu_fixture.h"
#include "ray_query.h"
#include "scene/io/load.h"

namespace penumbra::test {
namespace {

// Triangles around `meshes` random centres, one mesh each, so that objects get several boxes.
Scene soupOfMeshes(std::size_t triangles, std::size_t meshes, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    Scene scene;
    scene.name = "soup";
    scene.materials.push_back({"grey", Vec3{0.5f}, Vec3{0}});
    for (std::size_t m = 0; m < meshes; ++m) {
        Mesh mesh;
        mesh.name = "soup " + std::to_string(m);
        const Vec3 centre{u(rng) * 3, u(rng) * 3, u(rng) * 3};
        for (std::size_t i = 0; i < triangles / meshes; ++i) {
            const Vec3 c = centre + Vec3{u(rng), u(rng), u(rng)};
            for (Vec3 p : {c, c + Vec3{u(rng), u(rng), u(rng)} * 0.4f, c + Vec3{u(rng), u(rng), u(rng)} * 0.4f}) {
                mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
                mesh.positions.push_back(p);
            }
        }
        scene.meshes.push_back(mesh);
    }
    return scene;
}

// Whether primitive `slot` (a plain triangle) is hit at about distance t: where two tie, walks
// may keep either.
bool tiesAt(const SceneArrays& arrays, std::uint32_t slot, const shader::RayDesc& r, float t) {
    const shader::TriVerts& p = arrays.triVerts.at(slot);
    if (p.flags & (PN_TRI_SPHERE | PN_TRI_SPRITE | PN_TRI_ALPHA_TESTED)) return true;  // the CPU does not test these as the GPU does
    float tt, u, v;
    return bvh::intersectTriangle(p, Ray{r.origin, r.direction, r.tMax}, r.tMax, tt, u, v) &&
           std::abs(tt - t) <= 1e-5f * std::max(1.0f, t);
}

// Each of `walks` against the binary walk on the same kernel and rays; returns the rays that hit.
std::size_t expectWalksAgreeWithTheBvh(const gpu::Context& ctx, const SceneArrays& arrays,
                                       const std::vector<shader::RayDesc>& rays, std::initializer_list<Accel> walks) {
    const GpuHits bvh = traceOnGpu(ctx, arrays, rays, Accel::Bvh);
    std::size_t hits = 0;
    for (const shader::HitRecord& h : bvh.closest) hits += h.triangle != PN_NO_HIT;
    for (Accel accel : walks) {
        SCOPED_TRACE(accelName(accel));
        const GpuHits other = traceOnGpu(ctx, arrays, rays, accel);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const shader::HitRecord& b = bvh.closest[i];
            const shader::HitRecord& o = other.closest[i];
            EXPECT_EQ(o.triangle != PN_NO_HIT, b.triangle != PN_NO_HIT) << "ray " << i;
            EXPECT_EQ(other.occluded[i], bvh.occluded[i]) << "any-hit, ray " << i;
            if (::testing::Test::HasFailure()) return hits;
            if (b.triangle == PN_NO_HIT) continue;
            const float tol = 1e-5f * std::max(1.0f, b.t);
            EXPECT_NEAR(o.t, b.t, tol) << "ray " << i;
            if (o.triangle != b.triangle)
                EXPECT_TRUE(tiesAt(arrays, o.triangle, rays[i], b.t))
                    << "ray " << i << ": primitive " << o.triangle << ", the BVH's " << b.triangle;
            else
                EXPECT_EQ(o.t, b.t) << "the same primitive at another distance, ray " << i;
        }
    }
    return hits;
}

TEST_F(GpuTest, StacklessAndObjectsAgreeWithTheBvhOnSoupsOfMeshes) {
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        SCOPED_TRACE(seed);
        const Scene scene = soupOfMeshes(seed == 1 ? 6 : 1500 * seed, seed == 1 ? 2 : 7, seed);
        const SceneArrays arrays = buildSceneArrays(scene);
        const auto rays = boxRays(scene.bounds(), 1500, seed + 10);
        const std::size_t hits = expectWalksAgreeWithTheBvh(*ctx, arrays, rays, {Accel::Stackless, Accel::Objects});
        if (seed > 1) {
            EXPECT_GT(hits, rays.size() / 10) << "too few rays hit for the test to mean much";
        }
    }
}

// The objects' boxes: one per mesh of a flat scene, each holding exactly its mesh's primitives.
TEST_F(GpuTest, ObjectsGetOneBoxPerMeshHoldingItsPrimitives) {
    const Scene scene = soupOfMeshes(700, 7, 4);
    SceneArrays arrays = buildSceneArrays(scene, {}, Accel::Objects);
    ASSERT_EQ(arrays.objectBoxes.size(), 7u);
    ASSERT_EQ(arrays.objectPrims.size(), arrays.triVerts.size());
    for (const shader::ObjectBox& box : arrays.objectBoxes) {
        EXPECT_EQ(box.count, 100u);
        EXPECT_EQ(box.instance, PN_NO_HIT);
        EXPECT_EQ(box.listed, 1u);
        for (std::uint32_t e = box.first; e < box.first + box.count; ++e) {
            const shader::TriVerts& t = arrays.triVerts[arrays.objectPrims[e]];
            for (Vec3 p : {t.v0, t.v0 + t.e1, t.v0 + t.e2})
                for (int a = 0; a < 3; ++a) {
                    EXPECT_GE(p[a], box.boundsMin[a]);
                    EXPECT_LE(p[a], box.boundsMax[a]);
                }
        }
    }
    EXPECT_EQ(arrays.walk, PN_ACCEL_OBJECTS);
}

// Two levels: the stackless walk enters instances from the top level and resumes it; objects
// split the world's identity instance by object and give each moved instance one box.
TEST_F(GpuTest, StacklessAndObjectsAgreeWithTheBvhOverInstances) {
    const Scene scene = instancedRoom();
    const SceneArrays arrays = buildSceneArrays(scene);
    ASSERT_FALSE(arrays.instances.empty());
    SceneArrays withBoxes = arrays;
    buildWalkRecords(withBoxes, Accel::Objects);
    std::size_t moved = 0, worldBoxes = 0;
    for (const shader::ObjectBox& b : withBoxes.objectBoxes) {
        moved += b.listed == 0;
        worldBoxes += b.listed != 0 && b.instance == 0;
    }
    EXPECT_EQ(moved + 1, arrays.instances.size()) << "one box per moved instance";
    EXPECT_GT(worldBoxes, 1u) << "the world's meshes get a box each";
    const auto rays = boxRays(scene.bounds(), 2000, 31);
    const GpuHits bvh = traceOnGpu(*ctx, arrays, rays, Accel::Bvh);
    const std::size_t hits = expectWalksAgreeWithTheBvh(*ctx, arrays, rays, {Accel::Stackless, Accel::Objects});
    EXPECT_GT(hits, rays.size() / 4);
    std::size_t inInstances = 0;
    for (const shader::HitRecord& h : bvh.closest) inInstances += h.triangle != PN_NO_HIT;
    EXPECT_GT(inInstances, 0u);
}

TEST_F(GpuTest, StacklessAndObjectsAgreeWithTheBvhOnAWadMap) {
    const std::filesystem::path wad = "/usr/share/games/doom/freedoom1.wad";
    PENUMBRA_REQUIRE_ASSET(wad);
    LoadOptions options;
    options.map = "E1M1";
    const Scene scene = loadSceneFile(wad, options);
    ASSERT_FALSE(scene.sprites.empty()) << "the map should bring its things as sprites";
    const SceneArrays arrays = buildSceneArrays(scene);
    const auto rays = boxRays(scene.bounds(), 1500, 41);
    const std::size_t hits = expectWalksAgreeWithTheBvh(*ctx, arrays, rays, {Accel::Stackless, Accel::Objects});
    EXPECT_GT(hits, rays.size() / 3) << "too few rays hit the map for the test to mean much";
}

// The stackless walk only: the bunny is one mesh, so objects is brute force over 69,666
// triangles, which lavapipe gets wrong from 32,768 primitives per ray up, as it does brute force
// (docs/RELIABILITY.md; soups of 32,000 triangles in 2 or 8 meshes agree, of 70,000 in 1 or 4 do not).
TEST_F(GpuTest, StacklessAgreesWithTheBvhOnTheBunny) {
    const std::filesystem::path bunny = "/usr/share/glmark2/models/bunny.obj";
    PENUMBRA_REQUIRE_ASSET(bunny);
    const Scene scene = loadSceneFile(bunny, LoadOptions{});
    const SceneArrays arrays = buildSceneArrays(scene);
    const auto rays = boxRays(scene.bounds(), 1000, 51);
    const std::size_t hits = expectWalksAgreeWithTheBvh(*ctx, arrays, rays, {Accel::Stackless});
    EXPECT_GT(hits, rays.size() / 4) << "too few rays hit the bunny for the test to mean much";
}

}  // namespace
}  // namespace penumbra::test
