#include "render/passes/trace_pass.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "gpu/commands.h"
#include "render/passes/trace_tiles.h"

namespace penumbra {

TracePass::TracePass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
                     const gpu::Buffer& accumulation, const gpu::Buffer& counters, KernelSpec spec,
                     const gpu::Buffer* activeMask, TraceKernel kernel)
    : ctx_(ctx),
      scene_(scene),
      frameUniforms_(frameUniforms),
      accumulation_(accumulation),
      counters_(counters),
      activeMask_(activeMask),
      spec_(spec),
      kernel_(kernel),
      hasMask_(activeMask != nullptr),
      maxBudget_(WavefrontPass::maxSlots(ctx)) {
    defaultBudget_ = pathBudget_ = std::min(defaultPathBudget(ctx.info().type), maxBudget_);
    if (!activeMask_) {
        // The shaders declare the mask, so something valid must be bound even when it is unused.
        placeholderMask_ = gpu::Buffer(ctx, sizeof(std::uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                       gpu::MemoryKind::DeviceLocal);
        activeMask_ = &placeholderMask_;
    }
}

void TracePass::setPixelEstimates(const gpu::Buffer* estimates) {
    PN_CHECK(!pipeline_ && !wave_);  // the kernels bind it when they are made
    pixelEstimates_ = estimates;
}

// Without estimates the shaders never read that binding, but something valid must be bound there.
TraceOutputs TracePass::outputs() const {
    return {&accumulation_, &counters_, activeMask_, pixelEstimates_ ? pixelEstimates_ : &accumulation_};
}

const gpu::ComputePipeline& TracePass::megakernel() {
    if (!pipeline_) pipeline_ = makeTracePipeline(ctx_, "trace", scene_, frameUniforms_, outputs(), {}, spec_);
    return *pipeline_;
}

WavefrontPass& TracePass::wavefront() {
    if (!wave_) wave_ = std::make_unique<WavefrontPass>(ctx_, scene_, frameUniforms_, outputs(), spec_);
    return *wave_;
}

TraceKernel TracePass::kernelFor(std::uint32_t width, std::uint32_t height, std::uint32_t samplesPerPass) const {
    if (kernel_ != TraceKernel::Auto) return kernel_;
    const std::uint64_t paths = std::uint64_t(width) * height * samplesPerPass;
    return paths >= kWavefrontMinPaths ? TraceKernel::Wavefront : TraceKernel::Megakernel;
}

void TracePass::setPathBudget(std::uint64_t paths) { pathBudget_ = paths > 0 ? std::min(paths, maxBudget_) : defaultBudget_; }

std::vector<gpu::PipelineStatistic> TracePass::statistics() const {
    std::vector<gpu::PipelineStatistic> out;
    if (pipeline_) out = pipeline_->namedStatistics();
    if (wave_)
        for (gpu::PipelineStatistic& s : wave_->statistics()) out.push_back(std::move(s));
    return out;
}

std::map<std::string, double> TracePass::stageMilliseconds() const {
    return wave_ ? wave_->stageMilliseconds() : std::map<std::string, double>{};
}

void TracePass::reserve(std::uint32_t width, std::uint32_t height, std::uint32_t samplesPerPass) {
    if (kernelFor(width, height, samplesPerPass) != TraceKernel::Wavefront) {
        megakernel();
        return;
    }
    std::uint64_t most = 0;
    for (const TraceTile& tile : traceTiles(width, height, samplesPerPass, pathBudget_)) {
        const TraceTile inside = clipTile(tile, width, height);
        most = std::max<std::uint64_t>(most, std::uint64_t(inside.width) * inside.height * samplesPerPass);
    }
    wavefront().reserve(most);
}

void TracePass::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, std::uint32_t samplesPerPass,
                       std::uint32_t passIndex, std::uint32_t maxBounces, bool countRays, bool masked) {
    PN_CHECK(!masked || hasMask_);
    PN_CHECK(!masked || !replace_);  // a skipped pixel would keep the last pass's sums
    // One sample per pass has its camera ray to itself: sharing would only change its position.
    const bool shareCamera = shareCamera_ && samplesPerPass > 1;
    const std::uint32_t mode = (masked ? PN_TRACE_MASKED : 0u) | (replace_ ? PN_TRACE_REPLACE : 0u) |
                               (shareCamera ? PN_TRACE_SHARED_CAMERA : 0u) |
                               (pixelEstimates_ ? PN_TRACE_PIXEL_ESTIMATES : 0u);
    const std::vector<TraceTile> tiles = traceTiles(width, height, samplesPerPass, pathBudget_);
    if (kernelFor(width, height, samplesPerPass) == TraceKernel::Wavefront) {
        WavefrontPass& wave = wavefront();
        wave.beginPass(cmd);
        // The tiles share the working buffers, so each waits for the one before.
        for (std::size_t i = 0; i < tiles.size(); ++i) {
            if (i > 0) gpu::computeBarrier(cmd);
            wave.record(cmd, tiles[i], width, height, samplesPerPass, passIndex, maxBounces, countRays, mode);
        }
        return;
    }
    const gpu::ComputePipeline& mega = megakernel();
    for (const TraceTile& tile : tiles) {  // disjoint pixels: no barrier between tiles
        shader::PassPush push{passIndex, mode, 0, countRays ? 1u : 0u, tile.x, tile.y};
        mega.dispatch(cmd, (tile.width + PN_TRACE_GROUP_X - 1) / PN_TRACE_GROUP_X,
                      (tile.height + PN_TRACE_GROUP_Y - 1) / PN_TRACE_GROUP_Y, 1, &push);
    }
}

}  // namespace penumbra
