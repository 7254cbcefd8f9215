// The temporal pass: exact running mean with a still camera, reprojection that follows a known
// camera translation, and rejection of history that belongs to another surface.
#include <random>

#include "render/gpu_scene.h"
#include "render/passes/gbuffer_pass.h"
#include "render/passes/temporal_pass.h"
#include "scene/presets/mesh_builder.h"
#include "viewer_pass_fixture.h"

namespace penumbra::test {
namespace {

class TemporalTest : public ViewerPassTest {
protected:
    void makeBuffers() {
        accum = pixels<Vec4>();
        gbuffer = pixels<shader::GBufferTexel>();
        gbufferPrev = pixels<shader::GBufferTexel>();
        historyA = pixels<shader::HistoryTexel>();
        historyB = pixels<shader::HistoryTexel>();
        filterIn = pixels<Vec4>();
        guide = pixelBytes(PN_DENOISE_GUIDE_BYTES);
        estimates = pixels<Vec4>();
        auto make = [&](gpu::Buffer& in, gpu::Buffer& out) {
            return std::make_unique<TemporalPass>(
                *ctx, TemporalBuffers{&frame, &viewer, &accum, &gbuffer, &gbufferPrev, &in, &out, &filterIn, &guide,
                                      &estimates});
        };
        aToB = make(historyA, historyB);
        bToA = make(historyB, historyA);
    }
    // Runs frame `k` (history alternates between the two buffers); returns the written history.
    shader::HistoryTexel* runFrame(std::uint32_t k) {
        writeViewer();
        submit([&](VkCommandBuffer cmd) { (k % 2 == 0 ? aToB : bToA)->record(cmd, width, height); });
        return view<shader::HistoryTexel>(k % 2 == 0 ? historyB : historyA);
    }
    void fillGBuffers(const shader::GBufferTexel& g) {
        for (std::uint32_t i = 0; i < width * height; ++i) view<shader::GBufferTexel>(gbuffer)[i] = view<shader::GBufferTexel>(gbufferPrev)[i] = g;
    }
    // This frame's sums for `spp` samples whose mean is `mean` (and squared-luminance sum to match).
    void setCurrent(std::uint32_t i, Vec3 mean, std::uint32_t spp) {
        float y = luminance(mean);
        view<Vec4>(accum)[i] = Vec4{mean.x * spp, mean.y * spp, mean.z * spp, y * y * spp};
    }

    gpu::Buffer accum, gbuffer, gbufferPrev, historyA, historyB, filterIn, guide, estimates;
    std::unique_ptr<TemporalPass> aToB, bToA;
};

TEST_F(TemporalTest, StillCameraKeepsTheExactRunningMeanOfEveryFrame) {
    setUpImage(16, 12);
    makeBuffers();
    fillGBuffers(surfaceTexel(2.0f));
    const std::uint32_t spp = 3, frames = 10, n = width * height;
    viewerUniforms.samplesPerFrame = spp;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> value(0.0f, 5.0f);
    std::vector<std::array<double, 3>> sums(n, {0, 0, 0});
    shader::HistoryTexel* out = nullptr;
    for (std::uint32_t k = 0; k < frames; ++k) {
        for (std::uint32_t i = 0; i < n; ++i) {
            Vec3 c{value(rng), value(rng), value(rng)};
            setCurrent(i, c, spp);
            for (int ch = 0; ch < 3; ++ch) sums[i][ch] += c[ch];
        }
        viewerUniforms.historyValid = k > 0;
        out = runFrame(k);
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        EXPECT_EQ(out[i].samples, float(spp * frames));
        for (int ch = 0; ch < 3; ++ch)
            ASSERT_NEAR(out[i].color[ch], sums[i][ch] / frames, 1e-5 * (1 + sums[i][ch] / frames)) << "pixel " << i;
    }
}

TEST_F(TemporalTest, ASurfaceChangeUnderAStillCameraDropsThatPixelsHistory) {
    setUpImage(16, 12);
    makeBuffers();
    fillGBuffers(surfaceTexel(2.0f));
    for (std::uint32_t i = 0; i < width * height; ++i) setCurrent(i, Vec3{1.0f}, 1);
    for (std::uint32_t k = 0; k < 4; ++k) {
        viewerUniforms.historyValid = k > 0;
        runFrame(k);
    }
    // An object moves into pixel 5 (another surface id) and pixel 9 (closer, other normal).
    view<shader::GBufferTexel>(gbuffer)[5] = surfaceTexel(2.0f, {0, 0, -1}, Vec3{0.5f}, 2);
    view<shader::GBufferTexel>(gbuffer)[9] = surfaceTexel(1.0f, {1, 0, 0});
    for (std::uint32_t i = 0; i < width * height; ++i) setCurrent(i, Vec3{3.0f}, 1);
    shader::HistoryTexel* out = runFrame(4);
    for (std::uint32_t i : {5u, 9u}) {
        EXPECT_EQ(out[i].samples, 1.0f) << "pixel " << i;
        EXPECT_NEAR(out[i].color.x, 3.0f, 1e-6) << "pixel " << i;
    }
    EXPECT_EQ(out[0].samples, 5.0f);
    EXPECT_NEAR(out[0].color.x, (4 * 1.0 + 3.0) / 5, 1e-6);
}

TEST_F(TemporalTest, ReprojectionFollowsAKnownCameraTranslation) {
    // A wall facing the camera at depth 4; the camera then moves right by exactly 3 pixels' width
    // at that depth, so what was at pixel x is now at pixel x - 3.
    setUpImage(24, 16);
    makeBuffers();
    Scene scene;
    scene.name = "wall";
    std::uint32_t grey = addMaterial(scene, "grey", Vec3{0.5f});
    Mesh wall;
    wall.material = grey;
    const float depth = 4.0f;
    addQuad(wall, {-50, -50, depth}, {50, -50, depth}, {50, 50, depth}, {-50, 50, depth});
    scene.meshes.push_back(wall);
    SceneArrays arrays = buildSceneArrays(scene);
    GpuScene gpuScene(*ctx, *commands, arrays);
    frameUniforms.nodeCount = gpuScene.nodeCount;
    frameUniforms.triCount = gpuScene.triCount;
    std::memcpy(frame.mapped(), &frameUniforms, sizeof(frameUniforms));
    GBufferPass gbufferPass(*ctx, gpuScene, frame, viewer, gbuffer, KernelSpec{});

    // Frame 0: a distinct value per pixel, no history.
    const shader::FrameUniforms first = frameUniforms;
    setPreviousCamera(first);
    viewerUniforms.historyValid = 0;
    writeViewer();
    submit([&](VkCommandBuffer cmd) { gbufferPass.record(cmd, width, height); });
    for (std::uint32_t i = 0; i < width * height; ++i) setCurrent(i, Vec3{float(i % width) + 1, float(i / width) + 1, 1}, 1);
    shader::HistoryTexel* h0 = runFrame(0);
    std::vector<shader::HistoryTexel> before(h0, h0 + width * height);
    std::memcpy(gbufferPrev.mapped(), gbuffer.mapped(), gbuffer.size());

    // Frame 1: moved camera, this frame's samples all zero.
    const int shift = 3;
    const float pixelSize = 2 * depth * first.tanHalfFovY / float(height);
    Camera moved = defaultCamera();
    moved.position = moved.position + first.cameraRight * (shift * pixelSize);
    moved.lookAt = moved.lookAt + first.cameraRight * (shift * pixelSize);
    setCamera(moved);
    frameUniforms.nodeCount = gpuScene.nodeCount;
    frameUniforms.triCount = gpuScene.triCount;
    std::memcpy(frame.mapped(), &frameUniforms, sizeof(frameUniforms));
    viewerUniforms.historyValid = 1;
    viewerUniforms.cameraMoved = 1;
    writeViewer();
    submit([&](VkCommandBuffer cmd) { gbufferPass.record(cmd, width, height); });
    std::memset(accum.mapped(), 0, accum.size());
    shader::HistoryTexel* out = runFrame(1);

    const auto* g = view<shader::GBufferTexel>(gbuffer);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            std::uint32_t i = y * width + x;
            EXPECT_NEAR(g[i].motion.x, float(shift), 1e-3) << x << "," << y;
            EXPECT_NEAR(g[i].motion.y, 0.0f, 1e-3) << x << "," << y;
            if (x + shift < width) {
                // History from x + shift (N = 1), blended with a zero sample: half of it.
                const shader::HistoryTexel& src = before[y * width + x + shift];
                EXPECT_NEAR(out[i].color.x, 0.5f * src.color.x, 2e-3) << x << "," << y;
                EXPECT_NEAR(out[i].color.y, 0.5f * src.color.y, 2e-3) << x << "," << y;
                EXPECT_NEAR(out[i].samples, 2.0f, 1e-3);
            } else {
                // Came into view from beyond the old image's edge: no history.
                EXPECT_EQ(out[i].samples, 1.0f) << x << "," << y;
                EXPECT_EQ(out[i].color.x, 0.0f) << x << "," << y;
            }
        }
}

TEST_F(TemporalTest, DisoccludedHistoryIsRejectedByDepthAndNormal) {
    setUpImage(16, 12);
    makeBuffers();
    fillGBuffers(surfaceTexel(2.0f));
    for (std::uint32_t i = 0; i < width * height; ++i) setCurrent(i, Vec3{1.0f}, 1);
    runFrame(0);
    // The camera moved (motion vectors zero here, so each pixel looks at its own old position):
    // on the right half a closer object now covers the wall, in the top row a surface turned.
    viewerUniforms.historyValid = 1;
    viewerUniforms.cameraMoved = 1;
    auto* g = view<shader::GBufferTexel>(gbuffer);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            if (x >= width / 2) g[y * width + x] = surfaceTexel(1.0f);
            else if (y == 0) g[y * width + x] = surfaceTexel(2.0f, {0, 1, 0});
        }
    for (std::uint32_t i = 0; i < width * height; ++i) setCurrent(i, Vec3{5.0f}, 1);
    shader::HistoryTexel* out = runFrame(1);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const shader::HistoryTexel& o = out[y * width + x];
            const bool rejected = x >= width / 2 || y == 0;
            EXPECT_EQ(o.samples, rejected ? 1.0f : 2.0f) << x << "," << y;
            EXPECT_NEAR(o.color.x, rejected ? 5.0f : 3.0f, 1e-5) << x << "," << y;
        }
}

TEST_F(TemporalTest, ClampKeepsStaleHistoryInsideTheCurrentNeighbourhood) {
    // A light went out: history says 10, every current sample says 1. Moving-camera blending
    // without the clamp would give 5.5; clamped to the (uniform) neighbourhood it gives 1.
    setUpImage(16, 12);
    makeBuffers();
    fillGBuffers(surfaceTexel(2.0f));
    for (std::uint32_t i = 0; i < width * height; ++i) setCurrent(i, Vec3{10.0f}, 1);
    runFrame(0);
    viewerUniforms.historyValid = 1;
    viewerUniforms.cameraMoved = 1;
    viewerUniforms.clampSigma = 1.5f;
    for (std::uint32_t i = 0; i < width * height; ++i) setCurrent(i, Vec3{1.0f}, 1);
    shader::HistoryTexel* out = runFrame(1);
    for (std::uint32_t i = 0; i < width * height; ++i) ASSERT_NEAR(out[i].color.x, 1.0f, 1e-5) << i;
}

}  // namespace
}  // namespace penumbra::test
