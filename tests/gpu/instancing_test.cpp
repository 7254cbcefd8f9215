// Two-level traversal on the real shaders: GPU hits against the CPU reference over instances
// (BVH and brute force), and an instanced world renders as the same world with every instance
// baked into world meshes (mirrored and squashed placements included, so normals must go
// through the inverse transpose and keep their side).
#include <random>

#include "../unit/instanced_world.h"
#include "bvh/two_level.h"
#include "gpu_fixture.h"
#include "ray_query.h"
#include "render_compare.h"
#include "render_helpers.h"

namespace penumbra::test {
namespace {

std::vector<shader::RayDesc> roomRays(std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> x(-2.5f, 2.5f), y(-0.2f, 2.6f), u(0.0f, 1.0f);
    std::vector<shader::RayDesc> rays;
    for (std::size_t i = 0; i < count; ++i) {
        shader::RayDesc r{};
        r.origin = {x(rng), y(rng), x(rng) + 1.0f};
        const Vec3 to{x(rng) * 0.6f, y(rng) * 0.6f, x(rng) * 0.6f};
        r.direction = normalize(to - r.origin);
        r.tMax = i % 5 == 0 ? 4.0f * u(rng) : 1e30f;
        rays.push_back(r);
    }
    return rays;
}

// GPU hits on `scene` against the CPU's brute force, through the BVH and through brute force.
void expectGpuHitsMatchTheCpu(const gpu::Context& ctx, const Scene& scene) {
    const SceneArrays arrays = buildSceneArrays(scene);
    ASSERT_FALSE(arrays.instances.empty());
    const bvh::TwoLevelView view{arrays.nodes, arrays.triVerts, arrays.instances, arrays.topRoot};
    const auto rays = roomRays(2000, 5);
    for (Accel accel : {Accel::Bvh, Accel::Brute}) {
        const GpuHits gpu = traceOnGpu(ctx, arrays, rays, accel);
        std::size_t hits = 0, mismatches = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const Ray ray{rays[i].origin, rays[i].direction, rays[i].tMax};
            const bvh::Hit ref = bvh::closestHitBrute(view, ray);
            const auto& g = gpu.closest[i];
            EXPECT_EQ(gpu.occluded[i], g.triangle != PN_NO_HIT) << "any-hit disagrees with closest hit, ray " << i;
            // The ray's transform into an instance may round differently on the GPU (fused
            // multiply-adds): a ray grazing an edge may then miss or hit.
            if ((g.triangle == PN_NO_HIT) != (ref.triangle == PN_NO_HIT)) {
                ++mismatches;
                continue;
            }
            if (ref.triangle == PN_NO_HIT) continue;
            ++hits;
            if (std::abs(g.t - ref.t) > 1e-4f * std::max(1.0f, ref.t)) ++mismatches;
        }
        EXPECT_GT(hits, rays.size() / 4);
        EXPECT_LE(mismatches, rays.size() / 200) << (accel == Accel::Bvh ? "bvh" : "brute");
    }
}

TEST_F(GpuTest, TwoLevelTraversalMatchesTheCpuReference) { expectGpuHitsMatchTheCpu(*ctx, instancedRoom()); }

// Identity instances (the world's own geometry, and here one more sphere placed by the identity)
// are walked with the world ray, untransformed (PN_INSTANCE_IDENTITY); their hits are the same.
TEST_F(GpuTest, IdentityInstancesAreWalkedUntransformedWithTheSameHits) {
    Scene scene = instancedRoom();
    scene.instances.push_back({0, Affine::scaling(Vec3{0.3f})});
    scene.instances.push_back({0, Affine{}});
    const SceneArrays arrays = buildSceneArrays(scene);
    std::size_t identities = 0;
    for (const shader::Instance& i : arrays.instances) identities += (i.rootNode & PN_INSTANCE_IDENTITY) != 0;
    EXPECT_EQ(identities, 2u);  // the world's geometry and the last sphere
    expectGpuHitsMatchTheCpu(*ctx, scene);
}

TEST_F(GpuTest, InstancedMeshesRenderAsDuplicatedOnes) {
    RenderSettings settings = testSettings(24, 24, 64, 4);
    settings.seed = 1;
    const SampledImage expected = renderSamples(*ctx, baked(instancedRoom()), settings);
    settings.seed = 2;
    const SampledImage actual = renderSamples(*ctx, instancedRoom(), settings);
    expectSameImage(expected, actual, "instanced");
}

}  // namespace
}  // namespace penumbra::test
