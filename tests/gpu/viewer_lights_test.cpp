// Caffeine's rows in the viewer: each light slider (scene/light_edit.h, what the panel writes)
// reaches the GPU once the viewer rebuilds the scene, changing the picture as it must; and the
// anti-aliasing toggle puts every camera ray through its pixel's centre, in the viewer and in
// final renders.
#include <cmath>
#include <vector>

#include "gpu_fixture.h"
#include "render/interactive_renderer.h"
#include "render/renderer.h"
#include "scene/light_edit.h"
#include "scene/presets/mesh_builder.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {

using ViewerLightsTest = GpuTest;

constexpr std::uint32_t kW = 32, kH = 24;

// A grey floor (y = 0) seen from 4 m straight above, lit only by `light`; black sky.
Scene floorUnder(const Light& light) {
    Scene scene;
    scene.name = "floor";
    const std::uint32_t grey = addMaterial(scene, "floor", Vec3{0.8f});
    addQuadMesh(scene, "floor", grey, {-8, 0, -8}, {-8, 0, 8}, {8, 0, 8}, {8, 0, -8});
    scene.lights.push_back(light);
    scene.camera.position = {0, 4, 0};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.up = {0, 0, -1};
    scene.camera.fovYDegrees = 60;
    return scene;
}

Light sphereLight() {
    Light l;
    l.name = "bulb";
    l.position = {0, 1, 0};
    l.intensity = 10;
    l.radius = 0.1f;
    return l;
}

// Renders `frames` frames of 16 samples (direct light only) and returns the running mean.
std::vector<Vec3> render(gpu::Context& ctx, InteractiveRenderer& viewer, const Scene& scene, int frames = 4) {
    ViewSettings vs;
    vs.samplesPerFrame = 16;
    vs.maxBounces = 1;
    vs.clampSigma = 0;  // no history clamp: the mean stays linear in the light
    for (int k = 0; k < frames; ++k) {
        viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, vs); });
        viewer.finishFrame();
    }
    std::vector<Vec3> out;
    for (const shader::HistoryTexel& t : gpu::downloadBuffer<shader::HistoryTexel>(ctx, viewer.commands(), viewer.history(), kW * kH))
        out.push_back(t.color);
    return out;
}

// What the panel does with a slider let go: write the values, rebuild, render.
std::vector<Vec3> edited(gpu::Context& ctx, InteractiveRenderer& viewer, Scene& scene, EditableLight light,
                         const LightParams& params) {
    setLightParams(scene, light, params);
    viewer.rebuildScene(scene, false);
    return render(ctx, viewer, scene);
}

// The floor's mean, away from the middle 8 x 8 pixels, where a light right below the camera is
// seen itself (far brighter than the floor, and partly covering pixels at its edge).
double floorMean(const std::vector<Vec3>& image) {
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < image.size(); ++i) {
        const std::uint32_t x = std::uint32_t(i % kW), y = std::uint32_t(i / kW);
        if (x + 4 >= kW / 2 && x < kW / 2 + 4 && y + 4 >= kH / 2 && y < kH / 2 + 4) continue;
        sum += luminance(image[i]);
        ++n;
    }
    return sum / double(n);
}

// The image column of the luminance-weighted centroid.
double centroidX(const std::vector<Vec3>& image) {
    double sum = 0, weight = 0;
    for (std::size_t i = 0; i < image.size(); ++i) {
        sum += luminance(image[i]) * (double(i % kW) + 0.5);
        weight += luminance(image[i]);
    }
    return sum / weight;
}

std::size_t pixelsAbove(const std::vector<Vec3>& image, float threshold) {
    std::size_t n = 0;
    for (Vec3 c : image) n += luminance(c) > threshold;
    return n;
}

TEST_F(ViewerLightsTest, ASphereLightsIntensityColourPositionAndRadiusReachTheGpu) {
    Scene scene = floorUnder(sphereLight());
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    const std::vector<EditableLight> lights = editableLights(scene);
    ASSERT_EQ(lights.size(), 1u);
    EXPECT_EQ(lightName(scene, lights[0]), "sphere light 'bulb'");
    const EditableLight bulb = lights[0];
    const LightParams base = lightParams(scene, bulb);
    const double m0 = floorMean(render(*ctx, viewer, scene));
    ASSERT_GT(m0, 0.0);

    LightParams p = base;
    p.intensity = 2 * base.intensity;  // the floor is lit by the light alone: twice as bright
    EXPECT_NEAR(floorMean(edited(*ctx, viewer, scene, bulb, p)) / m0, 2.0, 0.1);

    p = base;
    p.color = {1, 0, 0};  // only red light: green and blue are exactly black
    double red = 0, other = 0;
    for (Vec3 c : edited(*ctx, viewer, scene, bulb, p)) red += c.x, other += c.y + c.z;
    EXPECT_GT(red, 0.0);
    EXPECT_EQ(other, 0.0);

    p = base;
    const double centred = centroidX(edited(*ctx, viewer, scene, bulb, p));
    p.position = {1.0f, 1, 0};
    const double right = centroidX(edited(*ctx, viewer, scene, bulb, p));
    p.position = {-1.0f, 1, 0};
    const double left = centroidX(edited(*ctx, viewer, scene, bulb, p));
    EXPECT_NEAR(centred, kW / 2.0, 0.5);
    EXPECT_GT(std::abs(right - centred), 2.0);  // the lit patch follows the light, to either side
    EXPECT_NEAR(right - centred, centred - left, 0.5);

    // The camera sees the sphere itself (radiance I / (pi r^2), far above the floor's): a radius
    // twice as large covers about four times the pixels.
    p = base;
    p.radius = 0.3f;
    const std::size_t small = pixelsAbove(edited(*ctx, viewer, scene, bulb, p), 5.0f);
    p.radius = 0.6f;
    const std::size_t large = pixelsAbove(edited(*ctx, viewer, scene, bulb, p), 5.0f);
    EXPECT_GT(small, 0u);
    EXPECT_GT(large, 2 * small) << small << " -> " << large;
}

TEST_F(ViewerLightsTest, ASpotLightsAngleReachesTheGpu) {
    Light spot;
    spot.name = "spot";
    spot.type = LightType::Spot;
    spot.position = {0, 2, 0};
    spot.direction = {0, -1, 0};
    spot.intensity = 20;
    spot.outerConeRadians = degreesToRadians(40.0f);
    spot.innerConeRadians = degreesToRadians(35.0f);
    Scene scene = floorUnder(spot);
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    const EditableLight light = editableLights(scene).at(0);
    LightParams p = lightParams(scene, light);
    ASSERT_TRUE(p.isSpot);
    EXPECT_NEAR(p.spotDegrees, 40.0f, 1e-3f);
    const std::size_t wide = pixelsAbove(render(*ctx, viewer, scene), 1e-3f);
    p.spotDegrees = 15;
    const std::size_t narrow = pixelsAbove(edited(*ctx, viewer, scene, light, p), 1e-3f);
    EXPECT_LE(scene.lights[0].innerConeRadians, scene.lights[0].outerConeRadians);
    // The lit disc's radius goes as tan(angle): (tan 15 / tan 40)^2 = 0.10 of the pixels.
    EXPECT_GT(narrow, 0u);
    EXPECT_LT(double(narrow), 0.3 * double(wide)) << wide << " -> " << narrow;
}

TEST_F(ViewerLightsTest, AnEmissiveSpheresSlidersReachTheGpu) {
    Scene scene = floorUnder(sphereLight());
    scene.lights.clear();
    const std::uint32_t lamp = addMaterial(scene, "lamp", Vec3{0}, {30, 30, 30});
    scene.spheres.push_back({{0, 1, 0}, 0.1f, lamp});
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    const EditableLight light = editableLights(scene).at(0);
    EXPECT_EQ(lightName(scene, light), "'lamp' sphere 0");
    LightParams p = lightParams(scene, light);
    EXPECT_NEAR(p.intensity, 30.0f, 1e-5f);
    const double m0 = floorMean(render(*ctx, viewer, scene));
    p.intensity = 60;
    EXPECT_NEAR(floorMean(edited(*ctx, viewer, scene, light, p)) / m0, 2.0, 0.1);
    EXPECT_EQ(scene.materials[lamp].emission.x, 60.0f);
    p.position = {1.5f, 1, 0};
    const double moved = centroidX(edited(*ctx, viewer, scene, light, p));
    EXPECT_GT(std::abs(moved - kW / 2.0), 2.0);
}

// A black card over the left of a white sky (radiance 1), its edge slanted across the image.
Scene slantedEdge() {
    Scene scene;
    scene.name = "edge";
    const std::uint32_t black = addMaterial(scene, "black", Vec3{0});
    addQuadMesh(scene, "card", black, {-5, -5, 0}, {0.7f, -5, 0}, {-0.3f, 5, 0}, {-5, 5, 0});
    scene.background = Vec3{1.0f};
    scene.camera.position = {0, 0, 3};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.fovYDegrees = 50;
    return scene;
}

// Pixels whose value is strictly between the card's 0 and the sky's 1: the edge's anti-aliasing.
std::size_t inBetween(const std::vector<float>& values) {
    std::size_t n = 0;
    for (float v : values) n += v > 1e-4f && v < 1.0f - 1e-4f;
    return n;
}

TEST_F(ViewerLightsTest, WithoutAntiAliasingEveryPixelIsCardOrSky) {
    const Scene scene = slantedEdge();
    for (bool aa : {true, false}) {
        // The viewer.
        InteractiveRenderer viewer(*ctx, scene, false);
        viewer.resize(kW, kH);
        ViewSettings vs;
        vs.samplesPerFrame = 8;
        vs.antiAliasing = aa;
        for (int k = 0; k < 3; ++k) {
            viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, vs); });
            viewer.finishFrame();
        }
        std::vector<float> shown;
        for (const auto& t : gpu::downloadBuffer<shader::HistoryTexel>(*ctx, viewer.commands(), viewer.history(), kW * kH))
            shown.push_back(luminance(t.color));
        // A final render.
        RenderSettings rs;
        rs.width = kW;
        rs.height = kH;
        rs.samplesPerPixel = 16;
        rs.samplesPerPass = 16;
        rs.pixelJitter = aa;
        Renderer renderer(*ctx, scene, rs);
        renderer.render();
        std::vector<float> rendered;
        for (const Vec4& s : renderer.accumulation()) rendered.push_back(luminance(Vec3{s.x, s.y, s.z}) / 16.0f);
        if (aa) {
            EXPECT_GE(inBetween(shown), kH / 2) << "the edge crosses every row";
            EXPECT_GE(inBetween(rendered), kH / 2);
        } else {
            EXPECT_EQ(inBetween(shown), 0u);
            EXPECT_EQ(inBetween(rendered), 0u);
        }
    }
}

}  // namespace
}  // namespace penumbra::test
