// What buildSceneArrays builds for each walk: the wide tree only for --accel wide on a flat scene,
// and then the binary nodes stay on the host (the wide walk never reads them), which the memory
// figures (deviceBytes, the per-buffer sizes the device check uses) follow.
#include <gtest/gtest.h>

#include "bvh/traverse_cpu.h"
#include "bvh/traverse_wide_cpu.h"
#include "instanced_world.h"
#include "render/gpu_scene.h"
#include "render/scene_limits.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

std::size_t sumOfBufferSizes(const SceneArrays& a) {
    std::size_t sum = 0;
    for (const SceneBufferSize& b : sceneBufferSizes(a)) sum += b.bytes;
    return sum;
}

TEST(WideArrays, OnlyTheWideWalkGetsTheWideTreeAndItAloneLeavesTheBinaryNodesOnTheHost) {
    const Scene scene = makeCornellBox();
    const SceneArrays binary = buildSceneArrays(scene);
    EXPECT_TRUE(binary.wideNodes.empty());
    EXPECT_TRUE(binary.binaryNodesOnGpu);
    const SceneArrays wide = buildSceneArrays(scene, {}, Accel::Wide);
    ASSERT_FALSE(wide.wideNodes.empty());
    EXPECT_FALSE(wide.binaryNodesOnGpu);
    // The host keeps the binary tree, over the wide tree's primitive order (picking, overlays).
    ASSERT_EQ(wide.nodes.size(), binary.nodes.size());
    int hits = 0;
    for (int i = 0; i < 100; ++i) {
        const Ray ray{scene.camera.position, Vec3{0.01f * float(i % 10) - 0.05f, 0.01f * float(i / 10) - 0.05f, 1.0f}};
        const bvh::Hit a = bvh::closestHit(wide.nodes, wide.triVerts, ray), b = bvh::closestHitWide(wide.wideNodes, wide.triVerts, ray);
        EXPECT_EQ(a.triangle, b.triangle) << "ray " << i;
        hits += a.triangle != PN_NO_HIT;
    }
    EXPECT_EQ(hits, 100);

    const std::size_t nodeBytes = binary.nodes.size() * sizeof(shader::BvhPair);  // the binary walk's records
    const std::size_t wideBytes = wide.wideNodes.size() * sizeof(shader::WideNode);
    EXPECT_EQ(deviceBytes(wide), deviceBytes(binary) - nodeBytes + wideBytes);
    EXPECT_EQ(sumOfBufferSizes(wide), deviceBytes(wide));
    EXPECT_EQ(sumOfBufferSizes(binary), deviceBytes(binary));
    EXPECT_LT(deviceBytes(wide), deviceBytes(binary));
}

// Texture coordinates live in their own array, only for the triangles that have any: a mesh
// without UVs adds nothing, and every triangle's slot still finds its own coordinates (matched by
// position, after the wide tree renumbered the primitives).
TEST(WideArrays, OnlyTrianglesWithTextureCoordinatesStoreThem) {
    Scene scene = makeCornellBox();
    const SceneArrays plain = buildSceneArrays(scene, {}, Accel::Wide);
    ASSERT_EQ(plain.triUvs.size(), 1u);  // the shared all-zero entry
    for (const shader::TriVerts& t : plain.triVerts) EXPECT_EQ(t.uvIndex, 0u);

    Mesh quad;
    quad.name = "textured quad";
    quad.positions = {{-0.3f, 0.2f, 0.1f}, {0.3f, 0.2f, 0.1f}, {0.3f, 0.8f, 0.1f}, {-0.3f, 0.8f, 0.1f}};
    quad.uvs = {{0.0f, 0.0f}, {250.5f, 0.0f}, {250.5f, -3.25f}, {0.0f, -3.25f}};  // tiled far past 1
    quad.indices = {0, 1, 2, 0, 2, 3};
    scene.meshes.push_back(quad);
    for (Accel accel : {Accel::Bvh, Accel::Wide}) {
        const SceneArrays a = buildSceneArrays(scene, {}, accel);
        ASSERT_EQ(a.triUvs.size(), 3u);
        int found = 0;
        for (const shader::TriVerts& t : a.triVerts) {
            if (t.uvIndex == 0) continue;
            ASSERT_LT(t.uvIndex, a.triUvs.size());
            const shader::TriUvs& uv = a.triUvs[t.uvIndex];
            // Vertex k of the slot is quad vertex j: its uv must be quad.uvs[j].
            const Vec3 corners[3] = {t.v0, t.v0 + t.e1, t.v0 + t.e2};
            const Vec2 uvs[3] = {uv.uv0, uv.uv1, uv.uv2};
            for (int k = 0; k < 3; ++k) {
                std::size_t j = 0;
                while (j < 4 && length(quad.positions[j] - corners[k]) > 1e-5f) ++j;
                ASSERT_LT(j, 4u) << "corner " << k << " is no quad vertex";
                EXPECT_EQ(uvs[k].x, quad.uvs[j].x);
                EXPECT_EQ(uvs[k].y, quad.uvs[j].y);
            }
            ++found;
        }
        EXPECT_EQ(found, 2);
        EXPECT_EQ(deviceBytes(a), sumOfBufferSizes(a));
    }
}

TEST(WideArrays, TwoLevelScenesKeepTheBinaryWalkUnderAccelWide) {
    const SceneArrays a = buildSceneArrays(test::instancedRoom(), {}, Accel::Wide);
    EXPECT_TRUE(a.wideNodes.empty());
    EXPECT_TRUE(a.binaryNodesOnGpu);
}

TEST(WideArrays, AnEmptySceneKeepsTheBinaryWalk) {
    Scene empty;
    empty.name = "empty";
    empty.materials.push_back(Material{});
    const SceneArrays a = buildSceneArrays(empty, {}, Accel::Wide);
    EXPECT_TRUE(a.wideNodes.empty());
    EXPECT_TRUE(a.binaryNodesOnGpu);
}

}  // namespace
}  // namespace penumbra
