#include "render/passes/trace_pass.h"

#include "render/scene_pipeline.h"

namespace penumbra {

TracePass::TracePass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
                     const gpu::Buffer& accumulation, const gpu::Buffer& counters, std::uint32_t features)
    : pipeline_(makeScenePipeline(ctx, "trace", scene, frameUniforms, {PN_BINDING_ACCUM, PN_BINDING_COUNTERS}, features)) {
    pipeline_->bind(PN_BINDING_ACCUM, accumulation);
    pipeline_->bind(PN_BINDING_COUNTERS, counters);
}

void TracePass::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, std::uint32_t passIndex,
                       bool countRays) const {
    shader::PassPush push{passIndex, 0, 0, countRays ? 1u : 0u};
    pipeline_->dispatch(cmd, (width + PN_TRACE_GROUP_X - 1) / PN_TRACE_GROUP_X,
                        (height + PN_TRACE_GROUP_Y - 1) / PN_TRACE_GROUP_Y, 1, &push);
}

}  // namespace penumbra
