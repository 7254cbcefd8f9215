#include "render/passes/image_pipeline.h"

#include "shared/types.h"

namespace penumbra {

std::unique_ptr<gpu::ComputePipeline> makeImagePipeline(const gpu::Context& ctx, const std::string& shader,
                                                        const gpu::Buffer& frameUniforms,
                                                        const std::vector<BufferBinding>& storage,
                                                        std::uint32_t pushBytes) {
    std::vector<gpu::BindingSpec> specs = {{PN_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}};
    for (const auto& [binding, buffer] : storage) specs.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    auto pipeline = std::make_unique<gpu::ComputePipeline>(ctx, shader, specs, pushBytes);
    pipeline->bind(PN_BINDING_FRAME, frameUniforms);
    for (const auto& [binding, buffer] : storage) pipeline->bind(binding, *buffer);
    return pipeline;
}

void dispatchImage(const gpu::ComputePipeline& pipeline, VkCommandBuffer cmd, std::uint32_t width,
                   std::uint32_t height, const void* push) {
    pipeline.dispatch(cmd, (width + PN_TRACE_GROUP_X - 1) / PN_TRACE_GROUP_X,
                      (height + PN_TRACE_GROUP_Y - 1) / PN_TRACE_GROUP_Y, 1, push);
}

}  // namespace penumbra
