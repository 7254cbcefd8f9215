#include "render/passes/denoise_pass.h"

#include "core/error.h"
#include "gpu/commands.h"
#include "render/passes/image_pipeline.h"
#include "shared/types.h"

namespace penumbra {

DenoisePass::DenoisePass(const gpu::Context& ctx, const gpu::Buffer& frameUniforms, const gpu::Buffer& viewerUniforms,
                         const gpu::Buffer& gbuffer, const gpu::Buffer& guide, const gpu::Buffer& history,
                         const gpu::Buffer& a, const gpu::Buffer& b, const gpu::Buffer* display)
    : a_(a), b_(b), hasDisplay_(display != nullptr) {
    // Without a display the binding still needs a buffer; the shader writes it only when told to.
    const gpu::Buffer& displayOrUnused = display ? *display : b;
    auto make = [&](const gpu::Buffer& in, const gpu::Buffer& out) {
        return makeImagePipeline(ctx, "atrous", frameUniforms,
                                 {{PN_BINDING_VIEWER, &viewerUniforms},
                                  {PN_BINDING_GBUFFER, &gbuffer},
                                  {PN_BINDING_DENOISE_GUIDE, &guide},
                                  {PN_BINDING_HISTORY_OUT, &history},
                                  {PN_BINDING_FILTER_IN, &in},
                                  {PN_BINDING_FILTER_OUT, &out},
                                  {PN_BINDING_DISPLAY, &displayOrUnused}},
                                 sizeof(shader::PassPush));
    };
    aToB_ = make(a, b);
    bToA_ = make(b, a);
}

const gpu::Buffer& DenoisePass::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height,
                                       std::uint32_t iterations, bool toDisplay, bool filterOnly) const {
    PN_CHECK(iterations >= 1 && (!toDisplay || hasDisplay_));
    const std::uint32_t lastMode =
        PN_ATROUS_LAST | (toDisplay ? PN_ATROUS_DISPLAY : 0u) | (filterOnly ? PN_ATROUS_FILTER_ONLY : 0u);
    for (std::uint32_t i = 0; i < iterations; ++i) {
        shader::PassPush push{1u << i, i + 1 == iterations ? lastMode : 0u, 0, 0};
        dispatchImage(i % 2 == 0 ? *aToB_ : *bToA_, cmd, width, height, &push);
        gpu::computeBarrier(cmd);
    }
    return output(iterations);
}

}  // namespace penumbra
