// Display (shaders/tonemap.comp): exposure, Reinhard or ACES, sRGB, packed RGBA8; or a debug view.
#pragma once

#include <memory>

#include "gpu/pipeline.h"

namespace penumbra {

class TonemapPass {
public:
    // history: HistoryTexel (the temporal result); filtered: vec4 radiance (denoiser output) or
    // heat-map counts; display: one uint per pixel.
    TonemapPass(const gpu::Context& ctx, const gpu::Buffer& frameUniforms, const gpu::Buffer& viewerUniforms,
                const gpu::Buffer& history, const gpu::Buffer& filtered, const gpu::Buffer& gbuffer,
                const gpu::Buffer& display);

    // Points the filtered input elsewhere; only between submissions.
    void setFiltered(const gpu::Buffer& filtered);
    void record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) const;

private:
    std::unique_ptr<gpu::ComputePipeline> pipeline_;
    const gpu::Buffer* filtered_;
};

}  // namespace penumbra
