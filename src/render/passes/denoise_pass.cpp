#include "render/passes/denoise_pass.h"

#include "core/error.h"
#include "gpu/commands.h"
#include "render/passes/image_pipeline.h"
#include "shared/types.h"

namespace penumbra {

DenoisePass::DenoisePass(const gpu::Context& ctx, const gpu::Buffer& frameUniforms, const gpu::Buffer& viewerUniforms,
                         const gpu::Buffer& gbuffer, const gpu::Buffer& a, const gpu::Buffer& b)
    : a_(a), b_(b) {
    PN_CHECK(a.size() == b.size());
    for (int tiled = 0; tiled < 2; ++tiled)
        for (int direction = 0; direction < 2; ++direction) {
            const std::uint32_t tileTexels = tiled ? PN_ATROUS_TILE_TEXELS : 1u;
            pipelines_[tiled][direction] =
                makeImagePipeline(ctx, "atrous", frameUniforms,
                                  {{PN_BINDING_VIEWER, &viewerUniforms},
                                   {PN_BINDING_GBUFFER, &gbuffer},
                                   {PN_BINDING_FILTER_IN, direction == 0 ? &a : &b},
                                   {PN_BINDING_FILTER_OUT, direction == 0 ? &b : &a}},
                                  sizeof(shader::PassPush), {&tileTexels, 1});
        }
}

const gpu::Buffer& DenoisePass::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height,
                                       std::uint32_t iterations) const {
    PN_CHECK(iterations >= 1);
    for (std::uint32_t i = 0; i < iterations; ++i) {
        const std::uint32_t step = 1u << i;
        shader::PassPush push{step, i + 1 == iterations ? PN_ATROUS_LAST : 0u, 0, 0};
        const bool tiled = step <= PN_ATROUS_TILE_MAX_STEP;
        dispatchImage(*pipelines_[tiled][i % 2], cmd, width, height, &push);
        gpu::computeBarrier(cmd);
    }
    return output(iterations);
}

}  // namespace penumbra
