#include "render/passes/tonemap_pass.h"

#include "render/passes/image_pipeline.h"
#include "shared/types.h"

namespace penumbra {

TonemapPass::TonemapPass(const gpu::Context& ctx, const gpu::Buffer& frameUniforms, const gpu::Buffer& viewerUniforms,
                         const gpu::Buffer& history, const gpu::Buffer& filtered, const gpu::Buffer& gbuffer,
                         const gpu::Buffer& display)
    : pipeline_(makeImagePipeline(ctx, "tonemap", frameUniforms,
                                  {{PN_BINDING_VIEWER, &viewerUniforms},
                                   {PN_BINDING_HISTORY_OUT, &history},
                                   {PN_BINDING_FILTER_OUT, &filtered},
                                   {PN_BINDING_GBUFFER, &gbuffer},
                                   {PN_BINDING_DISPLAY, &display}})),
      filtered_(&filtered) {}

void TonemapPass::setFiltered(const gpu::Buffer& filtered) {
    if (&filtered == filtered_) return;
    pipeline_->bind(PN_BINDING_FILTER_OUT, filtered);
    filtered_ = &filtered;
}

void TonemapPass::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) const {
    dispatchImage(*pipeline_, cmd, width, height);
}

}  // namespace penumbra
