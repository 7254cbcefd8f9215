// The Cornell box at low resolution: finite, deterministic, and consistent between sample
// counts, seeds and acceleration structures within statistical tolerance.
#include <cstdlib>
#include <filesystem>

#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/presets.h"

namespace penumbra::test {
namespace {

RenderSettings smallSettings(std::uint32_t spp, std::uint32_t seed, std::uint32_t size = 32) {
    RenderSettings s;
    s.width = size;
    s.height = size;
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

// A walk's final frames follow a Doom sector's flickering light by updating the material in
// place (render --walk, Renderer::setUnsampledEmission) rather than building a new renderer: the
// two must render the same image, sample for sample. The green wall glows here, found by rays
// only (not light-sampled), as a sector's fill light is.
TEST_F(GpuTest, AnEmissionUpdatedInPlaceRendersAsANewRenderer) {
    Scene before = makeCornellBox();
    constexpr std::uint32_t kGreen = 2;
    ASSERT_EQ(before.materials[kGreen].name, "green");
    before.materials[kGreen].emission = {0.5f, 0.5f, 0.5f};
    before.materials[kGreen].lightSampled = false;
    Scene after = before;
    after.materials[kGreen].emission = {3.0f, 1.5f, 0.25f};

    Renderer updated(*ctx, before, smallSettings(32, 5));
    updated.render();
    const std::vector<Vec4> old = updated.accumulation();
    updated.setUnsampledEmission(kGreen, after.materials[kGreen].emission);
    updated.restart(after.camera);
    updated.render();
    Renderer fresh(*ctx, after, smallSettings(32, 5));
    fresh.render();
    const std::vector<Vec4> a = updated.accumulation(), b = fresh.accumulation();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_NE(std::memcmp(a.data(), old.data(), a.size() * sizeof(Vec4)), 0) << "the new light changed nothing";
    if (ctx->info().type == VK_PHYSICAL_DEVICE_TYPE_CPU) {  // bit for bit on lavapipe; GPUs may round apart
        EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec4)), 0) << "in place and anew differ";
    } else {
        EXPECT_NEAR(imageMean(a, 32).mean, imageMean(b, 32).mean, 1e-4 * imageMean(b, 32).mean);
    }
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

// Every other walk against the binary BVH, with independent seeds: the image means agree within
// their noise.
TEST_F(GpuTest, EveryWalkRendersTheSameCornellBoxAsTheBvh) {
    Scene scene = makeCornellBox();
    RenderSettings settings = smallSettings(64, 3);
    Renderer bvh(*ctx, scene, settings);
    bvh.render();
    const MeanEstimate a = imageMean(bvh.accumulation(), 64);
    for (Accel accel : {Accel::Brute, Accel::Stackless, Accel::Objects, Accel::Wide}) {
        SCOPED_TRACE(accelName(accel));
        settings.accel = accel;
        settings.seed += 1;
        Renderer other(*ctx, scene, settings);
        other.render();
        const MeanEstimate b = imageMean(other.accumulation(), 64);
        const double sigma = std::sqrt(a.stderr * a.stderr + b.stderr * b.stderr);
        EXPECT_NEAR(a.mean, b.mean, 5 * sigma);
        EXPECT_LT(sigma, 0.05 * a.mean) << "the test has too little power to mean anything";
    }
}

// The suzanne preset at a tiny size: finite, lit, and the head shows where it floats (the middle
// of the picture differs from the same room without it, beyond the noise).
TEST_F(GpuTest, SuzanneRendersAndTheHeadShowsInTheMiddle) {
    if (!std::filesystem::exists(suzanneModelPath())) {
        if (std::getenv("CI")) FAIL() << "missing test asset " << suzanneModelPath();
        GTEST_SKIP() << "assimp-testmodels not installed";
    }
    Scene withHead = makePreset("suzanne");
    Scene empty = withHead;
    empty.meshes.pop_back();  // the head is the last mesh
    const std::uint32_t size = 24, spp = 64;
    auto middle = [&](const Scene& scene, std::uint32_t seed) {
        Renderer r(*ctx, scene, smallSettings(spp, seed, size));
        r.render();
        EXPECT_FALSE(r.image().hasNonFinite());
        EXPECT_EQ(r.stats().invalidSamples, 0u);
        const std::vector<Vec4> all = r.accumulation();
        std::vector<Vec4> centre;  // the middle 6 x 6 pixels, all on the head
        for (std::uint32_t y = size / 2 - 3; y < size / 2 + 3; ++y)
            for (std::uint32_t x = size / 2 - 3; x < size / 2 + 3; ++x) centre.push_back(all[y * size + x]);
        return imageMean(centre, spp);
    };
    const MeanEstimate head = middle(withHead, 1), wall = middle(empty, 2);
    const double sigma = std::sqrt(head.stderr * head.stderr + wall.stderr * wall.stderr);
    EXPECT_GT(head.mean, 0.005) << "the head is lit";
    EXPECT_GT(std::abs(head.mean - wall.mean), 5 * sigma) << head.mean << " vs " << wall.mean;
}

}  // namespace
}  // namespace penumbra::test
