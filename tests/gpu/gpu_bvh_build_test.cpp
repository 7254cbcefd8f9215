// The BVH built on the GPU (--bvh-build gpu, render/gpu_bvh_build.h) against the CPU's binned SAH
// build: its radix sort is a stable sort, its trees pass the structural validator (every box
// holds its children and its primitives, every primitive in one leaf, leaves of at most 4), and
// the real traversal shader finds the same closest hits through either tree on random soups, the
// bunny and a baked WAD map.
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <random>

#include "../unit/io/io_test_util.h"
#include "box_rays.h"
#include "bvh/stats.h"
#include "bvh/triangle.h"
#include "bvh/validate.h"
#include "gpu_fixture.h"
#include "scene/presets/dungeon_textures.h"
#include "ray_query.h"
#include "render/gpu_bvh_build.h"
#include "scene/instances.h"
#include "scene/io/load.h"

namespace penumbra::test {
namespace {

std::vector<std::uint32_t> stableOrder(const std::vector<std::uint32_t>& keys) {
    std::vector<std::uint32_t> order(keys.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
    return order;
}

TEST_F(GpuTest, GpuRadixSortIsAStableSort) {
    const GpuBvhBuilder builder(*ctx);
    std::mt19937 rng(7);
    // Sizes around the 256-key block; keys over all 32 bits, a few values (many ties, as equal
    // Morton codes give), and all equal.
    for (std::size_t n : {1u, 255u, 256u, 257u, 4099u}) {
        for (std::uint32_t range : {0u, 8u, 1u}) {
            SCOPED_TRACE(testing::Message() << n << " keys below " << range);
            std::vector<std::uint32_t> keys(n);
            for (std::uint32_t& k : keys) k = range == 0 ? std::uint32_t(rng()) : std::uint32_t(rng() % range);
            EXPECT_EQ(builder.sortOrder(keys), stableOrder(keys));
        }
    }
}

// Triangles of random size and place; `clustered`: a tenth share one corner, so equal Morton
// codes (and the index tie-break) are exercised.
std::vector<bvh::Triangle> triangleSoup(std::size_t count, std::uint32_t seed, bool clustered, float spread = 4.0f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<bvh::Triangle> tris;
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 c = clustered && i % 10 == 0 ? Vec3{0.5f} : Vec3{u(rng), u(rng), u(rng)} * spread;
        tris.push_back({c, c + Vec3{u(rng), u(rng), u(rng)} * 0.3f, c + Vec3{u(rng), u(rng), u(rng)} * 0.3f});
    }
    return tris;
}

std::vector<Aabb> boundsOf(const std::vector<bvh::Triangle>& tris) {
    std::vector<Aabb> boxes;
    for (const bvh::Triangle& t : tris) boxes.push_back(bvh::bounds(t));
    return boxes;
}

TEST_F(GpuTest, GpuBuiltTreesAreValidWithLeavesOfAtMostFour) {
    const GpuBvhBuilder builder(*ctx);
    for (std::size_t n : {2u, 3u, 5u, 300u, 3000u}) {
        for (bool clustered : {false, true}) {
            SCOPED_TRACE(testing::Message() << n << (clustered ? " clustered" : " spread") << " triangles");
            std::vector<Aabb> boxes = boundsOf(triangleSoup(n, std::uint32_t(n), clustered));
            if (n > 100) boxes[7] = Aabb{Vec3{std::nanf("")}, Vec3{1.0f}};  // sanitized to a point
            const GpuBvhBuild built = builder.build(boxes);
            ASSERT_TRUE(built.onGpu);
            EXPECT_NO_THROW(bvh::validate(built.bvh, boxes));
            const bvh::BvhStats gpu = bvh::computeStats(built.bvh, {});
            EXPECT_LE(gpu.maxLeafSize, 4u);
            // Overlapping triangles cost less tested together: the SAH collapse makes bigger leaves.
            if (clustered && n >= 300) {
                EXPECT_GT(gpu.maxLeafSize, 1u);
            }
            if (n >= 300) {
                // The target is 1.25x on the dragon; random soups are harder for Morton order.
                const bvh::BvhStats cpu = bvh::computeStats(bvh::build(boxes), {});
                EXPECT_LT(gpu.sahCost, 1.6 * cpu.sahCost) << "CPU SAH cost " << cpu.sahCost;
            }
        }
    }
}

// The validator must notice a box that does not hold its primitives (so the test above can fail).
TEST_F(GpuTest, TheValidatorRejectsAShrunkGpuBox) {
    const GpuBvhBuilder builder(*ctx);
    const std::vector<Aabb> boxes = boundsOf(triangleSoup(200, 3, false));
    GpuBvhBuild built = builder.build(boxes);
    auto leaf = std::find_if(built.bvh.nodes.begin(), built.bvh.nodes.end(),
                             [](const shader::BvhNode& n) { return n.triCount > 0; });
    ASSERT_NE(leaf, built.bvh.nodes.end());
    leaf->boundsMax = leaf->boundsMin;
    EXPECT_THROW(bvh::validate(built.bvh, boxes), Error);
}

// Whether the two hits are the same primitive (same vertices: the trees number slots
// differently) or two primitives at the same distance, which either walk may keep.
bool sameHit(const SceneArrays& a, const shader::HitRecord& x, const SceneArrays& b, const shader::HitRecord& y) {
    if ((x.triangle == PN_NO_HIT) != (y.triangle == PN_NO_HIT)) return false;
    if (x.triangle == PN_NO_HIT) return true;
    if (std::abs(x.t - y.t) > 1e-5f * std::max(1.0f, x.t)) return false;
    const shader::TriVerts &p = a.triVerts.at(x.triangle), &q = b.triVerts.at(y.triangle);
    return std::memcmp(&p, &q, sizeof(p)) == 0 ? x.t == y.t : true;
}

// Builds `scene` both ways and traces `rays` through each with the real shader; returns the hits.
std::size_t expectSameHits(const gpu::Context& ctx, const Scene& scene, std::size_t rayCount, std::uint32_t seed) {
    const GpuBvhBuilder builder(ctx);
    const SceneArrays cpu = buildSceneArrays(scene);
    const SceneArrays gpu = buildSceneArrays(scene, {}, Accel::Bvh, &builder);
    EXPECT_TRUE(gpu.bvhBuiltOnGpu);
    EXPECT_EQ(gpu.triVerts.size(), cpu.triVerts.size());
    const auto rays = boxRays(scene.bounds(), rayCount, seed);
    const GpuHits a = traceOnGpu(ctx, cpu, rays, Accel::Bvh), b = traceOnGpu(ctx, gpu, rays, Accel::Bvh);
    std::size_t hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        hits += a.closest[i].triangle != PN_NO_HIT;
        EXPECT_TRUE(sameHit(cpu, a.closest[i], gpu, b.closest[i]))
            << "ray " << i << ": CPU tree t " << a.closest[i].t << " slot " << a.closest[i].triangle << ", GPU tree t "
            << b.closest[i].t << " slot " << b.closest[i].triangle;
        EXPECT_EQ(a.occluded[i], b.occluded[i]) << "any-hit, ray " << i;
        if (::testing::Test::HasFailure()) break;
    }
    return hits;
}

Scene soupScene(std::size_t count, std::uint32_t seed) {
    Scene scene;
    scene.name = "soup";
    scene.materials.push_back({"grey", Vec3{0.5f}, Vec3{0}});
    Mesh mesh;
    mesh.name = "soup";
    for (const bvh::Triangle& t : triangleSoup(count, seed, true, 1.0f))
        for (Vec3 p : {t.v0, t.v1, t.v2}) {
            mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
            mesh.positions.push_back(p);
        }
    scene.meshes.push_back(mesh);
    return scene;
}

TEST_F(GpuTest, GpuAndCpuBuiltTreesGiveTheSameHitsOnSoups) {
    for (std::uint32_t seed : {1u, 2u}) {
        SCOPED_TRACE(seed);
        const std::size_t hits = expectSameHits(*ctx, soupScene(seed == 1 ? 40 : 4000, seed), 1500, seed + 20);
        EXPECT_GT(hits, seed == 1 ? 20u : 500u) << "too few rays hit for the test to mean much";
    }
}

TEST_F(GpuTest, GpuAndCpuBuiltTreesGiveTheSameHitsOnTheBunny) {
    const std::filesystem::path bunny = "/usr/share/glmark2/models/bunny.obj";
    PENUMBRA_REQUIRE_ASSET(bunny);
    const Scene scene = loadSceneFile(bunny, LoadOptions{});
    EXPECT_GT(expectSameHits(*ctx, scene, 1000, 61), 250u);
}

// E1M1 baked (its moving sectors' instances into the world), so the whole map is one GPU-built
// tree, sprites included.
TEST_F(GpuTest, GpuAndCpuBuiltTreesGiveTheSameHitsOnABakedWadMap) {
    const std::filesystem::path wad = freedoomWadPath();
    PENUMBRA_REQUIRE_ASSET(wad);
    LoadOptions options;
    options.map = "E1M1";
    Scene scene = loadSceneFile(wad, options);
    bakeAllInstances(scene);
    ASSERT_TRUE(scene.instances.empty());
    EXPECT_GT(expectSameHits(*ctx, scene, 1500, 71), 500u);
}

}  // namespace
}  // namespace penumbra::test
