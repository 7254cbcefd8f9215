// Editing in the viewer: picking agrees with the G-buffer, a moved sphere moves in the G-buffer,
// a material edit changes the image as it must, and depth-of-field changes restart the mean.
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <vector>

#include "render/interactive_renderer.h"
#include "render/picking.h"
#include "gpu_fixture.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {

using ViewerEditTest = GpuTest;

constexpr std::uint32_t kW = 24, kH = 18;

// A grey wall (mesh 0, material 0) at z = 0 behind a sphere (object 1, material 1) at z = 1,
// under a white sky, seen from z = 5.
Scene wallAndSphere() {
    Scene scene;
    scene.name = "wall and sphere";
    Material wall;
    wall.name = "wall";
    wall.albedo = Vec3{0.8f};
    Material ball;
    ball.name = "ball";
    ball.albedo = Vec3{0.5f, 0.2f, 0.2f};
    scene.materials = {wall, ball};
    Mesh quad;
    quad.name = "wall";
    quad.positions = {{-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    quad.material = 0;
    scene.meshes.push_back(quad);
    scene.spheres.push_back({Vec3{0, 0, 1}, 0.5f, 1});
    scene.background = Vec3{1.0f};
    scene.camera.position = {0, 0, 5};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.fovYDegrees = 40;
    return scene;
}

std::vector<shader::GBufferTexel> renderGBuffer(gpu::Context& ctx, InteractiveRenderer& viewer, const Camera& camera,
                                                const ViewSettings& vs) {
    viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, camera, vs); });
    viewer.finishFrame();
    return gpu::downloadBuffer<shader::GBufferTexel>(ctx, viewer.commands(), viewer.gbuffer(), kW * kH);
}

TEST_F(ViewerEditTest, PickingSeesWhatTheGBufferSees) {
    Scene scene = wallAndSphere();
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    auto g = renderGBuffer(*ctx, viewer, scene.camera, ViewSettings{});
    std::uint32_t sphereHits = 0;
    for (std::uint32_t y = 0; y < kH; ++y)
        for (std::uint32_t x = 0; x < kW; ++x) {
            const Pick pick = pickPixel(viewer.sceneArrays(), scene.camera, kW, kH, float(x) + 0.3f, float(y) + 0.8f);
            const shader::GBufferTexel& t = g[y * kW + x];
            ASSERT_NE(pick.primitive, PN_NO_HIT) << x << "," << y;  // the wall fills the view
            EXPECT_EQ(pick.material + 1, t.surfaceId) << x << "," << y;
            EXPECT_NEAR(pick.depth, t.depth, 1e-4f * t.depth) << x << "," << y;
            sphereHits += pick.object == sphereObject(scene, 0);
        }
    EXPECT_GT(sphereHits, 4u);
    // Known pixels: the centre sees the sphere, a corner the wall.
    EXPECT_EQ(pickPixel(viewer.sceneArrays(), scene.camera, kW, kH, kW / 2, kH / 2).object, sphereObject(scene, 0));
    EXPECT_EQ(pickPixel(viewer.sceneArrays(), scene.camera, kW, kH, 0, 0).object, 0u);
    EXPECT_EQ(objectName(scene, 0), "mesh 'wall'");
}

// The mean image column of the pixels showing material `material`.
double centroidX(const std::vector<shader::GBufferTexel>& g, std::uint32_t material, std::uint32_t& count) {
    double sum = 0;
    count = 0;
    for (std::uint32_t i = 0; i < g.size(); ++i)
        if (g[i].surfaceId == material + 1) {
            sum += double(i % kW) + 0.5;
            ++count;
        }
    return count ? sum / count : -1;
}

TEST_F(ViewerEditTest, MovingTheSphereMovesItInTheGBuffer) {
    Scene scene = wallAndSphere();
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    std::uint32_t before = 0, after = 0;
    const double x0 = centroidX(renderGBuffer(*ctx, viewer, scene.camera, ViewSettings{}), 1, before);
    EXPECT_NEAR(x0, kW / 2.0, 0.01);  // centred (the image is symmetric about its middle column)

    translateObject(scene, sphereObject(scene, 0), Vec3{1, 0, 0});
    EXPECT_EQ(scene.spheres[0].center.x, 1.0f);
    viewer.rebuildScene(scene, false);
    const double x1 = centroidX(renderGBuffer(*ctx, viewer, scene.camera, ViewSettings{}), 1, after);
    // +x is the image's right. The centre projects to 1 / (4 tan(20 deg) aspect) in NDC; the
    // silhouette's centroid is that up to a fraction of a pixel at this size.
    const double aspect = double(kW) / kH;
    const double expected = kW / 2.0 + 0.5 * kW / (4.0 * std::tan(degreesToRadians(20.0)) * aspect);
    EXPECT_NEAR(x1, expected, 0.75) << "before " << x0;
    EXPECT_NEAR(double(after), double(before), 0.25 * before);  // same size, nearly: same depth
    EXPECT_EQ(pickPixel(viewer.sceneArrays(), scene.camera, kW, kH, kW / 2, kH / 2).object, 0u);  // the wall now
}

// Mean radiance over the pixels whose G-buffer shows `material` there and at all 8 neighbours
// (the trace jitters samples over the pixel, so a pixel at a silhouette mixes both surfaces).
double meanOver(const std::vector<shader::HistoryTexel>& h, const std::vector<shader::GBufferTexel>& g,
                std::uint32_t material) {
    double sum = 0;
    std::uint32_t n = 0;
    for (std::uint32_t y = 1; y + 1 < kH; ++y)
        for (std::uint32_t x = 1; x + 1 < kW; ++x) {
            bool interior = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    interior = interior && g[(y + dy) * kW + (x + dx)].surfaceId == material + 1;
            if (!interior) continue;
            sum += luminance(h[y * kW + x].color);
            ++n;
        }
    EXPECT_GT(n, 3u) << "material " << material << " covers too few pixels to judge";
    return n ? sum / n : -1;
}

TEST_F(ViewerEditTest, ABlackWallTurnsBlackAndTheMeanRestarts) {
    Scene scene = wallAndSphere();
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    ViewSettings vs;
    vs.maxBounces = 3;
    auto run = [&](int frames) {
        std::vector<shader::GBufferTexel> g;
        for (int k = 0; k < frames; ++k) g = renderGBuffer(*ctx, viewer, scene.camera, vs);
        return std::pair{gpu::downloadBuffer<shader::HistoryTexel>(*ctx, viewer.commands(), viewer.history(), kW * kH),
                         g};
    };
    auto [h0, g0] = run(2);
    // Under a white sky of radiance 1 the wall's radiance is at most its albedo, and the sphere
    // blocks little of the sky at the wall: well above 0.3.
    const double wallBefore = meanOver(h0, g0, 0);
    EXPECT_GT(wallBefore, 0.3);
    EXPECT_LT(wallBefore, 0.8 + 1e-3);

    Material black = scene.materials[0];
    black.albedo = Vec3{0};
    viewer.setMaterial(0, black);
    auto [h1, g1] = run(1);
    EXPECT_EQ(viewer.stats().samplesPerPixel, 1u);  // the running mean restarted
    // A Lambertian wall of albedo 0 that emits nothing reflects nothing: exactly black.
    EXPECT_EQ(meanOver(h1, g1, 0), 0.0);
    EXPECT_GT(meanOver(h1, g1, 1), 0.0);  // the sphere still shows
}

// The scene is Lambertian, so its kernels leave the coat out; a clear coat put on the black wall
// must bring kernels that have it: a black Lambertian wall would stay exactly black, a coated one
// reflects the white sky by its Fresnel factor (about 0.04 near normal incidence).
TEST_F(ViewerEditTest, ACoatOnALambertianSceneBringsKernelsThatHaveIt) {
    Scene scene = wallAndSphere();
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    EXPECT_FALSE(viewer.kernelSpec().has(PN_FEATURE_GLOSSY));
    ViewSettings vs;
    vs.maxBounces = 3;
    Material coated = scene.materials[0];
    coated.albedo = Vec3{0};
    coated.specular = 1;
    coated.roughness = 0;
    viewer.setMaterial(0, coated);
    EXPECT_TRUE(viewer.kernelSpec().has(PN_FEATURE_GLOSSY));
    std::vector<shader::GBufferTexel> g;
    for (int k = 0; k < 2; ++k) g = renderGBuffer(*ctx, viewer, scene.camera, vs);
    auto h = gpu::downloadBuffer<shader::HistoryTexel>(*ctx, viewer.commands(), viewer.history(), kW * kH);
    const double wall = meanOver(h, g, 0);
    EXPECT_GT(wall, 0.02);
    EXPECT_LT(wall, 0.1);
}

bool sameBytes(const std::vector<shader::GBufferTexel>& a, const std::vector<shader::GBufferTexel>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

// No pixel moved (up to the rounding of projecting a point back through the same camera).
bool stands(const std::vector<shader::GBufferTexel>& g) {
    for (const shader::GBufferTexel& t : g)
        if (std::abs(t.motion.x) > 1e-3f || std::abs(t.motion.y) > 1e-3f) return false;
    return true;
}

// A still view's G-buffer is the same every frame, so once both of the viewer's G-buffers hold it
// the pass is skipped; a moved camera or an edited material traces it again, twice (both letters).
TEST_F(ViewerEditTest, AStillViewReusesItsGBufferUntilSomethingChanges) {
    Scene scene = wallAndSphere();
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    ViewSettings vs;
    vs.maxBounces = 1;
    // The denoiser's guide holds this frame's G-buffer normal and depth (zero where nothing was
    // hit), also in frames that reuse the G-buffer and leave the guide as it was.
    static_assert(sizeof(Vec4) == PN_DENOISE_GUIDE_BYTES);
    auto expectGuideOf = [&](const std::vector<shader::GBufferTexel>& g) {
        const auto guide = gpu::downloadBuffer<Vec4>(*ctx, viewer.commands(), viewer.denoiseGuide(), kW * kH);
        for (std::uint32_t i = 0; i < kW * kH; ++i) {
            const bool hit = g[i].surfaceId != 0;
            ASSERT_EQ(guide[i].x, hit ? g[i].normal.x : 0.0f) << i;
            ASSERT_EQ(guide[i].z, hit ? g[i].normal.z : 0.0f) << i;
            ASSERT_EQ(guide[i].w, hit ? g[i].depth : 0.0f) << i;
        }
    };
    auto frames = [&](const Camera& camera, std::initializer_list<bool> skipped) {
        std::vector<std::vector<shader::GBufferTexel>> out;
        for (bool skip : skipped) {
            out.push_back(renderGBuffer(*ctx, viewer, camera, vs));
            EXPECT_EQ(viewer.stats().gbufferSkipped, skip) << "frame " << out.size();
            expectGuideOf(out.back());
        }
        return out;
    };
    const auto still = frames(scene.camera, {false, false, true, true});
    for (const auto& g : still) {
        EXPECT_TRUE(sameBytes(g, still[0]));
        EXPECT_TRUE(stands(g));
    }
    Camera moved = scene.camera;
    moved.position.x += 0.5f;
    moved.lookAt.x += 0.5f;
    const auto moving = frames(moved, {false});
    EXPECT_FALSE(stands(moving[0])) << "the moved camera's frame has motion vectors";
    const auto settled = frames(moved, {false, false, true});
    EXPECT_TRUE(stands(settled[0]));
    EXPECT_FALSE(sameBytes(settled[0], still[0]));
    EXPECT_TRUE(sameBytes(settled[2], settled[0]));

    Material red = scene.materials[0];
    red.albedo = Vec3{0.6f, 0.1f, 0.1f};
    viewer.setMaterial(0, red);
    const auto edited = frames(moved, {false, false, true});
    std::uint32_t wall = 0;
    for (const shader::GBufferTexel& t : edited[2])
        if (t.surfaceId == 1) {
            EXPECT_NEAR(t.albedo.x, 0.6f, 1e-6f);
            EXPECT_NEAR(t.albedo.y, 0.1f, 1e-6f);
            ++wall;
        }
    EXPECT_GT(wall, 0u);
}

TEST_F(ViewerEditTest, DepthOfFieldChangesRestartTheMean) {
    Scene scene = wallAndSphere();
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    ViewSettings vs;
    vs.maxBounces = 1;
    for (int k = 0; k < 2; ++k) renderGBuffer(*ctx, viewer, scene.camera, vs);
    EXPECT_EQ(viewer.stats().samplesPerPixel, 2u);
    vs.apertureRadius = 0.1f;
    renderGBuffer(*ctx, viewer, scene.camera, vs);
    EXPECT_EQ(viewer.stats().samplesPerPixel, 1u);
    renderGBuffer(*ctx, viewer, scene.camera, vs);
    vs.focusDistance = 4.0f;
    renderGBuffer(*ctx, viewer, scene.camera, vs);
    EXPECT_EQ(viewer.stats().samplesPerPixel, 1u);
}

}  // namespace
}  // namespace penumbra::test
