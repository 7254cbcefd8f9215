// The furnace with spheres in it: spheres of the walls' own material (albedo a, emitting E) leave
// the answer E / (1 - a) in every pixel unchanged, however they are placed. Self-intersection
// on spheres would darken pixels, leaks brighten them, and any error in the sphere lights'
// cone pdf or the MIS weight at sphere hits (every sphere here is also a light) bias them.
#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/presets.h"

namespace penumbra::test {
namespace {

TEST_F(GpuTest, FurnaceWithSpheresStillConvergesToEmissionOverOneMinusAlbedo) {
    const float albedo = 0.7f;
    Scene scene = makeFurnace(albedo, Vec3{1.0f});
    const std::uint32_t wall = 0;
    scene.spheres = {{{0.2f, -0.1f, -0.4f}, 0.3f, wall},    // in the middle of the view
                     {{-0.6f, -0.6f, -0.6f}, 0.35f, wall},  // near a corner
                     {{0.7f, 0.5f, 0.2f}, 0.05f, wall},     // small
                     {{0.0f, 0.8f, -0.5f}, 0.4f, wall},     // cut by the ceiling: partly outside the box
                     {{-0.5f, 0.3f, 0.1f}, 0.002f, wall}};  // tiny
    scene.camera.apertureRadius = 0.05f;  // a thin lens does not change a furnace either
    scene.camera.focusDistance = 0.8f;
    RenderSettings settings;
    settings.width = 16;
    settings.height = 16;
    // 1024, not fewer: the paths that find the small spheres by BSDF sampling are rare and bright,
    // and with a few hundred samples a pixel that drew none has a mean and a standard error both
    // too low, so the normal approximation fails on the low side more often than alpha says.
    settings.samplesPerPixel = 1024;
    settings.samplesPerPass = 16;
    settings.maxBounces = kMaxBounces;
    settings.seed = 5;
    Renderer renderer(*ctx, scene, settings);
    ASSERT_EQ(renderer.sceneArrays().sphereLights.size(), scene.spheres.size());
    renderer.render();
    EXPECT_EQ(renderer.stats().invalidSamples, 0u);

    const double expected = 1.0 / (1.0 - albedo);
    std::vector<Vec4> sums = renderer.accumulation();
    const double z = sidakZ(1e-3, sums.size());
    int bad = 0;
    for (std::size_t i = 0; i < sums.size(); ++i) {
        PixelStats p = pixelStats(sums[i], settings.samplesPerPixel);
        if (std::abs(p.mean - expected) > z * p.stderr + 1e-5 * expected && bad++ < 5)
            ADD_FAILURE() << "pixel " << i << ": " << p.mean << ", expected " << expected << " +- " << z * p.stderr;
    }
    const MeanEstimate image = imageMean(sums, settings.samplesPerPixel);
    EXPECT_NEAR(image.mean, expected, 4.0 * image.stderr);
}

}  // namespace
}  // namespace penumbra::test
