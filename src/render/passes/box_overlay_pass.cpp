#include "render/passes/box_overlay_pass.h"

#include <algorithm>
#include <cstring>

#include "render/passes/image_pipeline.h"

namespace penumbra {

BoxOverlayPass::BoxOverlayPass(const gpu::Context& ctx, const gpu::Buffer& frameUniforms,
                               const gpu::Buffer& viewerUniforms, const gpu::Buffer& display)
    : boxes_(ctx, sizeof(shader::BvhNode) * PN_MAX_OVERLAY_BOXES, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
             gpu::MemoryKind::HostVisible) {
    std::memset(boxes_.mapped(), 0, boxes_.size());
    pipeline_ = makeImagePipeline(ctx, "boxes", frameUniforms,
                                  {{PN_BINDING_VIEWER, &viewerUniforms},
                                   {PN_BINDING_OVERLAY_BOXES, &boxes_},
                                   {PN_BINDING_DISPLAY, &display}},
                                  sizeof(shader::BoxOverlayPush));
}

void BoxOverlayPass::setBoxes(std::span<const shader::BvhNode> boxes) {
    count_ = static_cast<std::uint32_t>(std::min<std::size_t>(boxes.size(), PN_MAX_OVERLAY_BOXES));
    std::memcpy(boxes_.mapped(), boxes.data(), count_ * sizeof(shader::BvhNode));
}

void BoxOverlayPass::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, float lineWidth) const {
    shader::BoxOverlayPush push{};
    push.boxCount = count_;
    push.lineWidth = lineWidth;
    dispatchImage(*pipeline_, cmd, width, height, &push);
}

}  // namespace penumbra
