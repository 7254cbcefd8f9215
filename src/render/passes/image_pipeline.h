// Pipelines for the viewer's image passes (temporal, a-trous, tonemap): the frame uniforms plus
// storage buffers, each bound at its shared/types.h binding.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gpu/pipeline.h"

namespace penumbra {

using BufferBinding = std::pair<std::uint32_t, const gpu::Buffer*>;

std::unique_ptr<gpu::ComputePipeline> makeImagePipeline(const gpu::Context& ctx, const std::string& shader,
                                                        const gpu::Buffer& frameUniforms,
                                                        const std::vector<BufferBinding>& storage,
                                                        std::uint32_t pushBytes = 0);

// Workgroups covering a width x height image with the 8x8 groups every image pass uses.
void dispatchImage(const gpu::ComputePipeline& pipeline, VkCommandBuffer cmd, std::uint32_t width,
                   std::uint32_t height, const void* push = nullptr);

}  // namespace penumbra
