// Known answers rendered with the real tracer: a diffuse floor (albedo a, facing up) under
//  - a uniform environment of radiance 1 (constant background or a uniform map): radiance a,
//  - a non-uniform map: a / pi times the map's irradiance on the plane (exact with the
//    nearest-texel lookup: summed per texel on the CPU),
//  - a sun disk of illuminance E at elevation e: a / pi * E * sin(e). The disk has uniform
//    radiance E / (pi sin^2 alpha); the projected solid angle of a cone of half-angle alpha,
//    wholly above the horizon, is pi sin^2 alpha cos(theta0), so this holds for any alpha,
//  - the procedural sky: a / pi times (sun + sky irradiance),
// each with MIS and with light sampling or BSDF sampling alone (every estimator is unbiased).
#include "env_test_util.h"
#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/environment.h"
#include "scene/io/env_sky.h"

namespace penumbra::test {
namespace {

constexpr float kAlbedo = 0.5f;

using Measured = MeanEstimate;

// Mean luminance over the image and its standard error, plus a per-pixel check that every
// pixel agrees with `expected` (Sidak-corrected over the pixels). BSDF sampling alone finds a
// small bright source a handful of times per pixel: too few for a pixel's variance estimate,
// so in that mode only the image mean (tens of thousands of samples) is checked.
Measured renderFloor(const gpu::Context& ctx, const Scene& scene, std::uint32_t misMode, double expected,
                     std::uint32_t spp = 256) {
    RenderSettings settings;
    settings.width = 12;
    settings.height = 12;
    settings.samplesPerPixel = spp;
    settings.samplesPerPass = 64;
    settings.maxBounces = 1;  // floor, then the sky: nothing else to hit
    settings.seed = 3 + misMode;
    Renderer renderer(ctx, scene, settings);
    // The estimator switch (FrameUniforms.misMode) has no render setting yet: set it in place.
    static_cast<shader::FrameUniforms*>(renderer.frameUniforms().mapped())->misMode = misMode;
    renderer.render();
    EXPECT_EQ(renderer.stats().invalidSamples, 0u);
    std::vector<Vec4> sums = renderer.accumulation();
    const double z = sidakZ(1e-3, sums.size());
    int bad = 0;
    for (std::size_t i = 0; i < sums.size(); ++i) {
        PixelStats p = pixelStats(sums[i], spp);
        const double tolerance = z * p.stderr + 1e-4 * expected;
        if (misMode != PN_MIS_BSDF_ONLY && std::abs(p.mean - expected) > tolerance && bad++ < 3)
            ADD_FAILURE() << "mis mode " << misMode << ", pixel " << i << ": " << p.mean << ", expected " << expected
                          << " +- " << tolerance;
    }
    return imageMean(sums, spp);
}

void expectAllModes(const gpu::Context& ctx, const Scene& scene, double expected, std::uint32_t spp = 256) {
    for (std::uint32_t mode : {PN_MIS_BOTH, PN_MIS_LIGHT_ONLY, PN_MIS_BSDF_ONLY}) {
        Measured m = renderFloor(ctx, scene, mode, expected, spp);
        // Three modes per scene: 3-sigma-ish Sidak bound for the image means.
        EXPECT_NEAR(m.mean, expected, sidakZ(1e-3, 3) * m.stderr + 1e-4 * expected) << "mis mode " << mode;
    }
}

TEST_F(GpuTest, FloorUnderConstantWhiteSkyHasRadianceAlbedo) {
    Scene s = envFloorScene(kAlbedo);
    s.background = Vec3{1.0f};
    expectAllModes(*ctx, s, kAlbedo);
}

TEST_F(GpuTest, FloorUnderUniformMapHasRadianceAlbedo) {
    Scene s = envFloorScene(kAlbedo);
    s.environment.map = EnvironmentMap{"uniform", 8, 4, std::vector<Vec3>(32, Vec3{0.5f})};
    s.environment.intensity = 2.0f;  // radiance 0.5 x 2 = 1
    s.background = Vec3{7.0f};       // ignored when there is a map
    expectAllModes(*ctx, s, kAlbedo);
}

TEST_F(GpuTest, FloorUnderNonUniformMapMatchesItsIrradiance) {
    Scene s = envFloorScene(kAlbedo);
    s.environment.map = spotAndGradientMap();
    s.environment.rotationDegrees = 37.0f;  // turning about +y leaves the plane's irradiance alone
    const double expected = kAlbedo / kPi * luminance(upperIrradiance(*s.environment.map, 1.0f));
    expectAllModes(*ctx, s, expected);
}

Scene sunScene(float elevationDegrees, float radiusDegrees, float illuminance) {
    Scene s = envFloorScene(kAlbedo);
    Light sun;
    sun.type = LightType::Directional;
    const double e = elevationDegrees * kPi / 180;
    sun.direction = -normalize(Vec3{float(std::cos(e) * 0.6), float(std::sin(e)), float(std::cos(e) * 0.8)});
    sun.intensity = illuminance;
    sun.angularRadius = float(radiusDegrees * kPi / 180);
    s.lights.push_back(sun);
    return s;
}

TEST_F(GpuTest, FloorUnderSunDiskHasAlbedoOverPiTimesIlluminanceTimesSinElevation) {
    const double expected = kAlbedo / kPi * 2.0 * std::sin(40 * kPi / 180);
    expectAllModes(*ctx, sunScene(40, 10, 2.0f), expected, 512);
    // The real sun's 0.27 degrees: BSDF sampling would almost never find it, so light sampling
    // and MIS only.
    Scene small = sunScene(40, 0.27f, 2.0f);
    for (std::uint32_t mode : {PN_MIS_BOTH, PN_MIS_LIGHT_ONLY}) {
        Measured m = renderFloor(*ctx, small, mode, expected, 64);
        EXPECT_NEAR(m.mean, expected, 3 * m.stderr + 1e-3 * expected) << "mis mode " << mode;
    }
}

TEST_F(GpuTest, FloorUnderProceduralSkyIsLitBySunAndSky) {
    Scene s = envFloorScene(kAlbedo);
    SkyParams p;
    p.sunElevationDegrees = 35;
    p.width = 64;
    p.height = 32;
    p.sunRadiusDegrees = 3;  // soft enough for the BSDF-only estimator to find
    Sky sky = makeSky(p);
    s.environment.map = sky.map;
    s.environment.sun = sky.sun;
    s.environment.intensity = 1.5f;
    s.environment.rotationDegrees = 80;
    const double sunPart = 1.5 * luminance(sky.sun.color) * sky.sun.intensity * std::sin(35 * kPi / 180);
    const double expected = kAlbedo / kPi * (sunPart + luminance(upperIrradiance(sky.map, 1.5f)));
    expectAllModes(*ctx, s, expected, 512);
}

}  // namespace
}  // namespace penumbra::test
