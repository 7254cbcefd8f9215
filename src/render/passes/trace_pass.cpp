#include "render/passes/trace_pass.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "gpu/commands.h"
#include "render/passes/trace_tiles.h"
#include "render/scene_pipeline.h"

namespace penumbra {

TraceKernel traceKernelFromEnvironment() {
    const char* value = std::getenv("PENUMBRA_TRACE_KERNEL");
    if (!value || !*value) return TraceKernel::Wavefront;
    const std::string name = value;
    if (name == "mega") return TraceKernel::Megakernel;
    if (name == "wavefront") return TraceKernel::Wavefront;
    throw UsageError("PENUMBRA_TRACE_KERNEL must be 'mega' or 'wavefront' (got '" + name + "')");
}

TracePass::TracePass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
                     const gpu::Buffer& accumulation, const gpu::Buffer& counters, std::uint32_t features,
                     const gpu::Buffer* activeMask, TraceKernel kernel)
    : hasMask_(activeMask != nullptr), defaultBudget_(defaultPathBudget(ctx.info().type)), pathBudget_(defaultBudget_) {
    if (!activeMask) {
        // The shaders declare the mask, so something valid must be bound even when it is unused.
        placeholderMask_ = gpu::Buffer(ctx, sizeof(std::uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                       gpu::MemoryKind::DeviceLocal);
        activeMask = &placeholderMask_;
    }
    if (kernel == TraceKernel::Wavefront) {
        wave_ = std::make_unique<WavefrontPass>(ctx, scene, frameUniforms, accumulation, counters, *activeMask, features);
        maxBudget_ = WavefrontPass::maxSlots(ctx);
        defaultBudget_ = pathBudget_ = std::min(defaultBudget_, maxBudget_);
        return;
    }
    pipeline_ = makeScenePipeline(ctx, "trace", scene, frameUniforms,
                                  {PN_BINDING_ACCUM, PN_BINDING_COUNTERS, PN_BINDING_ACTIVE_MASK}, features);
    pipeline_->bind(PN_BINDING_ACCUM, accumulation);
    pipeline_->bind(PN_BINDING_COUNTERS, counters);
    pipeline_->bind(PN_BINDING_ACTIVE_MASK, *activeMask);
}

void TracePass::setPathBudget(std::uint64_t paths) { pathBudget_ = paths > 0 ? std::min(paths, maxBudget_) : defaultBudget_; }

std::vector<gpu::PipelineStatistic> TracePass::statistics() const {
    if (wave_) return wave_->statistics();
    std::vector<gpu::PipelineStatistic> out = pipeline_->statistics();
    for (gpu::PipelineStatistic& s : out) s.executable = pipeline_->name() + ": " + s.executable;
    return out;
}

std::map<std::string, double> TracePass::stageMilliseconds() const {
    return wave_ ? wave_->stageMilliseconds() : std::map<std::string, double>{};
}

void TracePass::reserve(std::uint32_t width, std::uint32_t height, std::uint32_t samplesPerPass) {
    if (!wave_) return;
    std::uint64_t most = 0;
    for (const TraceTile& tile : traceTiles(width, height, samplesPerPass, pathBudget_))
        most = std::max<std::uint64_t>(most, std::uint64_t(std::min(tile.width, width - tile.x)) *
                                                 std::min(tile.height, height - tile.y) * samplesPerPass);
    wave_->reserve(most);
}

void TracePass::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, std::uint32_t samplesPerPass,
                       std::uint32_t passIndex, std::uint32_t maxBounces, bool countRays, bool masked) {
    PN_CHECK(!masked || hasMask_);
    // Tiles write disjoint pixels, so megakernel tiles need no barrier between them; wavefront
    // tiles share the working buffers and follow one another.
    bool first = true;
    if (wave_) wave_->beginPass(cmd);
    for (const TraceTile& tile : traceTiles(width, height, samplesPerPass, pathBudget_)) {
        if (wave_) {
            if (!first) gpu::computeBarrier(cmd);
            wave_->record(cmd, tile, width, height, samplesPerPass, passIndex, maxBounces, countRays, masked);
            first = false;
            continue;
        }
        shader::PassPush push{passIndex, masked ? PN_TRACE_MASKED : 0u, 0, countRays ? 1u : 0u, tile.x, tile.y};
        pipeline_->dispatch(cmd, (tile.width + PN_TRACE_GROUP_X - 1) / PN_TRACE_GROUP_X,
                            (tile.height + PN_TRACE_GROUP_Y - 1) / PN_TRACE_GROUP_Y, 1, &push);
    }
}

}  // namespace penumbra
