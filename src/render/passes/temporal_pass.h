// Temporal accumulation (shaders/temporal.comp): this frame's samples into the history, and the
// denoiser's demodulated input.
#pragma once

#include <memory>

#include "gpu/pipeline.h"

namespace penumbra {

struct TemporalBuffers {
    const gpu::Buffer* frameUniforms;   // FrameUniforms (uniform)
    const gpu::Buffer* viewerUniforms;  // ViewerUniforms
    const gpu::Buffer* accumulation;    // vec4 per pixel: this frame's sums (rgb, squared luminance)
    const gpu::Buffer* gbuffer;         // GBufferTexel, this frame
    const gpu::Buffer* gbufferPrev;     // GBufferTexel, last frame
    const gpu::Buffer* history;         // HistoryTexel, last frame
    const gpu::Buffer* historyOut;      // HistoryTexel, this frame
    const gpu::Buffer* filterIn;        // vec4: illumination and variance for the denoiser
    const gpu::Buffer* guide;           // PN_DENOISE_GUIDE_BYTES per pixel: what the denoiser compares
    const gpu::Buffer* pixelEstimates;  // vec4 per pixel: the history's mean as the next trace's roulette scale
};

class TemporalPass {
public:
    TemporalPass(const gpu::Context& ctx, const TemporalBuffers& buffers);
    void record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) const;
    std::vector<gpu::PipelineStatistic> statistics() const { return pipeline_->namedStatistics(); }

private:
    std::unique_ptr<gpu::ComputePipeline> pipeline_;
};

}  // namespace penumbra
