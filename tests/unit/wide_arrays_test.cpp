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

    const std::size_t nodeBytes = binary.nodes.size() * sizeof(shader::BvhNode);
    const std::size_t wideBytes = wide.wideNodes.size() * sizeof(shader::WideNode);
    EXPECT_EQ(deviceBytes(wide), deviceBytes(binary) - nodeBytes + wideBytes);
    EXPECT_EQ(sumOfBufferSizes(wide), deviceBytes(wide));
    EXPECT_EQ(sumOfBufferSizes(binary), deviceBytes(binary));
    EXPECT_LT(deviceBytes(wide), deviceBytes(binary));
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
