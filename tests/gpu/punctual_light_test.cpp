// Punctual lights against analytic answers, and the split of light samples between punctual and
// triangle lights (lighting is additive, so rendering both must equal the sum of each alone).
#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/mesh_builder.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {

constexpr float kAlbedo = 0.5f;

// A large diffuse floor at y = 0 seen straight down from above; the 1-degree field of view makes
// the whole image see the point under the camera.
Scene floorScene() { return diffuseFloorScene(kAlbedo, {0, 3, 0}, {0, 0, -1}, 1.0f); }

Vec3 centre(const gpu::Context& ctx, const Scene& scene) {
    Renderer r(ctx, scene, testSettings(8, 8, 16, 1));
    r.render();
    EXPECT_EQ(r.stats().invalidSamples, 0u);
    return r.image().mean();
}

TEST_F(GpuTest, PointLightGivesAlbedoTimesIntensityOverPiDistanceSquared) {
    Scene s = floorScene();
    Light l;
    l.position = {0, 2, 0};
    l.intensity = 8.0f;
    l.color = {1.0f, 0.5f, 0.25f};
    s.lights.push_back(l);
    Vec3 got = centre(*ctx, s);
    // L = (albedo / pi) * I * cos / d^2 with cos = 1, d = 2.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], kAlbedo / kPiF * 8.0f * l.color[c] / 4.0f, 1e-3f);
}

TEST_F(GpuTest, SpotLightIsDarkOutsideItsConeAndFullInside) {
    Scene s = floorScene();
    Light l;
    l.type = LightType::Spot;
    l.position = {0, 2, 0};
    l.intensity = 8.0f;
    l.direction = {0, -1, 0};
    l.innerConeRadians = 0.3f;
    l.outerConeRadians = 0.4f;
    s.lights.push_back(l);
    EXPECT_NEAR(luminance(centre(*ctx, s)), kAlbedo / kPiF * 8.0f / 4.0f, 1e-3f);
    s.lights[0].direction = normalize(Vec3{1, -1, 0});  // 45 degrees away: outside the cone
    EXPECT_NEAR(luminance(centre(*ctx, s)), 0.0f, 1e-6f);
}

TEST_F(GpuTest, DirectionalLightGivesAlbedoTimesIrradianceOverPi) {
    Scene s = floorScene();
    Light l;
    l.type = LightType::Directional;
    l.direction = normalize(Vec3{0, -1, 1});  // 45 degrees: cos = 0.7071
    l.intensity = 2.0f;
    s.lights.push_back(l);
    EXPECT_NEAR(luminance(centre(*ctx, s)), kAlbedo / kPiF * 2.0f * 0.70710678f, 1e-3f);
}

TEST_F(GpuTest, PunctualAndTriangleLightsAddUp) {
    Scene tri = floorScene();
    tri.camera.fovYDegrees = 60.0f;
    std::uint32_t lamp = addMaterial(tri, "lamp", Vec3{0}, Vec3{4.0f});
    Mesh panel;
    panel.name = "panel";
    panel.material = lamp;
    addQuad(panel, {1, 1, -1}, {1, 1, 1}, {2, 1, 1}, {2, 1, -1});  // faces down
    tri.meshes.push_back(panel);
    Scene point = floorScene();
    point.camera = tri.camera;
    Light l;
    l.position = {-1, 1.5f, 0};
    l.intensity = 3.0f;
    point.lights.push_back(l);
    Scene both = tri;
    both.lights = point.lights;

    RenderSettings settings = testSettings(16, 16, 256, 1);
    auto meanOf = [&](const Scene& scene, std::uint32_t seed) {
        settings.seed = seed;
        Renderer r(*ctx, scene, settings);
        r.render();
        const MeanEstimate image = imageMean(r.accumulation(), settings.samplesPerPixel);
        return std::pair{image.mean, image.stderr};
    };
    auto [a, sa] = meanOf(tri, 1);
    auto [b, sb] = meanOf(point, 2);
    auto [c, sc] = meanOf(both, 3);
    EXPECT_GT(a, 0.01);
    EXPECT_GT(b, 0.01);
    EXPECT_NEAR(c, a + b, 5 * std::sqrt(sa * sa + sb * sb + sc * sc));
}

}  // namespace
}  // namespace penumbra::test
