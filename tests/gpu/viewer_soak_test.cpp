// Issue 12: the viewer's renderer, headless as `penumbra bench --viewer` drives it, renders
// many tiny frames with the camera moving and a scene reload, under validation (the fixture fails
// on any message). Afterwards nothing has grown (live Vulkan objects exactly; descriptors,
// threads and memory within noise) and nothing has drifted: a still camera's running mean agrees
// with the one it gave at the start, within the sampling error both carry.
// Two runs of the same checks: a short one in every run of the suite (8x8, two bounces, 40
// frames), and the real soak, opt-in, when PENUMBRA_SOAK_FRAMES sets its frame count (thousands;
// on lavapipe on 2 cores even 300 full-length frames took more than four minutes).
#include <cmath>

#include "gpu/buffer.h"
#include "gpu_fixture.h"
#include "leak_test_util.h"
#include "render/interactive_renderer.h"
#include "render/viewer_bench.h"
#include "scene/presets/presets.h"

namespace penumbra::test {
namespace {

constexpr std::uint32_t kW = 8, kH = 8;
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
    const auto texels = gpu::downloadBuffer<shader::HistoryTexel>(ctx, viewer.commands(), viewer.history(), viewer.width() * viewer.height());
    double sum = 0, variance = 0;
    for (const shader::HistoryTexel& t : texels) {
        EXPECT_TRUE(std::isfinite(t.color.x) && std::isfinite(t.color.y) && std::isfinite(t.color.z));
        sum += luminance(Vec3{t.color.x, t.color.y, t.color.z});
        variance += std::max(0.0, double(t.moment2) - double(t.moment1) * t.moment1) / std::max(1.0f, t.samples);
    }
    const double n = double(texels.size());
    return {sum / n, std::sqrt(variance) / n};
}

// `frames` frames with the camera orbiting and the scene reloaded once, then the checks.
// checkMemory: also hold mappings, resident memory and the heap to the leak tests' noise bounds.
void soak(const gpu::Context& ctx, int frames, int warmup, const ViewSettings& view, std::uint32_t stillFrames,
          bool checkMemory) {
    const Scene scene = makeCornellBox();
    InteractiveRenderer viewer(ctx, scene, false);
    viewer.resize(kW, kH);
    const MeanWithError before = stillMean(ctx, viewer, scene.camera, view, stillFrames);
    ASSERT_GT(before.mean, 0.0);

    // The reload comes half-way through the warm-up: lavapipe keeps the code it compiled for the
    // new pipelines (memory mappings, resident memory), which is not ours to count as growth. The
    // Vulkan objects are counted exactly across the reload as well.
    ProcessResources warm{};
    gpu::VulkanTally beforeReload{}, warmTally{};
    for (int k = 0; k < frames; ++k) {
        if (k == warmup / 2) {
            beforeReload = gpu::vulkanTally();
            viewer.rebuildScene(scene, false);  // as a reloaded file is
        }
        drawFrame(viewer, cameraInMotion(scene.camera, CameraMotion::Orbit, k / 60.0), view);
        if (k == warmup) {
            warm = sampleProcess();
            warmTally = gpu::vulkanTally();
        }
    }
    const ProcessResources last = sampleProcess();
    const gpu::VulkanTally lastTally = gpu::vulkanTally();
    leakLog(std::to_string(frames) + " soak frames; after warm-up " + describe(warm) + "; at the end " + describe(last) +
            "; " + describe(lastTally));
    expectSameObjects(beforeReload, lastTally, "reload and soak frames");
    expectSameObjects(warmTally, lastTally, "soak frames");
    if (checkMemory) {
        expectNoGrowth(warm, last, frames - warmup, "soak frames");
    } else {
        EXPECT_LE(last.fds - warm.fds, LeakSlack{}.fds) << "open file descriptors grew over the soak frames";
        EXPECT_LE(last.threads - warm.threads, LeakSlack{}.threads) << "threads grew over the soak frames";
    }

    const MeanWithError after = stillMean(ctx, viewer, scene.camera, view, stillFrames);
    const double sigma = std::sqrt(before.stderr * before.stderr + after.stderr * after.stderr);
    // 5 sigma: a false alarm about once in 3.5 million runs.
    EXPECT_NEAR(after.mean, before.mean, 5 * sigma) << "the still image drifted over " << frames << " frames";
}

using ViewerSoakTest = GpuTest;

// Every run: short paths (two bounces) and few frames. A moving frame is dear on lavapipe (it
// spends it in LLVM, compiling again: apparently per frame, not once), so this run is sized by
// time, not by frames; the warm-up leaves the allocators and caches settled before the resources
// are first sampled. 40 frames: the reload at frame 8, the warm-up to frame 16, then 24 frames
// compared, which is enough for every check: the live Vulkan objects must be exactly equal (one
// object left per frame shows at once), descriptors and threads have a slack of 2 (one per frame
// shows after 3 frames), and the drift test's tolerance comes from the still frames' own
// standard errors (16 frames before and after, as before). 80 frames (until issue 38) took 230 s
// of the 2-core machine in CI's ctest -j2, the longest test of the suite, for no more cover.
// Memory is not checked here: on lavapipe the process's heap grows by about 4 MiB every frame of
// this loop, moving camera or still, while the Vulkan objects stay exactly the same (issue 12,
// docs/RELIABILITY.md "Soak": not yet explained; the long soak checks memory and shows it).
TEST_F(ViewerSoakTest, MovingFramesAndAReloadLeaveNothingBehindAndNoDrift) {
    ViewSettings view;
    view.maxBounces = 2;
    soak(*ctx, 40, 16, view, 16, false);
}

TEST_F(ViewerSoakTest, ThousandsOfMovingFramesAndAReloadLeaveNothingBehindAndNoDrift) {
    const int frames = envInt("PENUMBRA_SOAK_FRAMES", 0);
    if (frames <= 0) GTEST_SKIP() << "the long soak runs only with PENUMBRA_SOAK_FRAMES=N (N frames, e.g. 5000)";
    ASSERT_GE(frames, 200) << "PENUMBRA_SOAK_FRAMES below 200 leaves too few frames after the warm-up";
    soak(*ctx, frames, 100, ViewSettings{}, 64, true);
}

}  // namespace
}  // namespace penumbra::test
