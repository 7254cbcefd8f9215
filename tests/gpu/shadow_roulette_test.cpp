// Shadow-ray roulette (lib/path.glsl keepShadowRay): light samples worth less than a share of their
// pixel's value so far are traced with a probability and weighted by its inverse. It must trace
// fewer shadow rays and leave the mean where it was, both in a headless render (whose estimate is
// the sums over their count) and in the viewer (whose estimate is its history's mean).
#include <cmath>
#include <cstdio>
#include <string>

#include "gpu/buffer.h"
#include "gpu_fixture.h"
#include "render/interactive_renderer.h"
#include "render/kernel_features.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/mesh_builder.h"
#include "scene/presets/presets.h"

namespace penumbra::test {
namespace {

// A dark room (floor and three walls) under a row of 16 small lights whose power falls by 2x from
// one to the next. Light samples from the second vertex of a path carry the dark first bounce's
// throughput, and with uniform light picks most samples go to faint lights: either way many
// carry little next to the pixel's value, the case the roulette is for.
Scene manyLightsScene() {
    Scene scene;
    scene.name = "many-lights";
    const std::uint32_t dark = addMaterial(scene, "dark", Vec3{0.15f});
    addQuadMesh(scene, "floor", dark, {-4, 0, 2}, {4, 0, 2}, {4, 0, -4}, {-4, 0, -4});
    addQuadMesh(scene, "back", dark, {-4, 0, -4}, {4, 0, -4}, {4, 3, -4}, {-4, 3, -4});
    addQuadMesh(scene, "left", dark, {-4, 0, 2}, {-4, 0, -4}, {-4, 3, -4}, {-4, 3, 2});
    addQuadMesh(scene, "right", dark, {4, 0, -4}, {4, 0, 2}, {4, 3, 2}, {4, 3, -4});
    static_assert(16 >= kShadowRouletteMinLights, "the roulette must be compiled in for this scene");
    for (int k = 0; k < 16; ++k) {
        const float x = -3.4f + 0.45f * float(k), power = 400.0f / float(1 << (k % 12));
        const std::uint32_t m = addMaterial(scene, "light" + std::to_string(k), Vec3{0.0f}, Vec3{power});
        Mesh tri;
        tri.name = scene.materials[m].name;
        tri.material = m;
        tri.positions = {{x, 1.5f, -1.0f}, {x + 0.1f, 1.5f, -1.0f}, {x + 0.05f, 1.5f, -1.1f}};
        tri.indices = {0, 2, 1};  // facing down
        scene.meshes.push_back(tri);
    }
    scene.camera.position = {0, 2.0f, 2.5f};
    scene.camera.lookAt = {0, 0, -1.0f};
    scene.camera.fovYDegrees = 60.0f;
    return scene;
}

// Only scenes of many lights get the roulette's code: with a few, a light sample rarely carries
// so little that the test pays for itself.
TEST(ShadowRouletteFeature, OnlyScenesOfManyLightsCarryIt) {
    EXPECT_TRUE(kernelSpec(buildSceneArrays(manyLightsScene())).has(PN_FEATURE_SHADOW_ROULETTE));
    EXPECT_FALSE(kernelSpec(buildSceneArrays(makeCornellBox())).has(PN_FEATURE_SHADOW_ROULETTE));
}

struct Estimate {
    MeanEstimate image;
    std::uint64_t shadowRays;
};

constexpr std::uint32_t kWidth = 24, kHeight = 18, kSamples = 256;

Estimate renderHeadless(const gpu::Context& ctx, float share, bool uniformPicks, std::uint32_t samples = kSamples) {
    RenderSettings s;
    s.width = kWidth;
    s.height = kHeight;
    s.samplesPerPixel = samples;
    s.samplesPerPass = 8;
    s.maxBounces = 2;
    s.seed = 5;
    s.shadowRouletteShare = share;
    s.uniformLightPick = uniformPicks;
    Renderer renderer(ctx, manyLightsScene(), s);
    renderer.render();
    EXPECT_EQ(renderer.stats().invalidSamples, 0u);
    return {imageMean(renderer.accumulation(), samples), renderer.stats().shadowRays};
}

TEST_F(GpuTest, ShadowRayRouletteTracesFewerRaysForTheSameMean) {
    // Enough samples that dropping the weights (a 5% bias here) shows: checked by mutation.
    const Estimate all = renderHeadless(*ctx, 0.0f, true, 2 * kSamples);
    const Estimate rouletted = renderHeadless(*ctx, 1.0f, true, 2 * kSamples);
    ASSERT_GT(all.image.mean, 1e-3) << "the scene is lit";
    EXPECT_NEAR(rouletted.image.mean, all.image.mean, sidakZ(1e-3, 1) * std::hypot(all.image.stderr, rouletted.image.stderr));
    EXPECT_LT(double(rouletted.shadowRays), 0.8 * double(all.shadowRays)) << "the roulette dropped few shadow rays";
    std::printf("mean (stderr), shadow rays: all %.5f (%.5f) %llu, rouletted %.5f (%.5f) %llu\n", all.image.mean,
                all.image.stderr, static_cast<unsigned long long>(all.shadowRays), rouletted.image.mean,
                rouletted.image.stderr, static_cast<unsigned long long>(rouletted.shadowRays));
}

// The viewer's frames read the estimates its temporal pass leaves (the history's mean): its
// running mean must still converge to the headless render's, with fewer shadow rays per frame
// once the history holds enough samples.
TEST_F(GpuTest, TheViewersShadowRayRouletteKeepsItsRunningMean) {
    const Estimate all = renderHeadless(*ctx, 0.0f, false);
    const Scene scene = manyLightsScene();
    InteractiveRenderer viewer(*ctx, scene, false, 9);
    viewer.resize(kWidth, kHeight);
    ViewSettings vs;
    vs.samplesPerFrame = 8;
    vs.maxBounces = 2;
    vs.shadowRouletteShare = 1.0f;
    std::uint64_t firstFrameRays = 0, lastFrameRays = 0;
    for (std::uint32_t k = 0; k < kSamples / vs.samplesPerFrame; ++k) {
        viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, vs); });
        viewer.finishFrame();
        (k == 0 ? firstFrameRays : lastFrameRays) = viewer.stats().rays;
    }
    ASSERT_EQ(viewer.stats().samplesPerPixel, kSamples);
    const auto history = gpu::downloadBuffer<shader::HistoryTexel>(*ctx, viewer.commands(), viewer.history(),
                                                                    kWidth * kHeight);
    double mean = 0;
    for (const shader::HistoryTexel& h : history) mean += luminance(h.color);
    mean /= double(history.size());
    // The viewer's own standard error is about the headless render's (same samples, a little more
    // variance from the roulette): twice its share of the allowance.
    EXPECT_NEAR(mean, all.image.mean, sidakZ(1e-3, 1) * std::sqrt(3.0) * all.image.stderr);
    // The first frame has no history to scale the roulette by: it traces every shadow ray.
    EXPECT_LT(double(lastFrameRays), 0.95 * double(firstFrameRays));
    std::printf("viewer mean %.5f, headless %.5f (%.5f); rays in the first frame %llu, the last %llu\n", mean,
                all.image.mean, all.image.stderr, static_cast<unsigned long long>(firstFrameRays),
                static_cast<unsigned long long>(lastFrameRays));
}

}  // namespace
}  // namespace penumbra::test
