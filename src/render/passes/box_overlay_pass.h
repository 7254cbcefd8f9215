// The BVH box overlay (shaders/boxes.comp): outlines the boxes of one BVH depth over the display
// buffer, after the tonemap pass. It owns the small host-visible buffer of boxes it draws.
#pragma once

#include <memory>
#include <span>

#include "gpu/buffer.h"
#include "gpu/pipeline.h"
#include "shared/types.h"

namespace penumbra {

class BoxOverlayPass {
public:
    BoxOverlayPass(const gpu::Context& ctx, const gpu::Buffer& frameUniforms, const gpu::Buffer& viewerUniforms,
                   const gpu::Buffer& display);

    // Boxes to outline (bounds only; at most PN_MAX_OVERLAY_BOXES are kept). Only while no
    // submission that draws them is in flight.
    void setBoxes(std::span<const shader::BvhNode> boxes);
    std::uint32_t boxCount() const { return count_; }
    void record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, float lineWidth) const;

private:
    gpu::Buffer boxes_;
    std::unique_ptr<gpu::ComputePipeline> pipeline_;
    std::uint32_t count_ = 0;
};

}  // namespace penumbra
