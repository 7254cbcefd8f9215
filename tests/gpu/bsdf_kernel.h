// Runs the real BSDF code (shaders/test/bsdf_sample.comp) for one material on the test device:
// draws samples for a direction, or evaluates f and pdf at given direction pairs. Textures the
// material refers to are looked up at uv (0, 0).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "gpu/commands.h"
#include "gpu/context.h"
#include "render/gpu_scene.h"
#include "render/kernel_features.h"
#include "scene/scene.h"

namespace penumbra::test {

class BsdfKernel {
public:
    // The material is packed exactly as a render packs it (buildSceneArrays), and the kernel is
    // specialised as a render's would be for a scene of that material (render/kernel_features.h),
    // or for `spec` where given (KernelSpec{}: every lobe's code).
    BsdfKernel(const gpu::Context& ctx, const Material& material, const std::vector<Texture>& textures = {},
               std::optional<KernelSpec> spec = std::nullopt);
    ~BsdfKernel();

    // count samples for wo (local frame, wo.z > 0); entering: wo is outside the material.
    std::vector<shader::BsdfTestResult> sample(Vec3 wo, bool entering, std::uint32_t count, std::uint32_t seed);
    // f and pdf of every query (value = f).
    std::vector<shader::BsdfTestResult> eval(const std::vector<shader::BsdfTestQuery>& queries);

private:
    std::vector<shader::BsdfTestResult> run(const std::vector<shader::BsdfTestQuery>& queries, std::uint32_t mode,
                                            std::uint32_t count, std::uint32_t seed);

    const gpu::Context& ctx_;
    gpu::Commands commands_;
    std::unique_ptr<GpuScene> scene_;
    KernelSpec spec_;
};

// A material with one lobe family, for tests: every field not named here keeps Material{}'s value.
Material diffuseMaterial(Vec3 albedo);
Material conductorMaterial(Vec3 albedo, float roughness);
Material plasticMaterial(Vec3 albedo, float roughness);
Material glassMaterial(float roughness, float ior, Vec3 tint = Vec3{1.0f});

// A unit direction at polar cosine cosTheta and azimuth phi in the local frame.
Vec3 localDirection(float cosTheta, float phi);

}  // namespace penumbra::test
