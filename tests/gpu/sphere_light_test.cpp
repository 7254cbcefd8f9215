// Sphere lights against analytic answers. A uniform sphere of radiance L, radius r, centre at
// distance d and angle beta from a surface's normal, wholly above the horizon, gives irradiance
// E = pi L (r/d)^2 cos(beta); a diffuse surface of albedo a then reflects radiance a L (r/d)^2
// cos(beta). Light sampling, BSDF sampling and their MIS combination must all converge to it.
#include <cstring>

#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/mesh_builder.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {

constexpr float kAlbedo = 0.5f;

// A large diffuse floor at y = 0; the camera looks at the origin from `eye` with a field of
// view so narrow that every pixel sees (almost exactly) the origin.
Scene floorScene(Vec3 eye, float fovDegrees = 0.2f) { return diffuseFloorScene(kAlbedo, eye, {0, 1, 0}, fovDegrees); }

void addSphereLight(Scene& s, Vec3 centre, float radius, Vec3 radiance) {
    std::uint32_t lamp = addMaterial(s, "lamp", Vec3{0}, radiance);
    s.spheres.push_back({centre, radius, lamp});
}

using Estimate = MeanEstimate;  // the image's mean luminance and its standard error

Estimate renderMean(const gpu::Context& ctx, const Scene& scene, std::uint32_t spp, std::uint32_t misMode,
                    std::uint32_t seed, std::uint32_t side = 8) {
    RenderSettings settings;
    settings.width = side;
    settings.height = side;
    settings.samplesPerPixel = spp;
    settings.samplesPerPass = std::min<std::uint32_t>(spp, 64);
    settings.maxBounces = 1;  // direct light only: the floor cannot light itself
    settings.seed = seed;
    Renderer r(ctx, scene, settings);
    // The estimator switch is a frame constant with no user-facing setting; the uniform buffer
    // is host visible and coherent, so the test sets it in place.
    auto* frame = static_cast<shader::FrameUniforms*>(r.frameUniforms().mapped());
    frame->misMode = misMode;
    r.render();
    EXPECT_EQ(r.stats().invalidSamples, 0u);
    return imageMean(r.accumulation(), settings.samplesPerPixel);
}

// Within z standard errors, plus 0.2% for the pixels' footprint around the origin and rounding.
void expectNear(Estimate got, double expected, const char* what) {
    const double z = sidakZ(1e-4, 1);
    EXPECT_NEAR(got.mean, expected, z * got.stderr + 2e-3 * expected) << what << " (stderr " << got.stderr << ")";
}

TEST_F(GpuTest, SphereLightStraightAboveGivesPiLRSquaredOverDSquared) {
    const float r = 0.25f, d = 1.0f, L = 4.0f;
    Scene s = floorScene({2, 1, 0});  // the camera ray passes 0.89 m from the light's centre
    addSphereLight(s, {0, d, 0}, r, Vec3{L});
    const double expected = kAlbedo * L * (r / d) * (r / d);
    expectNear(renderMean(*ctx, s, 256, PN_MIS_BOTH, 1), expected, "MIS");
    expectNear(renderMean(*ctx, s, 256, PN_MIS_LIGHT_ONLY, 2), expected, "light sampling only");
}

TEST_F(GpuTest, TiltedSphereLightGivesIrradianceTimesCosine) {
    const float r = 0.3f, d = 1.5f, L = 5.0f;
    const float beta = 50.0f * float(kPi) / 180.0f;  // 50 + asin(0.2) = 61.5 degrees: above the horizon
    Scene s = floorScene({-2, 1, 0.3f});
    addSphereLight(s, {d * std::sin(beta), d * std::cos(beta), 0}, r, Vec3{L});
    const double expected = kAlbedo * L * (r / d) * (r / d) * std::cos(beta);
    expectNear(renderMean(*ctx, s, 256, PN_MIS_BOTH, 3), expected, "MIS");
    expectNear(renderMean(*ctx, s, 256, PN_MIS_LIGHT_ONLY, 4), expected, "light sampling only");
}

// The same mean with sphere-light sampling on (MIS or alone) and off (BSDF-sampled hits only),
// over a wide view of the floor beside a large light that hangs just above it, where its cone
// is wide and changes from pixel to pixel: there the two pdfs are comparable, so both halves of
// each MIS weight (and the pdf a BSDF-sampled hit computes) matter. The light itself is out of
// view, so every pixel's value is estimated.
TEST_F(GpuTest, SphereLightMisAgreesWithEachEstimatorAlone) {
    Scene s = floorScene({1.5f, 1.0f, 0.0f}, 40.0f);
    s.camera.lookAt = {1.0f, 0, 0};
    addSphereLight(s, {0, 0.8f, 0}, 0.7f, Vec3{2.0f});
    Estimate both = renderMean(*ctx, s, 256, PN_MIS_BOTH, 5, 16);
    Estimate bsdf = renderMean(*ctx, s, 1024, PN_MIS_BSDF_ONLY, 6, 16);
    Estimate light = renderMean(*ctx, s, 256, PN_MIS_LIGHT_ONLY, 7, 16);
    const double z = sidakZ(1e-4, 2);
    EXPECT_GT(both.mean, 0.02);
    EXPECT_NEAR(bsdf.mean, both.mean, z * std::hypot(bsdf.stderr, both.stderr));
    EXPECT_NEAR(light.mean, both.mean, z * std::hypot(light.stderr, both.stderr));
    // MIS should not be noisier than BSDF sampling alone at equal sample counts (here 1/4 of them).
    EXPECT_LT(both.stderr, 2 * bsdf.stderr);
}

// A point light with a radius is an emissive sphere of radiance I / (pi r^2): from a point
// wholly outside it, exactly the point light's irradiance I / d^2.
TEST_F(GpuTest, PointLightWithRadiusMatchesThePointLight) {
    Scene s = floorScene({2, 1, 0});
    Light l;
    l.position = {0, 2, 0};
    l.intensity = 8.0f;
    l.color = {1.0f, 0.5f, 0.25f};
    l.radius = 0.4f;
    s.lights.push_back(l);
    const double expected = kAlbedo / kPi * 8.0 * luminance(l.color) / 4.0;
    expectNear(renderMean(*ctx, s, 256, PN_MIS_BOTH, 8), expected, "soft point light");
    expectNear(renderMean(*ctx, s, 1024, PN_MIS_BSDF_ONLY, 9), expected, "soft point light, BSDF hits only");
}

// A spot light with a radius is lit on its axis as the spot light, dark outside its cone, and,
// having no geometry, still reaches the surface when light sampling is the BSDF-only mode's only
// way to it.
TEST_F(GpuTest, SpotLightWithRadiusMatchesTheSpotLightOnItsAxis) {
    Scene s = floorScene({2, 1, 0});
    Light l;
    l.type = LightType::Spot;
    l.position = {0, 2, 0};
    l.intensity = 8.0f;
    l.direction = {0, -1, 0};
    l.innerConeRadians = 0.3f;
    l.outerConeRadians = 0.4f;
    l.radius = 0.2f;
    s.lights.push_back(l);
    const double expected = kAlbedo / kPi * 8.0 / 4.0;
    expectNear(renderMean(*ctx, s, 128, PN_MIS_BOTH, 10), expected, "soft spot light");
    expectNear(renderMean(*ctx, s, 128, PN_MIS_BSDF_ONLY, 11), expected, "soft spot light, BSDF-only mode");
    s.lights[0].direction = normalize(Vec3{1, -1, 0});  // 45 degrees away: outside the cone
    EXPECT_NEAR(renderMean(*ctx, s, 16, PN_MIS_BOTH, 12).mean, 0.0, 1e-7);
}

TEST_F(GpuTest, EmissiveSphereSeenDirectlyHasItsRadiance) {
    Scene s = floorScene({0, 1, 3}, 2.0f);
    s.camera.lookAt = {0, 1, 0};
    addSphereLight(s, {0, 1, 0}, 0.5f, Vec3{3.0f});
    Estimate e = renderMean(*ctx, s, 4, PN_MIS_BOTH, 13);
    EXPECT_NEAR(e.mean, 3.0, 1e-5);
}

}  // namespace
}  // namespace penumbra::test
