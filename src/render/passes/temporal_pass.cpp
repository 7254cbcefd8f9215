#include "render/passes/temporal_pass.h"

#include "render/passes/image_pipeline.h"
#include "shared/types.h"

namespace penumbra {

TemporalPass::TemporalPass(const gpu::Context& ctx, const TemporalBuffers& b)
    : pipeline_(makeImagePipeline(ctx, "temporal", *b.frameUniforms,
                                  {{PN_BINDING_VIEWER, b.viewerUniforms},
                                   {PN_BINDING_ACCUM, b.accumulation},
                                   {PN_BINDING_GBUFFER, b.gbuffer},
                                   {PN_BINDING_GBUFFER_PREV, b.gbufferPrev},
                                   {PN_BINDING_HISTORY, b.history},
                                   {PN_BINDING_HISTORY_OUT, b.historyOut},
                                   {PN_BINDING_FILTER_IN, b.filterIn},
                                   {PN_BINDING_DENOISE_GUIDE, b.guide},
                                   {PN_BINDING_PIXEL_ESTIMATES, b.pixelEstimates}})) {}

void TemporalPass::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) const {
    dispatchImage(*pipeline_, cmd, width, height);
}

}  // namespace penumbra
