#include "bsdf_kernel.h"

#include <cmath>
#include <cstring>

#include "render/frame_uniforms.h"
#include "render/kernel_features.h"
#include "render/scene_pipeline.h"

namespace penumbra::test {

BsdfKernel::BsdfKernel(const gpu::Context& ctx, const Material& material, const std::vector<Texture>& textures,
                       std::optional<KernelSpec> spec)
    : ctx_(ctx), commands_(ctx) {
    Scene scene;
    scene.name = "bsdf-test";
    scene.textures = textures;
    scene.materials.push_back(material);
    Mesh mesh;
    mesh.name = "carrier";  // the kernel only reads materials[0]; a scene needs some geometry
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.indices = {0, 1, 2};
    scene.meshes.push_back(mesh);
    const SceneArrays arrays = buildSceneArrays(scene);
    spec_ = spec.value_or(kernelSpec(arrays));
    scene_ = std::make_unique<GpuScene>(ctx, commands_, arrays);
}

BsdfKernel::~BsdfKernel() = default;

std::vector<shader::BsdfTestResult> BsdfKernel::run(const std::vector<shader::BsdfTestQuery>& queries,
                                                    std::uint32_t mode, std::uint32_t count, std::uint32_t seed) {
    RenderSettings settings;
    settings.seed = seed;
    shader::FrameUniforms frame =
        makeFrameUniforms(Camera{}, Vec3{0}, settings, scene_->lightNodeCount, scene_->triCount, scene_->nodeCount);
    gpu::Buffer frameBuffer(ctx_, sizeof(frame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryKind::HostVisible);
    std::memcpy(frameBuffer.mapped(), &frame, sizeof(frame));
    gpu::Buffer queryBuffer = gpu::uploadStorageBuffer<shader::BsdfTestQuery>(ctx_, commands_, queries);
    gpu::Buffer resultBuffer(ctx_, count * sizeof(shader::BsdfTestResult),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                             gpu::MemoryKind::DeviceLocal);
    auto pipeline =
        makeScenePipeline(ctx_, "test_bsdf_sample", *scene_, frameBuffer, {PN_BINDING_SCRATCH, PN_BINDING_SCRATCH2}, spec_);
    pipeline->bind(PN_BINDING_SCRATCH, queryBuffer);
    pipeline->bind(PN_BINDING_SCRATCH2, resultBuffer);
    shader::PassPush push{0, mode, count, 0};
    commands_.run([&](VkCommandBuffer cmd) {
        pipeline->dispatch(cmd, (count + PN_LINEAR_GROUP - 1) / PN_LINEAR_GROUP, 1, 1, &push);
        gpu::computeBarrier(cmd);
    });
    return gpu::downloadBuffer<shader::BsdfTestResult>(ctx_, commands_, resultBuffer, count);
}

std::vector<shader::BsdfTestResult> BsdfKernel::sample(Vec3 wo, bool entering, std::uint32_t count,
                                                       std::uint32_t seed) {
    shader::BsdfTestQuery q{};
    q.wo = wo;
    q.entering = entering ? 1u : 0u;
    return run({q}, PN_BSDF_TEST_SAMPLE, count, seed);
}

std::vector<shader::BsdfTestResult> BsdfKernel::eval(const std::vector<shader::BsdfTestQuery>& queries) {
    return run(queries, PN_BSDF_TEST_EVAL, static_cast<std::uint32_t>(queries.size()), 1);
}

Material diffuseMaterial(Vec3 albedo) {
    Material m;
    m.name = "diffuse";
    m.albedo = albedo;
    return m;
}

Material conductorMaterial(Vec3 albedo, float roughness) {
    Material m = diffuseMaterial(albedo);
    m.name = "conductor";
    m.metallic = 1.0f;
    m.roughness = roughness;
    return m;
}

Material plasticMaterial(Vec3 albedo, float roughness) {
    Material m = diffuseMaterial(albedo);
    m.name = "plastic";
    m.specular = 1.0f;
    m.roughness = roughness;
    return m;
}

Material glassMaterial(float roughness, float ior, Vec3 tint) {
    Material m = diffuseMaterial(tint);
    m.name = "glass";
    m.transmission = 1.0f;
    m.roughness = roughness;
    m.ior = ior;
    return m;
}

Vec3 localDirection(float cosTheta, float phi) {
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

}  // namespace penumbra::test
