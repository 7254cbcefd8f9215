// GPU traversal (the real bvh.glsl) against the CPU brute-force reference on the same rays.
#include <random>

#include "bvh/traverse_cpu.h"
#include "bvh/traverse_wide_cpu.h"
#include "gpu_fixture.h"
#include "ray_query.h"

namespace penumbra::test {
namespace {

Scene soupScene(const std::vector<std::array<Vec3, 3>>& tris) {
    Scene scene;
    scene.name = "soup";
    scene.materials.push_back({"grey", Vec3{0.5f}, Vec3{0}});
    Mesh mesh;
    mesh.name = "soup";
    for (const auto& t : tris) {
        for (Vec3 p : t) {
            mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
            mesh.positions.push_back(p);
        }
    }
    scene.meshes.push_back(mesh);
    return scene;
}

// Rays from inside and outside the soup's box, toward random points and along the axes.
std::vector<shader::RayDesc> makeRays(std::mt19937& rng, std::size_t count, Vec3 lo, Vec3 hi) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    auto inBox = [&](float margin) {
        Vec3 e = hi - lo;
        return Vec3{lo.x - margin * e.x + (1 + 2 * margin) * e.x * u(rng), lo.y - margin * e.y + (1 + 2 * margin) * e.y * u(rng),
                    lo.z - margin * e.z + (1 + 2 * margin) * e.z * u(rng)};
    };
    std::vector<shader::RayDesc> rays;
    for (std::size_t i = 0; i < count; ++i) {
        shader::RayDesc r{};
        r.origin = inBox(i % 2 ? 0.5f : 0.0f);  // half start inside the scene's box
        Vec3 d = inBox(0.0f) - r.origin;
        if (i % 7 == 0) d = Vec3{0, 0, 0}, d[int(i / 7 % 3)] = (i % 2 ? 1.0f : -1.0f);  // axis-parallel
        r.direction = length(d) > 0 ? normalize(d) : Vec3{0, 1, 0};
        r.tMax = (i % 5 == 0) ? 0.5f * length(hi - lo) * u(rng) : 1e30f;
        rays.push_back(r);
    }
    return rays;
}

void expectAgreement(const gpu::Context& ctx, const Scene& scene, std::size_t rayCount, std::uint32_t seed) {
    SceneArrays arrays = buildSceneArrays(scene, {}, Accel::Wide);  // both trees, one primitive order
    std::mt19937 rng(seed);
    Aabb box = scene.bounds();
    auto rays = makeRays(rng, rayCount, box.lo, box.hi);
    GpuHits bvh = traceOnGpu(ctx, arrays, rays, Accel::Bvh);
    GpuHits brute = traceOnGpu(ctx, arrays, rays, Accel::Brute);
    GpuHits wide = traceOnGpu(ctx, arrays, rays, Accel::Wide);
    ASSERT_FALSE(arrays.wideNodes.empty());
    int hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        Ray ray{rays[i].origin, rays[i].direction, rays[i].tMax};
        bvh::Hit ref = bvh::closestHitBrute(arrays.triVerts, ray);
        const auto& g = bvh.closest[i];
        ASSERT_EQ(g.triangle == PN_NO_HIT, ref.triangle == PN_NO_HIT) << "ray " << i;
        ASSERT_EQ(brute.closest[i].triangle == PN_NO_HIT, ref.triangle == PN_NO_HIT) << "ray " << i;
        ASSERT_EQ(wide.closest[i].triangle == PN_NO_HIT, ref.triangle == PN_NO_HIT) << "wide, ray " << i;
        const bvh::Hit cpuWide = bvh::closestHitWide(arrays.wideNodes, arrays.triVerts, ray);
        ASSERT_EQ(cpuWide.triangle == PN_NO_HIT, ref.triangle == PN_NO_HIT) << "CPU wide, ray " << i;
        EXPECT_EQ(bvh.occluded[i], ref.triangle != PN_NO_HIT) << "any-hit disagrees with closest hit, ray " << i;
        EXPECT_EQ(brute.occluded[i], ref.triangle != PN_NO_HIT) << "ray " << i;
        EXPECT_EQ(wide.occluded[i], ref.triangle != PN_NO_HIT) << "wide, ray " << i;
        if (ref.triangle == PN_NO_HIT) continue;
        ++hits;
        EXPECT_EQ(cpuWide.t, ref.t) << "CPU wide, ray " << i;
        for (const shader::HitRecord* gh : std::initializer_list<const shader::HitRecord*>{&g, &brute.closest[i], &wide.closest[i]}) {
            EXPECT_NEAR(gh->t, ref.t, 1e-5f * std::max(1.0f, ref.t)) << "ray " << i;
            // Same triangle, unless two triangles tie at this distance (coplanar duplicates).
            if (gh->triangle != ref.triangle) {
                float t, u, v;
                EXPECT_TRUE(bvh::intersectTriangle(arrays.triVerts[gh->triangle], ray, ray.tMax, t, u, v) &&
                            std::abs(t - ref.t) <= 1e-5f * std::max(1.0f, ref.t))
                    << "ray " << i << ": GPU triangle " << gh->triangle << ", CPU " << ref.triangle;
            }
        }
    }
    EXPECT_GT(hits, int(rayCount / 10)) << "too few rays hit anything for the test to mean much";
}

TEST_F(GpuTest, BvhMatchesBruteForceOnRandomSoups) {
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> u(-1.0f, 1.0f);
        std::vector<std::array<Vec3, 3>> tris;
        std::size_t n = seed == 1 ? 1 : (seed == 2 ? 300 : 3000);
        for (std::size_t i = 0; i < n; ++i) {
            Vec3 c{u(rng) * 4, u(rng) * 4, u(rng) * 4};
            tris.push_back({c, c + Vec3{u(rng), u(rng), u(rng)} * 0.5f, c + Vec3{u(rng), u(rng), u(rng)} * 0.5f});
        }
        expectAgreement(*ctx, soupScene(tris), 2000, seed);
    }
}

TEST_F(GpuTest, BvhMatchesBruteForceOnDegenerateAndAxisAlignedGeometry) {
    std::vector<std::array<Vec3, 3>> tris;
    // A coplanar grid in z = 0, with duplicates of some cells.
    for (int x = 0; x < 20; ++x)
        for (int y = 0; y < 20; ++y) {
            Vec3 a{float(x), float(y), 0}, b{float(x + 1), float(y), 0}, c{float(x), float(y + 1), 0};
            tris.push_back({a, b, c});
            if ((x + y) % 5 == 0) tris.push_back({a, b, c});
        }
    // Axis-aligned walls, degenerate triangles (zero area, repeated vertices) among them.
    for (int i = 0; i < 10; ++i) {
        float f = float(i) * 2;
        tris.push_back({Vec3{f, 0, 1}, Vec3{f, 20, 1}, Vec3{f, 0, 5}});
        tris.push_back({Vec3{f, 1, 1}, Vec3{f, 1, 1}, Vec3{f, 1, 1}});
        tris.push_back({Vec3{0, f, 2}, Vec3{5, f, 2}, Vec3{10, f, 2}});
    }
    expectAgreement(*ctx, soupScene(tris), 4000, 7);
}

}  // namespace
}  // namespace penumbra::test
