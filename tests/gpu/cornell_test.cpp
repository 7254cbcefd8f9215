// The Cornell box at low resolution: finite, deterministic, and consistent between sample
// counts, seeds and acceleration structures within statistical tolerance.
#include "gpu_fixture.h"
#include "render/kernel_features.h"
#include "render/renderer.h"
#include "scoped_env.h"
#include "render_helpers.h"
#include "scene/presets/presets.h"

namespace penumbra::test {
namespace {

RenderSettings smallSettings(std::uint32_t spp, std::uint32_t seed) {
    RenderSettings s;
    s.width = 32;
    s.height = 32;
    s.samplesPerPixel = spp;
    s.samplesPerPass = std::min(spp, 16u);
    s.seed = seed;
    return s;
}

TEST_F(GpuTest, CornellIsFiniteAndDeterministicForAFixedSeed) {
    Scene scene = makeCornellBox();
    Renderer a(*ctx, scene, smallSettings(32, 5));
    a.render();
    Renderer b(*ctx, scene, smallSettings(32, 5));
    b.render();
    std::vector<Vec4> sa = a.accumulation(), sb = b.accumulation();
    ASSERT_EQ(sa.size(), sb.size());
    EXPECT_EQ(std::memcmp(sa.data(), sb.data(), sa.size() * sizeof(Vec4)), 0) << "same seed, different image";
    EXPECT_FALSE(a.image().hasNonFinite());
    EXPECT_EQ(a.stats().invalidSamples, 0u);
    EXPECT_GT(luminance(a.image().mean()), 0.01f) << "the box is lit";

    Renderer c(*ctx, scene, smallSettings(32, 6));
    c.render();
    std::vector<Vec4> sc = c.accumulation();
    EXPECT_NE(std::memcmp(sa.data(), sc.data(), sa.size() * sizeof(Vec4)), 0) << "the seed is ignored";
}

TEST_F(GpuTest, CornellMeanAgreesWithHighSampleCountRender) {
    Scene scene = makeCornellBox();
    Renderer low(*ctx, scene, smallSettings(64, 1));
    low.render();
    Renderer high(*ctx, scene, smallSettings(1024, 2));
    high.render();
    MeanEstimate l = imageMean(low.accumulation(), 64), h = imageMean(high.accumulation(), 1024);
    double sigma = std::sqrt(l.stderr * l.stderr + h.stderr * h.stderr);
    EXPECT_NEAR(l.mean, h.mean, 5 * sigma) << "sigma " << sigma;
    EXPECT_LT(sigma, 0.05 * h.mean) << "the test has too little power to mean anything";
}

// The box is Lambertian throughout, so its kernels leave out the glossy lobes, glass, textures
// and the rest; they must render what the kernels that keep everything (PENUMBRA_GENERIC_KERNEL)
// render, to within the noise (the two compilations may round a few operations differently).
TEST_F(GpuTest, TheKernelsMadeForTheCornellBoxRenderWhatTheGenericOnesDo) {
    Scene scene = makeCornellBox();
    Renderer own(*ctx, scene, smallSettings(64, 7));
    own.render();
    EXPECT_EQ(own.kernelFeatures() & (PN_FEATURE_GLOSSY | PN_FEATURE_TRANSMISSION | PN_FEATURE_TEXTURES), 0u)
        << kernelFeatureNames(own.kernelFeatures());
    ScopedEnv generic("PENUMBRA_GENERIC_KERNEL", "1");
    Renderer all(*ctx, scene, smallSettings(64, 7));
    all.render();
    EXPECT_EQ(all.kernelFeatures(), PN_FEATURE_ALL);
    MeanEstimate a = imageMean(own.accumulation(), 64), b = imageMean(all.accumulation(), 64);
    double sigma = std::sqrt(a.stderr * a.stderr + b.stderr * b.stderr);
    EXPECT_NEAR(a.mean, b.mean, 5 * sigma) << "sigma " << sigma;
    EXPECT_LT(sigma, 0.05 * b.mean) << "the test has too little power to mean anything";
}

TEST_F(GpuTest, BruteForceAndBvhRenderTheSameCornellBox) {
    Scene scene = makeCornellBox();
    RenderSettings settings = smallSettings(64, 3);
    Renderer bvh(*ctx, scene, settings);
    bvh.render();
    settings.accel = Accel::Brute;
    settings.seed = 4;
    Renderer brute(*ctx, scene, settings);
    brute.render();
    MeanEstimate a = imageMean(bvh.accumulation(), 64), b = imageMean(brute.accumulation(), 64);
    EXPECT_NEAR(a.mean, b.mean, 5 * std::sqrt(a.stderr * a.stderr + b.stderr * b.stderr));
}

}  // namespace
}  // namespace penumbra::test
