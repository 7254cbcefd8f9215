// The furnace: inside a closed box whose walls all have albedo a and emit E, the radiance in
// every direction is E / (1 - a). Any bias in the integrator (double-counted light, a wrong pdf,
// biased Russian roulette, a truncated path) shows up as a wrong pixel.
#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/presets.h"

namespace penumbra::test {
namespace {

struct FurnaceCase {
    float albedo;
    Vec3 emission;
};

class FurnaceTest : public GpuTest, public ::testing::WithParamInterface<FurnaceCase> {};

TEST_P(FurnaceTest, EveryPixelConvergesToEmissionOverOneMinusAlbedo) {
    const FurnaceCase c = GetParam();
    RenderSettings settings;
    settings.width = 24;
    settings.height = 24;
    settings.samplesPerPixel = 512;
    settings.samplesPerPass = 16;
    settings.maxBounces = kMaxBounces;  // paths end by Russian roulette, not by the cap
    settings.seed = 11;
    Renderer renderer(*ctx, makeFurnace(c.albedo, c.emission), settings);
    renderer.render();
    EXPECT_EQ(renderer.stats().invalidSamples, 0u);

    const double expected = luminance(c.emission) / (1.0 - c.albedo);
    ImageRgb image = renderer.image();
    ASSERT_FALSE(image.hasNonFinite());
    EXPECT_NEAR(luminance(image.mean()), expected, 0.01 * expected);

    std::vector<Vec4> sums = renderer.accumulation();
    const double z = sidakZ(1e-3, sums.size());
    int bad = 0;
    for (std::size_t i = 0; i < sums.size(); ++i) {
        PixelStats p = pixelStats(sums[i], settings.samplesPerPixel);
        double tolerance = z * p.stderr + 1e-5 * expected;
        if (std::abs(p.mean - expected) > tolerance && bad++ < 5)
            ADD_FAILURE() << "pixel " << i << ": " << p.mean << ", expected " << expected << " +- " << tolerance;
    }
    // Colour is carried per channel: each channel converges to its own E / (1 - a).
    Vec3 mean = image.mean();
    for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(mean[ch], c.emission[ch] / (1.0 - c.albedo), 0.01 * c.emission[ch] / (1.0 - c.albedo) + 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Albedos, FurnaceTest,
                         ::testing::Values(FurnaceCase{0.0f, Vec3{1.0f}}, FurnaceCase{0.5f, Vec3{1.0f}},
                                           FurnaceCase{0.8f, Vec3{0.5f, 1.0f, 2.0f}}, FurnaceCase{0.9f, Vec3{1.0f}}),
                         [](const ::testing::TestParamInfo<FurnaceCase>& param) {
                             return "albedo" + std::to_string(int(param.param.albedo * 100 + 0.5f)) + "_case" +
                                    std::to_string(param.index);
                         });

}  // namespace
}  // namespace penumbra::test
