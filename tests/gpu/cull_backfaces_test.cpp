// --cull-backfaces (PN_OPTION_CULL_BACKFACES): the GPU walks (binary BVH, 8-wide BVH, brute
// force) against a CPU brute-force reference that culls by the same rule, on random soups: a
// closest-hit ray skips a triangle whose geometric normal e1 x e2 faces away from it, unless its
// material transmits (glass keeps its back faces); any-hit rays (shadows) cull nothing.
#include <random>

#include "bvh/traverse_cpu.h"
#include "gpu_fixture.h"
#include "ray_query.h"

namespace penumbra::test {
namespace {

// Random triangles, every third one of glass.
Scene soupWithGlass(std::uint32_t seed, std::size_t count) {
    Scene scene;
    scene.name = "soup";
    scene.materials.push_back({"grey", Vec3{0.5f}, Vec3{0}});
    Material glass{"glass", Vec3{1.0f}, Vec3{0}};
    glass.transmission = 1.0f;
    scene.materials.push_back(glass);
    Mesh grey, clear;
    grey.name = "grey";
    clear.name = "glass";
    clear.material = 1;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (std::size_t i = 0; i < count; ++i) {
        Mesh& m = i % 3 == 2 ? clear : grey;
        const Vec3 c{u(rng) * 4, u(rng) * 4, u(rng) * 4};
        for (Vec3 p : {c, c + Vec3{u(rng), u(rng), u(rng)} * 0.6f, c + Vec3{u(rng), u(rng), u(rng)} * 0.6f}) {
            m.indices.push_back(static_cast<std::uint32_t>(m.positions.size()));
            m.positions.push_back(p);
        }
    }
    scene.meshes = {grey, clear};
    return scene;
}

std::vector<shader::RayDesc> randomRays(std::uint32_t seed, std::size_t count) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<shader::RayDesc> rays;
    for (std::size_t i = 0; i < count; ++i) {
        shader::RayDesc r{};
        r.origin = Vec3{u(rng), u(rng), u(rng)} * (i % 2 ? 6.0f : 3.0f);  // outside and inside the soup
        const Vec3 d{u(rng), u(rng), u(rng)};
        r.direction = length(d) > 1e-3f ? normalize(d) : Vec3{0, 1, 0};
        r.tMax = i % 5 == 0 ? 4.0f : 1e30f;
        rays.push_back(r);
    }
    return rays;
}

// The reference: every triangle tested, back faces of non-glass triangles skipped.
bvh::Hit culledBrute(const SceneArrays& arrays, const Ray& ray) {
    bvh::Hit best;
    best.t = ray.tMax;
    for (std::uint32_t i = 0; i < arrays.triVerts.size(); ++i) {
        const shader::TriVerts& tri = arrays.triVerts[i];
        const bool glass = arrays.materials[arrays.triAttribs[i].materialId].transmission > 0;
        const float det = -dot(ray.direction, cross(tri.e1, tri.e2));  // intersectTriangle's determinant
        if (!glass && det < 0) continue;
        float t, u, v;
        if (bvh::intersectTriangle(tri, ray, best.t, t, u, v)) best = bvh::Hit{t, i, u, v};
    }
    return best;
}

TEST_F(GpuTest, CulledWalksAgreeWithACpuBruteForceThatCullsTheSameFaces) {
    for (std::uint32_t seed : {1u, 2u}) {
        const Scene scene = soupWithGlass(seed, seed == 1 ? 300 : 3000);
        const SceneArrays arrays = buildSceneArrays(scene, {}, Accel::Wide);  // both trees, one order
        ASSERT_FALSE(arrays.wideNodes.empty());
        // The flag follows the material, for every triangle.
        for (std::size_t i = 0; i < arrays.triVerts.size(); ++i)
            ASSERT_EQ((arrays.triVerts[i].flags & PN_TRI_KEEP_BACK) != 0,
                      arrays.materials[arrays.triAttribs[i].materialId].transmission > 0);
        const auto rays = randomRays(seed + 10, 3000);
        const KernelSpec cull = KernelSpec{}.withOption(PN_OPTION_CULL_BACKFACES, true);
        std::size_t culledAway = 0, glassBacks = 0, hits = 0;
        for (Accel accel : {Accel::Bvh, Accel::Wide, Accel::Brute}) {
            const GpuHits gpu = traceOnGpu(*ctx, arrays, rays, accel, cull);
            for (std::size_t i = 0; i < rays.size(); ++i) {
                const Ray ray{rays[i].origin, rays[i].direction, rays[i].tMax};
                const bvh::Hit ref = culledBrute(arrays, ray);
                const bvh::Hit all = bvh::closestHitBrute(arrays.triVerts, ray);
                const shader::HitRecord& g = gpu.closest[i];
                ASSERT_EQ(g.triangle == PN_NO_HIT, ref.triangle == PN_NO_HIT) << accelName(accel) << " ray " << i;
                // Shadow rays cull nothing: occluded exactly when the unculled walk hits something.
                EXPECT_EQ(gpu.occluded[i], all.triangle != PN_NO_HIT) << accelName(accel) << " ray " << i;
                if (accel == Accel::Bvh) {
                    culledAway += ref.triangle != all.triangle;
                    glassBacks += ref.triangle != PN_NO_HIT &&
                                  -dot(ray.direction, cross(arrays.triVerts[ref.triangle].e1, arrays.triVerts[ref.triangle].e2)) < 0;
                }
                if (ref.triangle == PN_NO_HIT) continue;
                hits += accel == Accel::Bvh;
                EXPECT_EQ(g.triangle, ref.triangle) << accelName(accel) << " ray " << i;
                EXPECT_NEAR(g.t, ref.t, 1e-5f * std::max(1.0f, ref.t)) << accelName(accel) << " ray " << i;
            }
        }
        // The test has teeth: culling changed many closest hits, glass was hit from behind, and
        // the unculled kernel still sees what culling hides.
        EXPECT_GT(culledAway, rays.size() / 50) << "seed " << seed;
        EXPECT_GT(glassBacks, 10u) << "seed " << seed;
        EXPECT_GT(hits, rays.size() / 20) << "seed " << seed;
        const GpuHits plain = traceOnGpu(*ctx, arrays, rays, Accel::Bvh);
        std::size_t same = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const Ray ray{rays[i].origin, rays[i].direction, rays[i].tMax};
            same += plain.closest[i].triangle == bvh::closestHitBrute(arrays.triVerts, ray).triangle;
        }
        EXPECT_EQ(same, rays.size()) << "without the feature nothing is culled";
    }
}

}  // namespace
}  // namespace penumbra::test
