// The viewer's fast preview (ViewSettings::preview): while the view moves, a frame shows each
// pixel's primary hit shaded by its albedo times the cosine between its normal and the ray, with
// no path tracing; at rest path tracing resumes with a fresh mean. The reference is worked out on
// the CPU from the scene itself: the pick under each pixel centre, the hit material's albedo and
// the floor's or the sphere's own normal.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "gpu_fixture.h"
#include "render/interactive_renderer.h"
#include "render/picking.h"
#include "scene/presets/mesh_builder.h"
#include "shared/color.h"

namespace penumbra::test {
namespace {

using ViewerPreviewTest = GpuTest;

constexpr std::uint32_t kW = 40, kH = 30;
const Vec3 kFloorAlbedo{0.8f, 0.5f, 0.2f}, kBallAlbedo{0.2f, 0.6f, 0.9f};
const Vec3 kBallCentre{0, 0.5f, 0};
constexpr float kBallRadius = 0.5f;

// A coloured floor and ball under a white sky, seen at a slant.
Scene floorAndBall() {
    Scene scene;
    scene.name = "floor and ball";
    const std::uint32_t floor = addMaterial(scene, "floor", kFloorAlbedo);
    const std::uint32_t ball = addMaterial(scene, "ball", kBallAlbedo);
    addQuadMesh(scene, "floor", floor, {-3, 0, -3}, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3});
    scene.spheres.push_back({kBallCentre, kBallRadius, ball});
    scene.background = Vec3{1.0f};
    scene.camera.position = {0.4f, 1.6f, 2.6f};
    scene.camera.lookAt = {0, 0.3f, 0};
    scene.camera.fovYDegrees = 55;
    return scene;
}

std::uint32_t srgb8(float linear) { return std::uint32_t(shader::linearToSrgb(std::clamp(linear, 0.0f, 1.0f)) * 255.0f + 0.5f); }

// The preview's pixel as the CPU works it out (RGBA8 channels), or black where nothing is hit.
std::array<std::uint32_t, 3> expectedPixel(const Scene& scene, const SceneArrays& arrays, const Camera& camera,
                                           std::uint32_t x, std::uint32_t y) {
    const Pick pick = pickPixel(arrays, camera, kW, kH, float(x) + 0.5f, float(y) + 0.5f);
    if (pick.primitive == PN_NO_HIT) return {0, 0, 0};
    const Vec3 dir = pixelRayDirection(camera, kW, kH, float(x) + 0.5f, float(y) + 0.5f);
    const Vec3 forward = normalize(camera.lookAt - camera.position);
    const Vec3 hit = camera.position + dir * (pick.depth / dot(dir, forward));
    const bool ball = pick.object == sphereObject(scene, 0);
    const Vec3 normal = ball ? normalize(hit - kBallCentre) : Vec3{0, 1, 0};
    const Vec3 c = (ball ? kBallAlbedo : kFloorAlbedo) * std::abs(dot(normal, dir));
    return {srgb8(c.x), srgb8(c.y), srgb8(c.z)};
}

std::vector<std::uint32_t> frame(gpu::Context& ctx, InteractiveRenderer& viewer, const Camera& camera,
                                 const ViewSettings& vs) {
    viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, camera, vs); });
    viewer.finishFrame();
    return gpu::downloadBuffer<std::uint32_t>(ctx, viewer.commands(), viewer.display(), kW * kH);
}

TEST_F(ViewerPreviewTest, MovingShowsAlbedoTimesCosineAndAtRestPathTracingResumes) {
    const Scene scene = floorAndBall();
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    ViewSettings vs;
    vs.preview = true;
    Camera camera = scene.camera;
    frame(*ctx, viewer, camera, vs);  // the first frame: nothing moved yet, path traced
    EXPECT_EQ(viewer.stats().samplesPerPixel, 1u);

    camera.position = camera.position + Vec3{0.05f, 0, 0};  // the view moves: a preview frame
    const std::vector<std::uint32_t> preview = frame(*ctx, viewer, camera, vs);
    EXPECT_EQ(viewer.stats().samplesPerPixel, 0u);
    EXPECT_EQ(viewer.stats().passMilliseconds[std::size_t(ViewerPass::Trace)], 0.0) << "nothing traced";
    std::uint32_t ballPixels = 0, skyPixels = 0, worst = 0;
    for (std::uint32_t y = 0; y < kH; ++y)
        for (std::uint32_t x = 0; x < kW; ++x) {
            const auto expected = expectedPixel(scene, viewer.sceneArrays(), camera, x, y);
            const std::uint32_t got = preview[y * kW + x];
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t byte = (got >> (8 * c)) & 0xffu;
                worst = std::max(worst, byte > expected[c] ? byte - expected[c] : expected[c] - byte);
            }
            const Pick pick = pickPixel(viewer.sceneArrays(), camera, kW, kH, float(x) + 0.5f, float(y) + 0.5f);
            ballPixels += pick.object == sphereObject(scene, 0);
            skyPixels += pick.primitive == PN_NO_HIT;
        }
    EXPECT_LE(worst, 1u) << "8-bit steps between the preview and albedo x cosine";
    EXPECT_GT(ballPixels, 20u);
    EXPECT_GT(skyPixels, 20u);

    // At rest (the same camera again): path tracing resumes from a fresh mean, and the white sky
    // (black in the preview) shows.
    const std::vector<std::uint32_t> rest = frame(*ctx, viewer, camera, vs);
    EXPECT_EQ(viewer.stats().samplesPerPixel, 1u);
    EXPECT_GT(viewer.stats().passMilliseconds[std::size_t(ViewerPass::Trace)], 0.0);
    std::uint32_t brightSky = 0;
    for (std::uint32_t y = 0; y < kH; ++y)
        for (std::uint32_t x = 0; x < kW; ++x)
            if (pickPixel(viewer.sceneArrays(), camera, kW, kH, float(x) + 0.5f, float(y) + 0.5f).primitive == PN_NO_HIT)
                brightSky += (rest[y * kW + x] & 0xffu) > 150u && (preview[y * kW + x] & 0xffu) == 0u;
    // (A jittered sample at the horizon may land on the floor: nearly all, not all.)
    EXPECT_GE(brightSky, skyPixels * 95 / 100) << skyPixels;

    // Without the preview, a moving view is path traced.
    vs.preview = false;
    camera.position = camera.position + Vec3{0.05f, 0, 0};
    frame(*ctx, viewer, camera, vs);
    EXPECT_GT(viewer.stats().passMilliseconds[std::size_t(ViewerPass::Trace)], 0.0);
}

}  // namespace
}  // namespace penumbra::test
