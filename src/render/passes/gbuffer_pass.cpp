#include "render/passes/gbuffer_pass.h"

#include "render/passes/image_pipeline.h"
#include "render/scene_pipeline.h"
#include "shared/types.h"

namespace penumbra {

GBufferPass::GBufferPass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
                         const gpu::Buffer& viewerUniforms, const gpu::Buffer& gbuffer, KernelSpec spec,
                         const gpu::Buffer* previousInstances)
    : pipeline_(makeScenePipeline(ctx, "gbuffer", scene, frameUniforms,
                                  {PN_BINDING_VIEWER, PN_BINDING_GBUFFER, PN_BINDING_INSTANCES_PREV}, spec)) {
    pipeline_->bind(PN_BINDING_VIEWER, viewerUniforms);
    pipeline_->bind(PN_BINDING_GBUFFER, gbuffer);
    pipeline_->bind(PN_BINDING_INSTANCES_PREV, previousInstances ? *previousInstances : scene.instances);
}

void GBufferPass::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, int subpixel) const {
    shader::PassPush push{};
    if (subpixel >= 0) {
        push.mode = PN_GBUFFER_SUBPIXEL;
        push.passIndex = std::uint32_t(subpixel);
    }
    dispatchImage(*pipeline_, cmd, width, height, &push);
}

HeatmapPass::HeatmapPass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
                         const gpu::Buffer& viewerUniforms, const gpu::Buffer& heat, const gpu::Buffer& counters)
    : pipeline_(makeScenePipeline(ctx, "heatmap", scene, frameUniforms,
                                  {PN_BINDING_VIEWER, PN_BINDING_FILTER_OUT, PN_BINDING_SCRATCH})) {
    pipeline_->bind(PN_BINDING_VIEWER, viewerUniforms);
    pipeline_->bind(PN_BINDING_FILTER_OUT, heat);
    pipeline_->bind(PN_BINDING_SCRATCH, counters);
}

void HeatmapPass::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) const {
    shader::PassPush push{};
    dispatchImage(*pipeline_, cmd, width, height, &push);
}

}  // namespace penumbra
