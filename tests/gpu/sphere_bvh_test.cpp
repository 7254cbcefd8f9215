// Spheres and triangles in one BVH: the GPU traversal (BVH and brute force) and the CPU BVH
// against the CPU brute-force reference, on random rays, many of them starting inside spheres.
#include <random>

#include "bvh/sphere.h"
#include "bvh/traverse_cpu.h"
#include "bvh/traverse_wide_cpu.h"
#include "gpu_fixture.h"
#include "ray_query.h"

namespace penumbra::test {
namespace {

Scene mixedScene(std::uint32_t seed, std::size_t sphereCount, std::size_t triangleCount) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    Scene scene;
    scene.name = "mixed";
    scene.materials.push_back({"grey", Vec3{0.5f}, Vec3{0}});
    Mesh mesh;
    mesh.name = "soup";
    for (std::size_t i = 0; i < triangleCount; ++i) {
        Vec3 c{u(rng) * 4, u(rng) * 4, u(rng) * 4};
        for (int k = 0; k < 3; ++k) {
            mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
            mesh.positions.push_back(k == 0 ? c : c + Vec3{u(rng), u(rng), u(rng)} * 0.6f);
        }
    }
    if (!mesh.positions.empty()) scene.meshes.push_back(mesh);
    for (std::size_t i = 0; i < sphereCount; ++i) {
        // Radii over three orders of magnitude; some spheres overlap, some hold others.
        float radius = 0.01f * std::pow(100.0f, 0.5f * (u(rng) + 1.0f));
        scene.spheres.push_back({Vec3{u(rng) * 4, u(rng) * 4, u(rng) * 4}, radius, 0});
    }
    return scene;
}

// A third of the rays start inside a sphere, a third anywhere in (or around) the scene's box
// toward a random point, a third toward a sphere's centre; every seventh is axis-parallel and
// every fifth has a short tMax.
std::vector<shader::RayDesc> mixedRays(const Scene& scene, std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    Aabb box = scene.bounds();
    Vec3 e = box.extent();
    auto inBox = [&](float margin) {
        return Vec3{box.lo.x - margin * e.x + (1 + 2 * margin) * e.x * u(rng),
                    box.lo.y - margin * e.y + (1 + 2 * margin) * e.y * u(rng),
                    box.lo.z - margin * e.z + (1 + 2 * margin) * e.z * u(rng)};
    };
    auto unit = [&] {
        for (;;) {
            Vec3 v{2 * u(rng) - 1, 2 * u(rng) - 1, 2 * u(rng) - 1};
            if (dot(v, v) > 1e-4f && dot(v, v) <= 1) return normalize(v);
        }
    };
    std::vector<shader::RayDesc> rays;
    for (std::size_t i = 0; i < count; ++i) {
        shader::RayDesc r{};
        const Sphere& s = scene.spheres[std::size_t(u(rng) * float(scene.spheres.size())) % scene.spheres.size()];
        Vec3 d;
        switch (i % 3) {
            case 0:  // inside a sphere, anywhere up to 0.99 of its radius
                r.origin = s.center + unit() * (s.radius * 0.99f * std::cbrt(u(rng)));
                d = unit();
                break;
            case 1:
                r.origin = inBox(0.5f);
                d = inBox(0.0f) - r.origin;
                break;
            default:
                r.origin = inBox(0.5f);
                d = s.center - r.origin;
                break;
        }
        if (i % 7 == 0) d = Vec3{0, 0, 0}, d[int(i / 7 % 3)] = (i % 2 ? 1.0f : -1.0f);
        r.direction = length(d) > 0 ? normalize(d) : Vec3{0, 1, 0};
        r.tMax = (i % 5 == 0) ? 0.5f * length(e) * u(rng) : 1e30f;
        rays.push_back(r);
    }
    return rays;
}

void expectAgreement(const gpu::Context& ctx, const Scene& scene, std::size_t rayCount, std::uint32_t seed) {
    SceneArrays arrays = buildSceneArrays(scene, {}, Accel::Wide);  // both trees, one primitive order
    ASSERT_EQ(arrays.triVerts.size(), scene.triangleCount() + scene.spheres.size());
    auto rays = mixedRays(scene, rayCount, seed);
    GpuHits bvh = traceOnGpu(ctx, arrays, rays, Accel::Bvh);
    GpuHits brute = traceOnGpu(ctx, arrays, rays, Accel::Brute);
    GpuHits wide = traceOnGpu(ctx, arrays, rays, Accel::Wide);
    int hits = 0, sphereHits = 0, insideExits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        Ray ray{rays[i].origin, rays[i].direction, rays[i].tMax};
        bvh::Hit ref = bvh::closestHitBrute(arrays.triVerts, ray);
        bvh::Hit cpu = bvh::closestHit(arrays.nodes, arrays.triVerts, ray);
        const bool refHit = ref.triangle != PN_NO_HIT;
        ASSERT_EQ(cpu.triangle != PN_NO_HIT, refHit) << "CPU BVH, ray " << i;
        ASSERT_EQ(bvh.closest[i].triangle != PN_NO_HIT, refHit) << "GPU BVH, ray " << i;
        ASSERT_EQ(brute.closest[i].triangle != PN_NO_HIT, refHit) << "GPU brute force, ray " << i;
        ASSERT_EQ(wide.closest[i].triangle != PN_NO_HIT, refHit) << "GPU wide, ray " << i;
        const bvh::Hit cpuWide = bvh::closestHitWide(arrays.wideNodes, arrays.triVerts, ray);
        ASSERT_EQ(cpuWide.triangle != PN_NO_HIT, refHit) << "CPU wide, ray " << i;
        EXPECT_EQ(wide.occluded[i], refHit) << "GPU wide any-hit, ray " << i;
        EXPECT_EQ(bvh::anyHit(arrays.nodes, arrays.triVerts, ray), refHit) << "CPU any-hit, ray " << i;
        EXPECT_EQ(bvh.occluded[i], refHit) << "GPU any-hit, ray " << i;
        EXPECT_EQ(brute.occluded[i], refHit) << "GPU brute any-hit, ray " << i;
        if (!refHit) continue;
        ++hits;
        if (bvh::isSphere(arrays.triVerts[ref.triangle])) {
            ++sphereHits;
            if (i % 3 == 0) ++insideExits;
        }
        // GPU division and square root may round differently from the CPU's in the last bit.
        const float tol = 1e-5f * std::max(1.0f, ref.t);
        EXPECT_EQ(cpu.t, ref.t) << "ray " << i;
        EXPECT_EQ(cpuWide.t, ref.t) << "CPU wide, ray " << i;
        for (const shader::HitRecord* g : {&bvh.closest[i], &brute.closest[i], &wide.closest[i]}) {
            EXPECT_NEAR(g->t, ref.t, tol) << "ray " << i;
            if (g->triangle != ref.triangle) {  // only where two primitives tie at this distance
                float t, u, v;
                EXPECT_TRUE(bvh::intersectPrimitive(arrays.triVerts[g->triangle], ray, ray.tMax, t, u, v) &&
                            std::abs(t - ref.t) <= tol)
                    << "ray " << i << ": GPU primitive " << g->triangle << ", CPU " << ref.triangle;
            }
        }
    }
    EXPECT_GT(hits, int(rayCount / 3));
    EXPECT_GT(sphereHits, int(rayCount / 4)) << "too few sphere hits for the test to mean much";
    EXPECT_GT(insideExits, int(rayCount / 10));
}

TEST_F(GpuTest, SpheresAndTrianglesInOneBvhMatchBruteForce) {
    expectAgreement(*ctx, mixedScene(1, 1, 0), 1500, 11);       // one sphere: a single leaf
    expectAgreement(*ctx, mixedScene(2, 300, 0), 3000, 12);     // spheres only
    expectAgreement(*ctx, mixedScene(3, 400, 1500), 4000, 13);  // mixed
}

}  // namespace
}  // namespace penumbra::test
