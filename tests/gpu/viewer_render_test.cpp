// The viewer's frame loop as a whole: with a still camera its running mean is the image
// `penumbra render` makes with the same samples; debug views show what they claim.
#include <map>
#include <set>
#include <string>
#include <utility>

#include "bvh/traverse_cpu.h"
#include "render/frame_uniforms.h"
#include "render/interactive_renderer.h"
#include "render/renderer.h"
#include "scene/presets/presets.h"
#include "gpu_fixture.h"
#include "scoped_tuning.h"

namespace penumbra::test {
namespace {

using ViewerRenderTest = GpuTest;

// Both trace kernels: the viewer's passes store over the last frame's sums (no clear between
// frames), which a kernel that added to them would show as a mean growing frame by frame.
class ViewerRenderKernelTest : public GpuTest, public ::testing::WithParamInterface<const char*> {};

// The viewer's running mean after `frames` still frames of samplesPerFrame samples each equals
// the headless render of as many passes, with the samples of a frame (a pass) sharing their
// camera ray or not.
void expectStillViewerMatchesTheRender(const gpu::Context& ctx, std::uint32_t samplesPerFrame, bool shareCameraRays) {
    Scene scene = makeCornellBox();
    const std::uint32_t w = 24, h = 18, frames = 6;
    RenderSettings rs;
    rs.width = w;
    rs.height = h;
    rs.samplesPerPixel = frames * samplesPerFrame;
    rs.samplesPerPass = samplesPerFrame;
    rs.maxBounces = 6;
    rs.shareCameraRays = shareCameraRays;
    // The two estimate a pixel's value differently (the history's running mean, the sums over
    // their count), which the shadow-ray roulette would turn into different samples.
    rs.shadowRouletteShare = 0;
    Renderer reference(ctx, scene, rs);
    reference.render();
    ImageRgb expected = reference.image();

    InteractiveRenderer viewer(ctx, scene, false, rs.seed);
    viewer.resize(w, h);
    ViewSettings vs;
    vs.samplesPerFrame = samplesPerFrame;
    vs.shareCameraRays = shareCameraRays;
    vs.shadowRouletteShare = rs.shadowRouletteShare;
    vs.maxBounces = rs.maxBounces;
    vs.rouletteStart = rs.rouletteStart;
    for (std::uint32_t k = 0; k < frames; ++k) {
        viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, vs); });
        viewer.finishFrame();
    }
    EXPECT_EQ(viewer.stats().samplesPerPixel, frames * samplesPerFrame);
    auto history = gpu::downloadBuffer<shader::HistoryTexel>(ctx, viewer.commands(), viewer.history(), w * h);
    double total = 0;
    for (std::uint32_t i = 0; i < w * h; ++i) {
        EXPECT_EQ(history[i].samples, float(frames * samplesPerFrame));
        for (int c = 0; c < 3; ++c) {
            float want = expected.pixels[i][c];
            ASSERT_NEAR(history[i].color[c], want, 1e-4f * (1 + want)) << "pixel " << i << " channel " << c;
            total += want;
        }
    }
    EXPECT_GT(total, 0.0);  // the comparison was not between two black images
}

TEST_P(ViewerRenderKernelTest, StillCameraConvergesToTheHeadlessRender) {
    ScopedTuning tuning;
    tuning.kernel(GetParam());
    expectStillViewerMatchesTheRender(*ctx, 1, false);
    expectStillViewerMatchesTheRender(*ctx, 3, false);
    expectStillViewerMatchesTheRender(*ctx, 3, true);
}

INSTANTIATE_TEST_SUITE_P(Kernels, ViewerRenderKernelTest, ::testing::Values("mega", "wavefront"));

// The wavefront's stage timer (RenderTuning::waveStageTimes, PENUMBRA_WAVE_STAGE_TIMES=1)
// reports each step per round of the bounce loop as well as in total; after one timed pass the medians are that pass's figures, so
// a step's rounds add up to its total.
TEST_F(ViewerRenderTest, WavefrontStageTimesPerRoundAddUpToEachStep) {
    ScopedTuning tuning;
    tuning.kernel("wavefront").stageTimes(true);
    Scene scene = makeCornellBox();
    InteractiveRenderer viewer(*ctx, scene, false, 7);
    viewer.resize(16, 12);
    ViewSettings vs;
    vs.maxBounces = 3;
    for (int frame = 0; frame < 2; ++frame) {  // the second collects the first's timestamps
        viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, vs); });
        viewer.finishFrame();
    }
    const std::map<std::string, double> ms = viewer.traceStageMilliseconds();
    ASSERT_FALSE(ms.empty()) << "no stage times: are timestamps supported?";
    auto sumOfRounds = [&](const std::string& step) {
        double sum = 0;
        int rounds = 0;
        for (const auto& [name, value] : ms)
            if (name.rfind(step + ".b", 0) == 0) {
                sum += value;
                ++rounds;
            }
        return std::pair{sum, rounds};
    };
    const std::pair<const char*, int> steps[] = {{"start", 1}, {"extend", 4}, {"shade", 4}, {"shadow", 4}, {"finish", 1}};
    for (const auto& [step, rounds] : steps) {
        ASSERT_TRUE(ms.count(step)) << step;
        const auto [sum, found] = sumOfRounds(step);
        EXPECT_EQ(found, rounds) << step;  // bounces 0-3 trace closest hits; shadows follow rounds 0-3's shading
        EXPECT_NEAR(sum, ms.at(step), 1e-9 * (1 + ms.at(step))) << step;
        EXPECT_GE(ms.at(step), 0.0) << step;
    }
    EXPECT_TRUE(ms.count("extend.b0") && ms.count("shadow.b1") && ms.count("shadow.b4") && !ms.count("shadow.b0"));
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

// The CPU's answer for a pixel's primary ray: the leaf whose range holds its closest hit, as
// (depth, primitives); (0, 0) on a miss. Children follow their parents in the node array, so one
// pass in index order gives every node's depth.
std::pair<std::uint32_t, std::uint32_t> hitLeaf(const SceneArrays& a, const Ray& ray) {
    const bvh::Hit hit = bvh::closestHit(a.nodes, a.triVerts, ray);
    if (hit.triangle == PN_NO_HIT) return {0, 0};
    std::vector<std::uint32_t> depth(a.nodes.size(), 0);
    depth[0] = 1;  // the root, as bvh::treeDepth counts
    for (std::size_t n = 0; n < a.nodes.size(); ++n) {
        const shader::BvhNode& node = a.nodes[n];
        if (node.triCount == 0) {
            depth[n + 1] = depth[n] + 1;
            depth[node.firstOrRight] = depth[n] + 1;
        } else if (hit.triangle >= node.firstOrRight && hit.triangle < node.firstOrRight + node.triCount) {
            return {depth[n], node.triCount};
        }
    }
    ADD_FAILURE() << "primitive " << hit.triangle << " is in no leaf";
    return {0, 0};
}

TEST_F(ViewerRenderTest, LeafViewsShowTheDepthAndSizeOfTheLeafHoldingEachPixelsHit) {
    Scene scene = makeCornellBox();
    const std::uint32_t w = 16, h = 12;
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(w, h);
    ViewSettings vs;
    vs.debug = DebugView::LeafDepth;
    viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, vs); });
    viewer.finishFrame();
    const auto heat = gpu::downloadBuffer<Vec4>(*ctx, viewer.commands(), viewer.heatCounts(), w * h);
    const SceneArrays& a = viewer.sceneArrays();

    RenderSettings rs;
    rs.width = w;
    rs.height = h;
    const shader::FrameUniforms f = makeFrameUniforms(scene.camera, scene.background, rs, 0, 0, 0);
    int agree = 0, hits = 0;
    std::set<std::uint32_t> depths;
    std::uint32_t deepest = 0, largest = 0;
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            // viewer_common.glsl's viewDirection at the pixel's centre.
            const float nx = 2.0f * (float(x) + 0.5f) / float(w) - 1.0f, ny = 1.0f - 2.0f * (float(y) + 0.5f) / float(h);
            const Vec3 d = normalize(f.cameraForward + f.cameraRight * (nx * f.aspect * f.tanHalfFovY) +
                                     f.cameraUp * (ny * f.tanHalfFovY));
            const auto [depth, primitives] = hitLeaf(a, Ray{scene.camera.position, d});
            const Vec4 got = heat[y * w + x];
            if (got.z == float(depth) && got.w == float(primitives)) ++agree;
            if (primitives > 0) {
                ++hits;
                depths.insert(depth);
                deepest = std::max(deepest, depth);
                largest = std::max(largest, primitives);
            }
        }
    // A ray grazing an edge may hit the neighbouring triangle on one side and not the other.
    EXPECT_GE(agree, int(w * h) - 4);
    EXPECT_GT(hits, int(w * h) / 2);
    EXPECT_GE(depths.size(), 2u) << "every hit in leaves of one depth: the test would not see a wrong depth";
    // The legend's maxima are the frame's.
    EXPECT_EQ(viewer.stats().heatMaxLeafDepth, deepest);
    EXPECT_EQ(viewer.stats().heatMaxLeafTriangles, largest);
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
