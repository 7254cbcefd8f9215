// The environment and sun-disk samplers on the GPU (shaders/test/env_sample.comp running the
// real lib/environment.glsl): sampled directions follow the pdf the sampler reports (chi-square),
// the pdf integrates to 1 over the sphere, and the lookup matches the CPU's mapping.
#include <cstring>
#include <random>

#include "env_test_util.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "render/frame_uniforms.h"
#include "render/scene_pipeline.h"
#include "render_helpers.h"
#include "scene/environment.h"

namespace penumbra::test {
namespace {

// Runs the test kernel over `count` items on a scene holding only the environment (and one
// far-away triangle, since a scene needs geometry).
std::vector<Vec4> runEnvKernel(const gpu::Context& ctx, Scene scene, std::uint32_t mode, std::uint32_t count,
                               const std::vector<Vec4>& input = {}) {
    std::uint32_t m = addMaterial(scene, "grey", Vec3{0.5f});
    Mesh speck;
    speck.name = "speck";
    speck.material = m;
    addQuad(speck, {1000, -1000, 1000}, {1000, -1000, 1001}, {1001, -1000, 1001}, {1001, -1000, 1000});
    scene.meshes.push_back(speck);
    SceneArrays arrays = buildSceneArrays(scene);
    gpu::Commands commands(ctx);
    GpuScene gpuScene(ctx, commands, arrays);
    RenderSettings settings;
    settings.seed = 7;
    shader::FrameUniforms frame =
        makeSceneFrameUniforms(scene.camera, scene.background, scene.environment, settings, gpuScene);
    gpu::Buffer frameBuffer(ctx, sizeof(frame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryKind::HostVisible);
    std::memcpy(frameBuffer.mapped(), &frame, sizeof(frame));
    std::vector<Vec4> in = input.empty() ? std::vector<Vec4>(1) : input;
    gpu::Buffer inBuffer = gpu::uploadStorageBuffer<Vec4>(ctx, commands, in);
    const std::size_t outCount = mode == 0 ? 2 * std::size_t(count) : count;
    gpu::Buffer outBuffer(ctx, outCount * sizeof(Vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                          gpu::MemoryKind::DeviceLocal);
    auto pipeline = makeScenePipeline(ctx, "test_env_sample", gpuScene, frameBuffer, {PN_BINDING_SCRATCH, PN_BINDING_SCRATCH2});
    pipeline->bind(PN_BINDING_SCRATCH, inBuffer);
    pipeline->bind(PN_BINDING_SCRATCH2, outBuffer);
    shader::PassPush push{0, mode, count, 0};
    commands.run([&](VkCommandBuffer cmd) {
        pipeline->dispatch(cmd, (count + PN_LINEAR_GROUP - 1) / PN_LINEAR_GROUP, 1, 1, &push);
        gpu::computeBarrier(cmd);
    });
    return gpu::downloadBuffer<Vec4>(ctx, commands, outBuffer, outCount);
}

Scene mapScene(float rotationDegrees) {
    Scene s;
    s.name = "env";
    s.environment.map = spotAndGradientMap();
    s.environment.rotationDegrees = rotationDegrees;
    s.environment.intensity = 1.5f;
    return s;
}

// Chi-square: each texel split 2 x 2 in (phi, cos theta), within which the sampler is uniform,
// so every sub-bin expects a quarter of the texel's probability (luminance x solid angle,
// computed here from the map, not from the table under test).
class EnvSamplingTest : public GpuTest, public ::testing::WithParamInterface<float> {};

TEST_P(EnvSamplingTest, DirectionsFollowTheReportedPdf) {
    const float rotation = GetParam();
    Scene scene = mapScene(rotation);
    const EnvironmentMap& map = *scene.environment.map;
    const int w = map.width, h = map.height;
    const std::uint32_t n = 200000;
    std::vector<Vec4> out = runEnvKernel(*ctx, scene, 0, n);

    double total = 0;
    for (int i = 0; i < w * h; ++i) total += luminance(map.radiance[i]) * (2 * kPi / w) * (std::cos(kPi * (i / w) / h) - std::cos(kPi * (i / w + 1) / h));
    std::vector<double> observed(std::size_t(w) * h * 4, 0.0), expected(observed.size(), 0.0);
    for (int i = 0; i < w * h; ++i) {
        const int y = i / w;
        const double omega = (2 * kPi / w) * (std::cos(kPi * y / h) - std::cos(kPi * (y + 1) / h));
        for (int q = 0; q < 4; ++q) expected[4 * i + q] = n * luminance(map.radiance[i]) * omega / total / 4;
    }
    int pdfMismatches = 0;
    for (std::uint32_t s = 0; s < n; ++s) {
        const Vec3 d{out[2 * s].x, out[2 * s].y, out[2 * s].z};
        ASSERT_NEAR(length(d), 1.0f, 1e-4f);
        const Vec3 local = rotateAboutY(d, -double(rotation) * kPi / 180);
        const Vec2 uv = environmentUv(local);
        const double fx = uv.x * w, cosT = local.y;
        const int x = std::min(int(fx), w - 1);
        const int y = std::min(int(uv.y * h), h - 1);
        const double c0 = std::cos(kPi * y / h), c1 = std::cos(kPi * (y + 1) / h);
        const int qx = (fx - x) < 0.5 ? 0 : 1, qy = (c0 - cosT) < 0.5 * (c0 - c1) ? 0 : 1;
        observed[4 * (std::size_t(y) * w + x) + 2 * qy + qx] += 1;
        // The pdf the sampler reports is the texel's density, and the lookup agrees with it
        // (up to directions that round across a texel edge).
        const double density = luminance(map.radiance[std::size_t(y) * w + x]) / total;
        if (std::abs(out[2 * s].w - density) > 1e-4 * density || std::abs(out[2 * s + 1].x - out[2 * s].w) > 1e-4 * density)
            ++pdfMismatches;
        const Vec3 L = map.radiance[std::size_t(y) * w + x] * scene.environment.intensity;
        if (std::abs(out[2 * s + 1].y - L.x) > 1e-4f * L.x + 1e-6f) ++pdfMismatches;
    }
    EXPECT_LE(pdfMismatches, int(n / 1000)) << "reported pdf or radiance disagrees with the map";
    const double p = chiSquarePValue(observed, expected);
    EXPECT_GT(p, 1.0 - std::pow(1.0 - 0.01, 1.0 / 2.0)) << "chi-square p-value " << p << " (two rotations tested)";
}

INSTANTIATE_TEST_SUITE_P(Rotations, EnvSamplingTest, ::testing::Values(0.0f, 37.0f),
                         [](const ::testing::TestParamInfo<float>& p) { return "rotation" + std::to_string(int(p.param)); });

TEST_F(GpuTest, EnvironmentPdfIntegratesToOneAndLookupMatchesTheCpu) {
    for (float rotation : {0.0f, 37.0f}) {
        Scene scene = mapScene(rotation);
        const std::uint32_t n = 100000;
        std::mt19937 rng(9);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        std::vector<Vec4> dirs(n);
        for (Vec4& d : dirs) {
            float z = 1 - 2 * u(rng), r = std::sqrt(std::max(0.0f, 1 - z * z)), phi = float(2 * kPi) * u(rng);
            d = Vec4{r * std::cos(phi), z, r * std::sin(phi), 0};
        }
        std::vector<Vec4> out = runEnvKernel(*ctx, scene, 1, n, dirs);
        double sum = 0, sum2 = 0;
        int lookupMismatches = 0;
        for (std::uint32_t i = 0; i < n; ++i) {
            const double f = out[i].w * 4 * kPi;  // pdf / uniform pdf
            sum += f;
            sum2 += f * f;
            Vec3 cpu = environmentRadiance(scene.environment, scene.background, Vec3{dirs[i].x, dirs[i].y, dirs[i].z});
            if (std::abs(cpu.y - out[i].y) > 1e-4f * cpu.y + 1e-6f) ++lookupMismatches;
        }
        const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
        EXPECT_NEAR(mean, 1.0, 5 * se) << "rotation " << rotation;
        EXPECT_LE(lookupMismatches, int(n / 1000)) << "rotation " << rotation;
    }
}

// The constant background is sampled cosine-weighted around the surface normal (the kernel's
// fixed normal): cos^2 theta is then uniform in [0, 1], and phi uniform.
TEST_F(GpuTest, ConstantBackgroundIsSampledCosineWeighted) {
    Scene scene;
    scene.name = "bg";
    scene.background = Vec3{0.5f, 1.0f, 2.0f};
    const std::uint32_t n = 20000;
    std::vector<Vec4> out = runEnvKernel(*ctx, scene, 0, n);
    const Vec3 normal = normalize(Vec3{0.3f, 0.8f, -0.52f});
    const Vec3 t = normalize(cross(normal, Vec3{1, 0, 0})), b = cross(normal, t);
    const int rings = 8, sectors = 8;
    std::vector<double> observed(rings * sectors, 0.0), expected(observed.size(), double(n) / (rings * sectors));
    for (std::uint32_t s = 0; s < n; ++s) {
        const Vec3 d{out[2 * s].x, out[2 * s].y, out[2 * s].z};
        const double cosTheta = dot(d, normal);
        ASSERT_GE(cosTheta, -1e-6);
        EXPECT_NEAR(out[2 * s].w, cosTheta / kPi, 1e-5);
        EXPECT_NEAR(out[2 * s + 1].x, out[2 * s].w, 1e-5);  // environmentPdf agrees
        EXPECT_NEAR(out[2 * s + 1].z, 1.0f, 1e-6f);          // green radiance
        const int ring = std::min(int(cosTheta * cosTheta * rings), rings - 1);
        const double phi = std::atan2(double(dot(d, b)), double(dot(d, t))) + kPi;
        observed[std::size_t(ring) * sectors + std::min(int(phi / (2 * kPi) * sectors), sectors - 1)] += 1;
    }
    EXPECT_GT(chiSquarePValue(observed, expected), 1e-3);
}

// The sun disk: directions uniform over the cone (chi-square on 1 - cos theta and phi).
TEST_F(GpuTest, SunDiskSamplesAreUniformInsideItsCone) {
    Scene scene;
    scene.name = "sun";
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = normalize(Vec3{0.3f, -1.0f, 0.2f});
    sun.angularRadius = float(10 * kPi / 180);
    scene.lights.push_back(sun);
    const std::uint32_t n = 50000;
    std::vector<Vec4> out = runEnvKernel(*ctx, scene, 2, n);
    const double c = 1 - std::cos(double(sun.angularRadius));
    const Vec3 axis = -sun.direction;
    Vec3 t = normalize(cross(axis, Vec3{1, 0, 0})), b = cross(axis, t);
    const int rings = 10, sectors = 8;
    std::vector<double> observed(rings * sectors, 0.0), expected(observed.size(), double(n) / (rings * sectors));
    for (std::uint32_t s = 0; s < n; ++s) {
        const Vec3 d{out[s].x, out[s].y, out[s].z};
        EXPECT_NEAR(out[s].w, 1 / (2 * kPi * c), 1e-3 / (2 * kPi * c));
        const double oneMinusCos = 1 - double(dot(d, axis));
        ASSERT_LE(oneMinusCos, c * 1.001 + 1e-6) << "sample outside the cone";
        const int ring = std::min(int(oneMinusCos / c * rings), rings - 1);
        const double phi = std::atan2(double(dot(d, b)), double(dot(d, t))) + kPi;
        const int sector = std::min(int(phi / (2 * kPi) * sectors), sectors - 1);
        observed[std::size_t(ring) * sectors + sector] += 1;
    }
    EXPECT_GT(chiSquarePValue(observed, expected), 1e-3);
}

}  // namespace
}  // namespace penumbra::test
