// The SVGF-style a-trous denoiser (shaders/atrous.comp): `iterations` passes with step sizes
// 1, 2, 4, ..., ping-ponging between two buffers of denoiser texels (PN_DENOISE_TEXEL_BYTES per
// pixel); the last pass multiplies the albedo back and writes float vec4(radiance, variance).
// Steps up to PN_ATROUS_TILE_MAX_STEP run a pipeline that reads through a shared-memory tile.
#pragma once

#include <memory>

#include "gpu/pipeline.h"

namespace penumbra {

class DenoisePass {
public:
    // a holds temporal.comp's output texels (guide, illumination, variance); b is scratch of the
    // same size.
    DenoisePass(const gpu::Context& ctx, const gpu::Buffer& frameUniforms, const gpu::Buffer& viewerUniforms,
                const gpu::Buffer& gbuffer, const gpu::Buffer& a, const gpu::Buffer& b);

    // iterations >= 1. Returns the buffer that holds the result (radiance, variance).
    const gpu::Buffer& record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height,
                              std::uint32_t iterations) const;
    // Where the result of `iterations` passes lands, without recording anything.
    const gpu::Buffer& output(std::uint32_t iterations) const { return iterations % 2 ? b_ : a_; }

private:
    const gpu::Buffer& a_;
    const gpu::Buffer& b_;
    // [tiled][direction]: direction 0 reads a and writes b.
    std::unique_ptr<gpu::ComputePipeline> pipelines_[2][2];
};

}  // namespace penumbra
