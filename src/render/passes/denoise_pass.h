// The SVGF-style a-trous denoiser (shaders/atrous.comp): `iterations` passes with step sizes
// 1, 2, 4, ..., ping-ponging between two buffers; the last pass multiplies the albedo back and
// weighs the result against the running mean, to which it converges at rest.
#pragma once

#include <memory>

#include "gpu/pipeline.h"

namespace penumbra {

class DenoisePass {
public:
    // a holds temporal.comp's output (illumination, variance); b is scratch of the same size;
    // history: the HistoryTexels temporal.comp wrote this frame (the running mean and its
    // variance); display (optional): the viewer's RGBA8 pixels, which the last pass can write (below).
    DenoisePass(const gpu::Context& ctx, const gpu::Buffer& frameUniforms, const gpu::Buffer& viewerUniforms,
                const gpu::Buffer& gbuffer, const gpu::Buffer& guide, const gpu::Buffer& history, const gpu::Buffer& a,
                const gpu::Buffer& b, const gpu::Buffer* display = nullptr);

    // iterations >= 1. Returns the buffer that holds the result (radiance, variance). With
    // toDisplay (only if a display was given), the last pass also writes what the tonemap pass
    // would make of the result with no debug view, so that pass need not run. filterOnly leaves
    // out the blend with the running mean (measurements of what the blend costs in motion).
    const gpu::Buffer& record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height,
                              std::uint32_t iterations, bool toDisplay = false, bool filterOnly = false) const;
    // Where the result of `iterations` passes lands, without recording anything.
    const gpu::Buffer& output(std::uint32_t iterations) const { return iterations % 2 ? b_ : a_; }
    std::vector<gpu::PipelineStatistic> statistics() const { return aToB_->namedStatistics(); }

private:
    const gpu::Buffer& a_;
    const gpu::Buffer& b_;
    bool hasDisplay_;
    std::unique_ptr<gpu::ComputePipeline> aToB_, bToA_;
};

}  // namespace penumbra
