// The viewer's frame loop as a whole: with a still camera its running mean is the image
// `penumbra render` makes with the same samples; debug views show what they claim.
#include "render/interactive_renderer.h"
#include "render/renderer.h"
#include "scene/presets/presets.h"
#include "gpu_fixture.h"

namespace penumbra::test {
namespace {

using ViewerRenderTest = GpuTest;

TEST_F(ViewerRenderTest, StillCameraConvergesToTheHeadlessRender) {
    Scene scene = makeCornellBox();
    const std::uint32_t w = 24, h = 18, frames = 6;
    RenderSettings rs;
    rs.width = w;
    rs.height = h;
    rs.samplesPerPixel = frames;
    rs.samplesPerPass = 1;
    rs.maxBounces = 6;
    Renderer reference(*ctx, scene, rs);
    reference.render();
    ImageRgb expected = reference.image();

    InteractiveRenderer viewer(*ctx, scene, false, rs.seed);
    viewer.resize(w, h);
    ViewSettings vs;
    vs.samplesPerFrame = 1;
    vs.maxBounces = rs.maxBounces;
    vs.rouletteStart = rs.rouletteStart;
    for (std::uint32_t k = 0; k < frames; ++k) {
        viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, vs); });
        viewer.finishFrame();
    }
    EXPECT_EQ(viewer.stats().samplesPerPixel, frames);
    auto history = gpu::downloadBuffer<shader::HistoryTexel>(*ctx, viewer.commands(), viewer.history(), w * h);
    double total = 0;
    for (std::uint32_t i = 0; i < w * h; ++i) {
        EXPECT_EQ(history[i].samples, float(frames));
        for (int c = 0; c < 3; ++c) {
            float want = expected.pixels[i][c];
            ASSERT_NEAR(history[i].color[c], want, 1e-4f * (1 + want)) << "pixel " << i << " channel " << c;
            total += want;
        }
    }
    EXPECT_GT(total, 0.0);  // the comparison was not between two black images
}

// Without history (temporal accumulation off) each frame shows only its own samples; they must
// be new samples every frame, or the noise freezes on the screen.
TEST_F(ViewerRenderTest, FramesWithoutHistoryDrawNewSamples) {
    Scene scene = makeCornellBox();
    const std::uint32_t w = 24, h = 18;
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(w, h);
    ViewSettings vs;
    vs.temporal = false;
    auto frame = [&] {
        viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, vs); });
        viewer.finishFrame();
        return gpu::downloadBuffer<shader::HistoryTexel>(*ctx, viewer.commands(), viewer.history(), w * h);
    };
    const auto first = frame(), second = frame();
    std::uint32_t same = 0, lit = 0;
    for (std::uint32_t i = 0; i < w * h; ++i) {
        EXPECT_EQ(second[i].samples, 1.0f);
        if (first[i].color[0] + first[i].color[1] + first[i].color[2] <= 0) continue;
        ++lit;
        same += first[i].color[0] == second[i].color[0] && first[i].color[1] == second[i].color[1] &&
                first[i].color[2] == second[i].color[2];
    }
    ASSERT_GT(lit, w * h / 2);
    // One path per pixel through a diffuse box: a repeat of the same value is rare, except where
    // both frames see only the light (its emission, no noise).
    EXPECT_LT(same, lit / 4) << same << " of " << lit << " lit pixels are unchanged";
}

TEST_F(ViewerRenderTest, HeatMapMaximaAreCountsWithinTheBvh) {
    Scene scene = makeCornellBox();
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(16, 12);
    ViewSettings vs;
    vs.debug = DebugView::HeatNodes;
    for (int k = 0; k < 2; ++k) {
        viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, vs); });
        viewer.finishFrame();
    }
    // Rays into the box descend below the root; no ray can visit more nodes or test more
    // triangles than exist.
    EXPECT_GE(viewer.stats().heatMaxNodes, 2u);
    EXPECT_GE(viewer.stats().heatMaxTriangles, 1u);
    EXPECT_LE(viewer.stats().heatMaxNodes, std::uint32_t(viewer.sceneArrays().nodes.size()));
    EXPECT_LE(viewer.stats().heatMaxTriangles, std::uint32_t(viewer.sceneArrays().triVerts.size()));
}

TEST_F(ViewerRenderTest, TheTorchFollowsTheCameraAndSwitchesOff) {
    Scene scene = makeCornellBox();
    scene.torch.enabled = true;
    attachTorch(scene);
    InteractiveRenderer viewer(*ctx, scene, true);
    ASSERT_TRUE(viewer.hasTorch());
    viewer.resize(16, 12);
    ViewSettings vs;
    vs.maxBounces = 2;
    vs.torch = true;
    vs.torchIntensity = 5.0f;
    Camera moved = scene.camera;
    moved.position = moved.position + Vec3{0.1f, 0.05f, 0.3f};
    moved.lookAt = moved.lookAt + Vec3{0.1f, 0.05f, 0.3f};
    auto frameMean = [&](const Camera& cam) {
        viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, cam, vs); });
        viewer.finishFrame();
        auto h = gpu::downloadBuffer<shader::HistoryTexel>(*ctx, viewer.commands(), viewer.history(), 16 * 12);
        double sum = 0;
        for (const auto& t : h) sum += luminance(t.color);
        return sum / h.size();
    };
    const double on = frameMean(moved);
    auto lights = gpu::downloadBuffer<shader::PunctualLight>(*ctx, viewer.commands(), viewer.gpuScene().punctual,
                                                             viewer.gpuScene().punctualCount);
    const shader::PunctualLight& torch = lights.back();
    EXPECT_NEAR(torch.position.x, moved.position.x, 1e-6);
    EXPECT_NEAR(torch.position.y, moved.position.y - 0.15f, 1e-6);  // attachTorch's 15 cm below the eye
    EXPECT_NEAR(torch.position.z, moved.position.z, 1e-6);
    EXPECT_NEAR(torch.intensity.x, vs.torchColor.x * 5.0f, 1e-5);
    vs.torch = false;
    const double off = frameMean(moved);
    // Same samples (switching resets the running mean to frame 0), minus the torch's light.
    EXPECT_GT(on, off * 1.05) << "on " << on << " off " << off;
}

}  // namespace
}  // namespace penumbra::test
