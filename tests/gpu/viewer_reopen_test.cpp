// The viewer reopens a scene many times on one context (InteractiveRenderer::rebuildScene, as when
// a file is reloaded): the reopened scene is the one on the GPU and drawn, and nothing grows with
// the number of reopens: live Vulkan objects exactly, file descriptors, threads, mappings and
// memory within noise.
//
// A reopen of a viewer that draws also rebuilds its nine compute pipelines, which lavapipe compiles
// in seconds; so 100 reopens (PENUMBRA_LEAK_REOPENS) re-upload the scene of a viewer that has not
// drawn yet, checking the upload each time, and a few (PENUMBRA_LEAK_REOPEN_FRAMES, default 4;
// 100 on a GPU) reopen a drawing viewer and draw a frame.
#include <cstring>

#include "gpu/buffer.h"
#include "gpu_fixture.h"
#include "leak_test_util.h"
#include "render/interactive_renderer.h"

namespace penumbra::test {
namespace {

using ViewerReopenTest = GpuTest;

constexpr std::uint32_t kW = 8, kH = 6;

// A grey wall (material 0) at z = 0 and a ball (material 1) of radius 0.5 at z = 1, seen from
// z = 5: centred, the ball covers the middle of the image; moved sideways, the wall does.
Scene wallAndBall(float ballX) {
    Scene scene;
    scene.name = "wall and ball";
    scene.materials = {{"wall", Vec3{0.8f}}, {"ball", Vec3{0.5f, 0.2f, 0.2f}}};
    Mesh quad;
    quad.name = "wall";
    quad.positions = {{-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    quad.material = 0;
    scene.meshes.push_back(quad);
    scene.spheres.push_back({Vec3{ballX, 0, 1}, 0.5f, 1});
    scene.background = Vec3{1.0f};
    scene.camera.position = {0, 0, 5};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.fovYDegrees = 40;
    return scene;
}

// Whether the GPU holds exactly `expected` as the viewer's triangles (and sphere slots).
bool uploaded(const gpu::Context& ctx, InteractiveRenderer& viewer, const SceneArrays& expected) {
    auto tris = gpu::downloadBuffer<shader::TriVerts>(ctx, viewer.commands(), viewer.gpuScene().triVerts,
                                                      expected.triVerts.size());
    return std::memcmp(tris.data(), expected.triVerts.data(), tris.size() * sizeof(shader::TriVerts)) == 0;
}

// Draws one frame; returns the material seen at the image's centre, -1 for none.
int centreMaterial(const gpu::Context& ctx, InteractiveRenderer& viewer, const Scene& scene) {
    viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, ViewSettings{}); });
    viewer.finishFrame();
    auto g = gpu::downloadBuffer<shader::GBufferTexel>(ctx, viewer.commands(), viewer.gbuffer(), kW * kH);
    return int(g[(kH / 2) * kW + kW / 2].surfaceId) - 1;
}

TEST_F(ViewerReopenTest, ReopeningASceneManyTimesLeavesNothingBehind) {
    const int reopens = std::max(8, envInt("PENUMBRA_LEAK_REOPENS", 100));
    const int warmup = std::min(10, reopens / 4) / 2 * 2;  // even: the same scene is open then and at the end
    const Scene centred = wallAndBall(0.0f), aside = wallAndBall(2.5f);
    const SceneArrays centredArrays = buildSceneArrays(centred), asideArrays = buildSceneArrays(aside);
    ASSERT_NE(std::memcmp(centredArrays.triVerts.data(), asideArrays.triVerts.data(),
                          centredArrays.triVerts.size() * sizeof(shader::TriVerts)),
              0);

    InteractiveRenderer viewer(*ctx, centred, false);
    ProcessResources warm = sampleProcess();
    gpu::VulkanTally warmTally = gpu::vulkanTally();
    for (int i = 0; i < reopens; ++i) {
        const bool ballAside = i % 2 == 0;
        viewer.rebuildScene(ballAside ? aside : centred, false);
        ASSERT_TRUE(uploaded(*ctx, viewer, ballAside ? asideArrays : centredArrays)) << "reopen " << i + 1;
        if (i + 1 == warmup) {
            warm = sampleProcess();
            warmTally = gpu::vulkanTally();
        }
    }
    ProcessResources last = sampleProcess();
    gpu::VulkanTally lastTally = gpu::vulkanTally();
    leakLog("scene reopened " + std::to_string(reopens) + " times; after warm-up " + describe(warm) + "; at the end " +
            describe(last) + "; " + describe(lastTally));
    expectSameObjects(warmTally, lastTally, "reopens");
    expectNoGrowth(warm, last, reopens - warmup, "reopens");

    // A viewer that draws: each reopen rebuilds its passes too; the frame shows the new scene.
    const int drawn = std::max(4, envInt("PENUMBRA_LEAK_REOPEN_FRAMES", 4));
    viewer.resize(kW, kH);
    const bool lastAside = (reopens - 1) % 2 == 0;
    ASSERT_EQ(centreMaterial(*ctx, viewer, lastAside ? aside : centred), lastAside ? 0 : 1) << "first drawn frame";
    for (int i = 0; i < drawn; ++i) {
        const bool ballAside = i % 2 == 1;
        const Scene& scene = ballAside ? aside : centred;
        viewer.rebuildScene(scene, false);
        ASSERT_EQ(centreMaterial(*ctx, viewer, scene), ballAside ? 0 : 1) << "drawn reopen " << i + 1;
        EXPECT_EQ(viewer.stats().samplesPerPixel, 1u) << "a reopened scene starts a new mean";
        if (i + 1 == 2) {
            warm = sampleProcess();
            warmTally = gpu::vulkanTally();
        }
    }
    last = sampleProcess();
    lastTally = gpu::vulkanTally();
    leakLog("scene reopened and drawn " + std::to_string(drawn) + " times; after 2 " + describe(warm) +
            "; at the end " + describe(last) + "; " + describe(lastTally));
    expectSameObjects(warmTally, lastTally, "drawn reopens");
    if (drawn - 2 >= 50) expectNoGrowth(warm, last, drawn - 2, "drawn reopens");
}

}  // namespace
}  // namespace penumbra::test
