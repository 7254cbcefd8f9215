// The three direct-light estimators (light sampling only, BSDF sampling only, both with the power
// heuristic) are each unbiased, so they must converge to the same image; MIS exists because the
// combination has lower variance than either alone where one of them is poor: a small bright
// light over a diffuse floor (BSDF sampling rarely hits it) and a large light seen in a glossy
// floor (light sampling rarely lands in the narrow lobe).
#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/mesh_builder.h"

namespace penumbra::test {
namespace {

Scene misScene() {
    Scene scene;
    scene.name = "mis";
    std::uint32_t diffuse = addMaterial(scene, "diffuse", Vec3{0.6f});
    std::uint32_t glossy = addMaterial(scene, "glossy", Vec3{0.9f, 0.8f, 0.7f});
    scene.materials[glossy].metallic = 1.0f;
    scene.materials[glossy].roughness = 0.25f;
    std::uint32_t small = addMaterial(scene, "small-light", Vec3{0.0f}, Vec3{300.0f, 250.0f, 200.0f});
    std::uint32_t large = addMaterial(scene, "large-light", Vec3{0.0f}, Vec3{1.0f, 1.2f, 1.5f});
    auto quad = [&](std::uint32_t material, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
        addQuadMesh(scene, scene.materials[material].name, material, a, b, c, d);
    };
    // Floor at y = 0, facing up: glossy on the left half, diffuse on the right.
    quad(glossy, {-2, 0, 1}, {0, 0, 1}, {0, 0, -3}, {-2, 0, -3});
    quad(diffuse, {0, 0, 1}, {2, 0, 1}, {2, 0, -3}, {0, 0, -3});
    // A large dim panel and a small bright triangle, both facing down.
    quad(large, {-2, 2, -3}, {2, 2, -3}, {2, 2, -1}, {-2, 2, -1});
    Mesh tri;
    tri.name = "small-light";
    tri.material = small;
    tri.positions = {{0.8f, 1.0f, -1.0f}, {0.9f, 1.0f, -1.0f}, {0.85f, 1.0f, -1.1f}};
    tri.indices = {0, 2, 1};  // counter-clockwise seen from below
    scene.meshes.push_back(tri);
    scene.camera.position = {0, 1.0f, 2.5f};
    scene.camera.lookAt = {0, 0, -1.0f};
    scene.camera.fovYDegrees = 50.0f;
    return scene;
}

struct Estimate {
    double mean;      // image mean luminance
    double stderr;    // its standard error
    double variance;  // mean per-sample variance over pixels: what MIS should lower
};

Estimate render(const gpu::Context& ctx, MisMode mode, Scene scene = misScene()) {
    RenderSettings s;
    s.width = 24;
    s.height = 18;
    s.samplesPerPixel = 256;
    s.samplesPerPass = 32;
    s.maxBounces = 2;
    s.seed = 21 + std::uint32_t(mode);
    s.mis = mode;
    Renderer renderer(ctx, std::move(scene), s);
    renderer.render();
    EXPECT_EQ(renderer.stats().invalidSamples, 0u);
    std::vector<Vec4> sums = renderer.accumulation();
    const MeanEstimate image = imageMean(sums, s.samplesPerPixel);
    // The pixels' squared standard errors sum to (n stderr)^2; each is a per-sample variance
    // over the sample count.
    const double n = double(sums.size());
    return {image.mean, image.stderr, image.stderr * image.stderr * n * s.samplesPerPixel};
}

TEST_F(GpuTest, MisModesConvergeToTheSameImageAndBothHasTheLowestVariance) {
    const Estimate both = render(*ctx, MisMode::Both);
    const Estimate light = render(*ctx, MisMode::LightOnly);
    const Estimate bsdf = render(*ctx, MisMode::BsdfOnly);
    ASSERT_GT(both.mean, 0.05) << "the scene is lit";
    const double z = sidakZ(1e-3, 3);
    auto agree = [&](const Estimate& a, const Estimate& b, const char* what) {
        EXPECT_NEAR(a.mean, b.mean, z * std::hypot(a.stderr, b.stderr)) << what;
    };
    agree(both, light, "MIS vs light sampling only");
    agree(both, bsdf, "MIS vs BSDF sampling only");
    agree(light, bsdf, "light sampling only vs BSDF sampling only");
    EXPECT_LT(both.variance, light.variance) << "MIS should beat light sampling on the glossy floor";
    EXPECT_LT(both.variance, bsdf.variance) << "MIS should beat BSDF sampling for the small light";
    std::printf("mean luminance (stderr), per-sample variance: both %.5f (%.5f) %.4f, light %.5f (%.5f) %.4f, "
                "bsdf %.5f (%.5f) %.4f\n",
                both.mean, both.stderr, both.variance, light.mean, light.stderr, light.variance, bsdf.mean,
                bsdf.stderr, bsdf.variance);
}

// An emitter that light sampling leaves out (Material::lightSampled false, as Doom's fill light)
// is found by BSDF-sampled rays alone, with MIS weight 1 at every mode: the image is the same.
TEST_F(GpuTest, AnEmitterLeftOutOfLightSamplingLightsTheSameImage) {
    Scene unsampled = misScene();
    for (Material& m : unsampled.materials)
        if (m.name == "large-light") m.lightSampled = false;
    const Estimate both = render(*ctx, MisMode::Both);
    const double z = sidakZ(1e-3, 2);
    for (MisMode mode : {MisMode::Both, MisMode::LightOnly}) {
        const Estimate e = render(*ctx, mode, unsampled);
        EXPECT_NEAR(e.mean, both.mean, z * std::hypot(e.stderr, both.stderr)) << "mode " << int(mode);
    }
}

}  // namespace
}  // namespace penumbra::test
