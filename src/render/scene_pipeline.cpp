#include "render/scene_pipeline.h"

#include "shared/types.h"
#include "shared/accel_layouts.h"

namespace penumbra {

std::unique_ptr<gpu::ComputePipeline> makeScenePipeline(const gpu::Context& ctx, const std::string& shader,
                                                        const GpuScene& scene, const gpu::Buffer& frameUniforms,
                                                        const std::vector<std::uint32_t>& extraStorageBindings,
                                                        KernelSpec spec, std::uint32_t camera) {
    constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    std::vector<gpu::BindingSpec> bindings = {
        {PN_BINDING_NODES, storage},     {PN_BINDING_TRI_VERTS, storage},
        {PN_BINDING_TRI_ATTRIBS, storage}, {PN_BINDING_TRI_UVS, storage}, {PN_BINDING_MATERIALS, storage},
        {PN_BINDING_LIGHTS, storage},    {PN_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
        {PN_BINDING_TEXTURES, storage},  {PN_BINDING_TEXELS, storage},
        {PN_BINDING_PUNCTUAL, storage},  {PN_BINDING_SPHERE_LIGHTS, storage}, {PN_BINDING_ENV_TABLE, storage},
        {PN_BINDING_ENV_TEXELS, storage}, {PN_BINDING_LIGHT_NODES, storage}, {PN_BINDING_LIGHT_TREE, storage},
        {PN_BINDING_INSTANCES, storage}, {PN_BINDING_STACKLESS_NODES, storage}, {PN_BINDING_OBJECT_BOXES, storage},
        {PN_BINDING_OBJECT_PRIMS, storage}};
    for (std::uint32_t b : extraStorageBindings) bindings.push_back({b, storage});
    // In constant_id order (shaders/shared/features.h, shaders/lib/scene_bindings.glsl).
    const std::uint32_t specialization[] = {spec.capabilities, scene.walk, camera, spec.options};
    auto pipeline = std::make_unique<gpu::ComputePipeline>(ctx, shader, bindings, sizeof(shader::PassPush), specialization);
    pipeline->bind(PN_BINDING_NODES, scene.nodes);
    pipeline->bind(PN_BINDING_TRI_VERTS, scene.triVerts);
    pipeline->bind(PN_BINDING_TRI_ATTRIBS, scene.triAttribs);
    pipeline->bind(PN_BINDING_TRI_UVS, scene.triUvs);
    pipeline->bind(PN_BINDING_MATERIALS, scene.materials);
    pipeline->bind(PN_BINDING_LIGHTS, scene.lightRefs);
    pipeline->bind(PN_BINDING_LIGHT_NODES, scene.lightNodes);
    pipeline->bind(PN_BINDING_LIGHT_TREE, scene.lightTree);
    pipeline->bind(PN_BINDING_FRAME, frameUniforms);
    pipeline->bind(PN_BINDING_TEXTURES, scene.textures);
    pipeline->bind(PN_BINDING_TEXELS, scene.texels);
    pipeline->bind(PN_BINDING_PUNCTUAL, scene.punctual);
    pipeline->bind(PN_BINDING_SPHERE_LIGHTS, scene.sphereLights);
    pipeline->bind(PN_BINDING_ENV_TABLE, scene.envTable);
    pipeline->bind(PN_BINDING_ENV_TEXELS, scene.envTexels);
    pipeline->bind(PN_BINDING_INSTANCES, scene.instances);
    pipeline->bind(PN_BINDING_STACKLESS_NODES, scene.stacklessNodes);
    pipeline->bind(PN_BINDING_OBJECT_BOXES, scene.objectBoxes);
    pipeline->bind(PN_BINDING_OBJECT_PRIMS, scene.objectPrims);
    return pipeline;
}

}  // namespace penumbra
