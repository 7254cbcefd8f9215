#include "render/passes/trace_pass.h"

#include "core/error.h"
#include "render/passes/trace_tiles.h"
#include "render/scene_pipeline.h"

namespace penumbra {

TracePass::TracePass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
                     const gpu::Buffer& accumulation, const gpu::Buffer& counters, std::uint32_t features,
                     const gpu::Buffer* activeMask)
    : hasMask_(activeMask != nullptr),
      defaultBudget_(defaultPathBudget(ctx.info().type)),
      pathBudget_(defaultBudget_),
      pipeline_(makeScenePipeline(ctx, "trace", scene, frameUniforms,
                                  {PN_BINDING_ACCUM, PN_BINDING_COUNTERS, PN_BINDING_ACTIVE_MASK}, features)) {
    if (!activeMask) {
        // The shader declares the mask, so something valid must be bound even when it is unused.
        placeholderMask_ = gpu::Buffer(ctx, sizeof(std::uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                       gpu::MemoryKind::DeviceLocal);
        activeMask = &placeholderMask_;
    }
    pipeline_->bind(PN_BINDING_ACCUM, accumulation);
    pipeline_->bind(PN_BINDING_COUNTERS, counters);
    pipeline_->bind(PN_BINDING_ACTIVE_MASK, *activeMask);
}

void TracePass::setPathBudget(std::uint64_t paths) { pathBudget_ = paths > 0 ? paths : defaultBudget_; }

void TracePass::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, std::uint32_t samplesPerPass,
                       std::uint32_t passIndex, bool countRays, bool masked) const {
    PN_CHECK(!masked || hasMask_);
    // Tiles write disjoint pixels, so they need no barrier between them.
    for (const TraceTile& tile : traceTiles(width, height, samplesPerPass, pathBudget_)) {
        shader::PassPush push{passIndex, masked ? PN_TRACE_MASKED : 0u, 0, countRays ? 1u : 0u, tile.x, tile.y, 0, 0};
        pipeline_->dispatch(cmd, (tile.width + PN_TRACE_GROUP_X - 1) / PN_TRACE_GROUP_X,
                            (tile.height + PN_TRACE_GROUP_Y - 1) / PN_TRACE_GROUP_Y, 1, &push);
    }
}

}  // namespace penumbra
