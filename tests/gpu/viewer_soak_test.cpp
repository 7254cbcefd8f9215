// Issue 12: the viewer's renderer, headless as `penumbra bench --viewer` drives it, renders
// thousands of tiny frames with the camera moving and a scene reload half-way, under validation
// (the fixture fails on any message). Afterwards nothing has grown (live Vulkan objects exactly;
// descriptors, threads and memory within noise) and nothing has drifted: a still camera's running
// mean agrees with the one it gave at the start, within the sampling error both carry.
// Opt-in: it runs only when PENUMBRA_SOAK_FRAMES sets the frame count (thousands for a real soak).
// On lavapipe on 2 cores even 300 frames took more than four minutes, too long for every run of
// the suite (issue 12 is open for making it fast enough to run always).
#include <cmath>

#include "gpu/buffer.h"
#include "gpu_fixture.h"
#include "leak_test_util.h"
#include "render/interactive_renderer.h"
#include "render/viewer_bench.h"
#include "scene/presets/presets.h"

namespace penumbra::test {
namespace {

constexpr std::uint32_t kW = 8, kH = 6;
constexpr std::uint32_t kStillFrames = 64;  // per still-camera mean, before and after the soak

void drawFrame(InteractiveRenderer& viewer, const Camera& camera, const ViewSettings& view) {
    viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, camera, view); });
    viewer.finishFrame();
}

struct MeanWithError {
    double mean = 0, stderr = 0;
};

// The image's mean luminance after `frames` frames from a fresh history with a still camera, and
// its standard error from the history's per-pixel moments.
MeanWithError stillMean(const gpu::Context& ctx, InteractiveRenderer& viewer, const Camera& camera,
                        const ViewSettings& view, std::uint32_t frames) {
    viewer.resetHistory();
    for (std::uint32_t i = 0; i < frames; ++i) drawFrame(viewer, camera, view);
    EXPECT_EQ(viewer.stats().samplesPerPixel, frames * view.samplesPerFrame) << "a still camera's mean grows each frame";
    const auto texels = gpu::downloadBuffer<shader::HistoryTexel>(ctx, viewer.commands(), viewer.history(), kW * kH);
    double sum = 0, variance = 0;
    for (const shader::HistoryTexel& t : texels) {
        EXPECT_TRUE(std::isfinite(t.color.x) && std::isfinite(t.color.y) && std::isfinite(t.color.z));
        sum += luminance(Vec3{t.color.x, t.color.y, t.color.z});
        variance += std::max(0.0, double(t.moment2) - double(t.moment1) * t.moment1) / std::max(1.0f, t.samples);
    }
    const double n = double(texels.size());
    return {sum / n, std::sqrt(variance) / n};
}

using ViewerSoakTest = GpuTest;

TEST_F(ViewerSoakTest, ThousandsOfMovingFramesAndAReloadLeaveNothingBehindAndNoDrift) {
    const int frames = envInt("PENUMBRA_SOAK_FRAMES", 0);
    if (frames <= 0) GTEST_SKIP() << "the soak runs only with PENUMBRA_SOAK_FRAMES=N (N frames, e.g. 5000)";
    ASSERT_GE(frames, 200) << "PENUMBRA_SOAK_FRAMES below 200 leaves too few frames after the warm-up";
    const int warmup = 100;
    const Scene scene = makeCornellBox();
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    const ViewSettings view;
    const MeanWithError before = stillMean(*ctx, viewer, scene.camera, view, kStillFrames);
    ASSERT_GT(before.mean, 0.0);

    ProcessResources warm{};
    gpu::VulkanTally warmTally{};
    for (int k = 0; k < frames; ++k) {
        drawFrame(viewer, cameraInMotion(scene.camera, CameraMotion::Orbit, k / 60.0), view);
        if (k == warmup) {
            warm = sampleProcess();
            warmTally = gpu::vulkanTally();
        }
        if (k == frames / 2) viewer.rebuildScene(scene, false);  // as a reloaded file is
    }
    const ProcessResources last = sampleProcess();
    const gpu::VulkanTally lastTally = gpu::vulkanTally();
    leakLog(std::to_string(frames) + " soak frames; after warm-up " + describe(warm) + "; at the end " + describe(last) +
            "; " + describe(lastTally));
    expectSameObjects(warmTally, lastTally, "soak frames");
    expectNoGrowth(warm, last, frames - warmup, "soak frames");

    const MeanWithError after = stillMean(*ctx, viewer, scene.camera, view, kStillFrames);
    const double sigma = std::sqrt(before.stderr * before.stderr + after.stderr * after.stderr);
    // 5 sigma: a false alarm about once in 3.5 million runs.
    EXPECT_NEAR(after.mean, before.mean, 5 * sigma) << "the still image drifted over " << frames << " frames";
}

}  // namespace
}  // namespace penumbra::test
