// The sphere-light sampler (lib/sphere_lights.glsl, through shaders/test/sphere_light_sample.comp):
// directions uniform over the subtended cone (chi-square), samples on the visible side of the
// sphere with the stated pdf, and the inside fallback. (Which light is picked: light_pick_test.cpp.)
#include <cstring>

#include "bvh/sphere.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "render/frame_uniforms.h"
#include "render/scene_pipeline.h"
#include "render_helpers.h"
#include "scene/presets/mesh_builder.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {


struct LightSampleRecord {
    Vec3 wi;
    float pdf;
    Vec3 position;
    float radiance;  // luminance
};

Scene lightsScene(const std::vector<Sphere>& spheres, const std::vector<Vec3>& radiance) {
    Scene s;
    s.name = "sphere lights";
    addMaterial(s, "unused", Vec3{0.5f});
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        Sphere sphere = spheres[i];
        sphere.material = addMaterial(s, "lamp" + std::to_string(i), Vec3{0}, radiance[i]);
        s.spheres.push_back(sphere);
    }
    return s;
}

// `perPoint` samples from each of `points`.
std::vector<LightSampleRecord> drawSamples(const gpu::Context& ctx, const Scene& scene, const std::vector<Vec3>& points,
                                           std::uint32_t perPoint) {
    SceneArrays arrays = buildSceneArrays(scene);
    gpu::Commands commands(ctx);
    GpuScene gpuScene(ctx, commands, arrays);
    shader::FrameUniforms frame = makeFrameUniforms(Camera{}, Vec3{0}, RenderSettings{}, gpuScene.lightNodeCount,
                                                    gpuScene.triCount, gpuScene.nodeCount);
    frame.sphereLightCount = gpuScene.sphereLightCount;
    frame.seed = 7;
    gpu::Buffer frameBuffer(ctx, sizeof(frame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryKind::HostVisible);
    std::memcpy(frameBuffer.mapped(), &frame, sizeof(frame));
    std::vector<shader::RayDesc> rays;
    for (Vec3 p : points) rays.push_back({p, 0, Vec3{0, 0, 1}, 0});
    const std::size_t count = points.size() * perPoint;
    gpu::Buffer pointBuffer = gpu::uploadStorageBuffer<shader::RayDesc>(ctx, commands, rays);
    gpu::Buffer out(ctx, count * sizeof(LightSampleRecord), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                    gpu::MemoryKind::DeviceLocal);
    auto pipeline = makeScenePipeline(ctx, "test_sphere_light_sample", gpuScene, frameBuffer, {PN_BINDING_SCRATCH, PN_BINDING_SCRATCH2});
    pipeline->bind(PN_BINDING_SCRATCH, pointBuffer);
    pipeline->bind(PN_BINDING_SCRATCH2, out);
    shader::PassPush push{0, perPoint, static_cast<std::uint32_t>(count), 0};
    commands.run([&](VkCommandBuffer cmd) {
        pipeline->dispatch(cmd, static_cast<std::uint32_t>((count + PN_LINEAR_GROUP - 1) / PN_LINEAR_GROUP), 1, 1, &push);
        gpu::computeBarrier(cmd);
    });
    return gpu::downloadBuffer<LightSampleRecord>(ctx, commands, out, count);
}

// Upper critical value of chi-square with k degrees of freedom at false-alarm rate alpha
// (Wilson-Hilferty), Sidak-corrected over `tests`.
double chiSquareLimit(double k, double alpha, std::size_t tests) {
    const double z = sidakZ(alpha, tests);
    const double a = 2.0 / (9.0 * k);
    return k * std::pow(1 - a + z * std::sqrt(a), 3);
}

// From p toward a sphere (centre c, radius r): every sample is on the sphere's visible side,
// the pdf is 1 / (2 pi (1 - cos theta_max)), and (1 - cos theta) / (1 - cos theta_max) and the
// azimuth about the axis are jointly uniform.
void checkCone(const gpu::Context& ctx, Vec3 p, Vec3 c, float r, std::size_t tests) {
    const std::uint32_t n = 100000;
    auto samples = drawSamples(ctx, lightsScene({{c, r, 0}}, {Vec3{3.0f}}), {p}, n);
    const double dc = length(c - p);
    const double sin2Max = double(r) * r / (dc * dc);
    const double oneMinusCosMax = sin2Max / (1 + std::sqrt(1 - sin2Max));
    const double pdf = 1.0 / (2 * kPi * oneMinusCosMax);
    Vec3 axis = normalize(c - p), t = normalize(cross(axis, std::abs(axis.x) < 0.9f ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    Vec3 b = cross(axis, t);
    constexpr int kBins = 10;
    std::vector<double> counts(kBins * kBins, 0.0);
    const shader::TriVerts sphere = bvh::toSphereVerts(c, r);
    for (std::uint32_t i = 0; i < n; ++i) {
        const LightSampleRecord& s = samples[i];
        ASSERT_NEAR(s.pdf, pdf, 1e-4 * pdf) << "sample " << i;
        ASSERT_FLOAT_EQ(s.radiance, 3.0f);
        ASSERT_NEAR(length(s.position - c), r, 2e-6f * (r + length(c))) << "sample " << i;
        // Angle from the axis via the sine, which keeps its digits for tiny cones.
        const double sinTheta = std::min(1.0, double(length(cross(s.wi, axis))));
        // The point is where wi first meets the sphere: seen, not behind it. A direction at the
        // very rim may miss by rounding; it must then be at the rim.
        float hitT = 0;
        const float dist = length(s.position - p);
        if (bvh::intersectSphere(sphere, Ray{p, s.wi, 1e30f}, 1e30f, hitT)) {
            ASSERT_NEAR(hitT, dist, 1e-4f * dist + 2e-3f * r) << "sample " << i;
        } else {
            ASSERT_GT(sinTheta, 0.999 * std::sqrt(sin2Max)) << "sample " << i << " misses the sphere";
        }
        const double oneMinusCos = sinTheta * sinTheta / (1 + std::sqrt(1 - sinTheta * sinTheta));
        const double u = std::min(oneMinusCos / oneMinusCosMax, 0.999999);
        const double phi = std::atan2(double(dot(s.wi, b)), double(dot(s.wi, t))) / (2 * kPi) + 0.5;
        counts[std::size_t(u * kBins) * kBins + std::min(kBins - 1, int(phi * kBins))] += 1;
    }
    double chi2 = 0, expected = double(n) / (kBins * kBins);
    for (double o : counts) chi2 += (o - expected) * (o - expected) / expected;
    EXPECT_LT(chi2, chiSquareLimit(kBins * kBins - 1, 1e-3, tests)) << "r " << r << ", distance " << dc;
}

TEST_F(GpuTest, SphereLightSamplesAreUniformOverTheVisibleCone) {
    checkCone(*ctx, {0.5f, -0.2f, 0.1f}, {1.5f, 1.8f, 2.1f}, 1.2f, 3);  // a wide cone (24 degrees)
    checkCone(*ctx, {0, 0, 0}, {0, 0, -1.05f}, 1.0f, 3);               // almost a hemisphere
    checkCone(*ctx, {0, 0, 0}, {10, 20, 20}, 0.01f, 3);                // a tiny, distant cone
}

// From inside a sphere there is no cone: samples fall uniformly on the whole sphere, whose
// inside does not emit.
TEST_F(GpuTest, SphereLightSampledFromInsideFallsBackToTheArea) {
    const Vec3 c{0, 1, 0};
    auto samples = drawSamples(*ctx, lightsScene({{c, 2.0f, 0}}, {Vec3{1.0f}}), {{0.3f, 1.2f, -0.5f}}, 20000);
    double meanY = 0;
    for (const LightSampleRecord& s : samples) {
        ASSERT_NEAR(length(s.position - c), 2.0f, 1e-5f);
        ASSERT_GT(s.pdf, 0.0f);
        ASSERT_EQ(s.radiance, 0.0f);
        meanY += (s.position.y - c.y) / 2.0 / double(samples.size());
    }
    // Uniform on the sphere: the mean height is 0 with standard deviation 1/sqrt(3 n).
    EXPECT_NEAR(meanY, 0.0, 5.0 / std::sqrt(3.0 * double(samples.size())));
}

}  // namespace
}  // namespace penumbra::test
