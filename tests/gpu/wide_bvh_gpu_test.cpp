// The wide BVH walk on the GPU (lib/wide_bvh.glsl) against the binary walk and brute force, on
// the Stanford bunny and on what only the shaders intersect: a WAD map (sprites, alpha-tested
// walls) and stacked alpha-tested quads whose holes let rays through to the layers behind. (Soups and spheres, with the CPU
// reference walks, are in bvh_gpu_test.cpp and sphere_bvh_test.cpp.)
#include <filesystem>
#include <random>

#include "../unit/io/io_test_util.h"
#include "gpu_fixture.h"
#include "box_rays.h"
#include "ray_query.h"
#include "scene/instances.h"
#include "scene/io/load.h"
#include "scene/presets/mesh_builder.h"

namespace penumbra::test {
namespace {

struct Agreement {
    std::size_t hits = 0;
    std::vector<float> t;  // the binary walk's closest t per ray (tMax on a miss)
};

// Wide, binary and brute force on the GPU: the same rays hit, at the same distance (the primitive
// may differ only where two tie), and any-hit agrees. Returns what the binary walk found.
// withBrute false compares the two walks alone (see the bunny's test).
Agreement expectGpuWalksAgree(const gpu::Context& ctx, const SceneArrays& arrays,
                              const std::vector<shader::RayDesc>& rays, bool withBrute = true) {
    EXPECT_FALSE(arrays.wideNodes.empty());
    const GpuHits bvh = traceOnGpu(ctx, arrays, rays, Accel::Bvh);
    const GpuHits wide = traceOnGpu(ctx, arrays, rays, Accel::Wide);
    const GpuHits brute = withBrute ? traceOnGpu(ctx, arrays, rays, Accel::Brute) : bvh;
    Agreement out;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const shader::HitRecord& b = bvh.closest[i];
        const bool hit = b.triangle != PN_NO_HIT;
        out.t.push_back(hit ? b.t : rays[i].tMax);
        EXPECT_EQ(wide.closest[i].triangle != PN_NO_HIT, hit) << "wide, ray " << i;
        EXPECT_EQ(brute.closest[i].triangle != PN_NO_HIT, hit) << "brute force, ray " << i;
        EXPECT_EQ(wide.occluded[i], bvh.occluded[i]) << "wide any-hit, ray " << i;
        EXPECT_EQ(brute.occluded[i], bvh.occluded[i]) << "brute any-hit, ray " << i;
        if (::testing::Test::HasFailure()) return out;
        if (!hit) continue;
        ++out.hits;
        const float tol = 1e-5f * std::max(1.0f, b.t);
        EXPECT_NEAR(wide.closest[i].t, b.t, tol) << "wide, ray " << i;
        EXPECT_NEAR(brute.closest[i].t, b.t, tol) << "brute force, ray " << i;
        if (wide.closest[i].t == b.t && wide.closest[i].triangle == b.triangle) {
            EXPECT_EQ(wide.closest[i].u, b.u) << "ray " << i;
            EXPECT_EQ(wide.closest[i].v, b.v) << "ray " << i;
        }
    }
    return out;
}

TEST_F(GpuTest, WideBvhMatchesBinaryAndBruteForceOnAWadMap) {
    const std::filesystem::path wad = "/usr/share/games/doom/freedoom1.wad";
    PENUMBRA_REQUIRE_ASSET(wad);
    LoadOptions options;
    options.map = "E1M1";
    Scene scene = loadSceneFile(wad, options);
    ASSERT_FALSE(scene.sprites.empty()) << "the map should bring its things as sprites";
    // The doors and lifts are instances (they move); the wide tree is a one-level walk, so the
    // map is baked whole into the world, as it stands at the start.
    ASSERT_FALSE(scene.instances.empty());
    bakeAllInstances(scene);
    const SceneArrays arrays = buildSceneArrays(scene, {}, Accel::Wide);
    const std::vector<shader::RayDesc> rays = boxRays(scene.bounds(), 1500, 21);
    const Agreement a = expectGpuWalksAgree(*ctx, arrays, rays);
    EXPECT_GT(a.hits, rays.size() / 3) << "too few rays hit the map for the test to mean much";
}

// The Stanford bunny: 69,666 small triangles of a scanned surface, a tree far deeper than the map's.
// The two walks only: brute force on lavapipe goes wrong from 32,768 primitives up (32,000 agree):
// its any-hit reports occluders for rays both walks and its own closest hit find unoccluded, and
// its closest hit misses some hits. Not understood yet (noted in docs/RELIABILITY.md).
TEST_F(GpuTest, WideBvhMatchesTheBinaryWalkOnTheBunny) {
    const std::filesystem::path bunny = "/usr/share/glmark2/models/bunny.obj";
    PENUMBRA_REQUIRE_ASSET(bunny);
    const Scene scene = loadSceneFile(bunny, LoadOptions{});
    ASSERT_EQ(scene.triangleCount(), 69666u);
    const SceneArrays arrays = buildSceneArrays(scene, {}, Accel::Wide);
    const std::vector<shader::RayDesc> rays = boxRays(scene.bounds(), 1000, 23);
    const Agreement a = expectGpuWalksAgree(*ctx, arrays, rays, false);
    EXPECT_GT(a.hits, rays.size() / 4) << "too few rays hit the bunny for the test to mean much";
}

// Four layers of 4x4 quads at z = 0, -1, -2, -3 under one alpha-tested texture with a
// checkerboard of holes; rays from z = 3 toward random points of the layers.
Scene alphaStack() {
    Scene scene;
    scene.name = "alpha stack";
    Texture tex;
    tex.name = "holes";
    tex.width = 8;
    tex.height = 8;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const std::uint8_t alpha = ((x / 2 + y / 2) % 2) ? 0 : 255;
            tex.rgba.insert(tex.rgba.end(), {200, 150, 100, alpha});
        }
    scene.textures.push_back(tex);
    const std::uint32_t mat = addMaterial(scene, "holes", Vec3{1.0f});
    scene.materials[mat].albedoTexture.texture = 0;
    scene.materials[mat].alphaCutoff = 0.5f;
    Mesh mesh;
    mesh.name = "layers";
    mesh.material = mat;
    for (int layer = 0; layer < 4; ++layer)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
                const float z = -float(layer), x0 = float(x) - 2, y0 = float(y) - 2;
                addQuad(mesh, {x0, y0 + 1, z}, {x0, y0, z}, {x0 + 1, y0, z}, {x0 + 1, y0 + 1, z});
                mesh.uvs.insert(mesh.uvs.end(), {{0, 0}, {0, 1}, {1, 1}, {1, 0}});
            }
    scene.meshes.push_back(mesh);
    return scene;
}

TEST_F(GpuTest, WideBvhMatchesBinaryAndBruteForceThroughAlphaTestedHoles) {
    const Scene scene = alphaStack();
    const SceneArrays arrays = buildSceneArrays(scene, {}, Accel::Wide);
    std::mt19937 rng(31);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    std::vector<shader::RayDesc> rays;
    for (int i = 0; i < 2000; ++i) {
        shader::RayDesc r{};
        r.origin = Vec3{u(rng) * 0.5f, u(rng) * 0.5f, 3.0f};
        r.direction = normalize(Vec3{u(rng), u(rng), -3.0f - 0.75f * (u(rng) + 2.0f)} - r.origin);
        r.tMax = 1e30f;
        rays.push_back(r);
    }
    const Agreement a = expectGpuWalksAgree(*ctx, arrays, rays);
    // The holes must matter: rays stop on the first layer and on the ones behind it.
    std::size_t first = 0, behind = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        if (a.t[i] >= rays[i].tMax) continue;
        const float z = rays[i].origin.z + a.t[i] * rays[i].direction.z;
        (z > -0.5f ? first : behind)++;
    }
    EXPECT_GT(first, rays.size() / 5);
    EXPECT_GT(behind, rays.size() / 5);
}

// The comparisons above would pass if --accel wide silently ran the binary walk: with every
// slot of the wide nodes emptied, the wide walk must find nothing where the binary walk hits.
TEST_F(GpuTest, WideAccelReallyWalksTheWideNodes) {
    SceneArrays arrays = buildSceneArrays(alphaStack(), {}, Accel::Wide);
    for (shader::WideNode& n : arrays.wideNodes) n.meta[0] = n.meta[1] = 0;
    std::vector<shader::RayDesc> rays;
    for (int i = 0; i < 64; ++i) {
        shader::RayDesc r{};
        r.origin = Vec3{-1.9f + 0.06f * float(i), 0.3f, 3.0f};
        r.direction = Vec3{0, 0, -1};
        r.tMax = 1e30f;
        rays.push_back(r);
    }
    const GpuHits bvh = traceOnGpu(*ctx, arrays, rays, Accel::Bvh);
    const GpuHits wide = traceOnGpu(*ctx, arrays, rays, Accel::Wide);
    std::size_t binaryHits = 0, wideHits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        binaryHits += bvh.closest[i].triangle != PN_NO_HIT;
        wideHits += wide.closest[i].triangle != PN_NO_HIT || wide.occluded[i];
    }
    EXPECT_GT(binaryHits, rays.size() / 4);  // the rest pass through holes in line on every layer
    EXPECT_EQ(wideHits, 0u);
}

}  // namespace
}  // namespace penumbra::test
