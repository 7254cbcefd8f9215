#include "render/passes/temporal_pass.h"

#include "core/error.h"
#include "render/passes/image_pipeline.h"
#include "shared/types.h"

namespace penumbra {

namespace {

std::unique_ptr<gpu::ComputePipeline> makeTemporalPipeline(const gpu::Context& ctx, const TemporalBuffers& b) {
    // Every binding needs a buffer: a missing one would be dereferenced when bound.
    PN_CHECK(b.frameUniforms && b.viewerUniforms && b.accumulation && b.gbuffer && b.gbufferPrev && b.history &&
             b.historyOut && b.filterIn && b.guide && b.pixelEstimates);
    return makeImagePipeline(ctx, "temporal", *b.frameUniforms,
                             {{PN_BINDING_VIEWER, b.viewerUniforms},
                              {PN_BINDING_ACCUM, b.accumulation},
                              {PN_BINDING_GBUFFER, b.gbuffer},
                              {PN_BINDING_GBUFFER_PREV, b.gbufferPrev},
                              {PN_BINDING_HISTORY, b.history},
                              {PN_BINDING_HISTORY_OUT, b.historyOut},
                              {PN_BINDING_FILTER_IN, b.filterIn},
                              {PN_BINDING_DENOISE_GUIDE, b.guide},
                              {PN_BINDING_PIXEL_ESTIMATES, b.pixelEstimates}});
}

}  // namespace

TemporalPass::TemporalPass(const gpu::Context& ctx, const TemporalBuffers& buffers)
    : pipeline_(makeTemporalPipeline(ctx, buffers)) {}

void TemporalPass::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) const {
    dispatchImage(*pipeline_, cmd, width, height);
}

}  // namespace penumbra
