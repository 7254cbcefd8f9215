// A 2D device-local image with its own memory (one mip level, one layer), and the layout
// transition barrier for colour images.
#pragma once

#include <cstdint>

#include "gpu/context.h"
#include "gpu/handle.h"

namespace penumbra::gpu {

using ImageHandle = DeviceHandle<VkImage, vkDestroyImage>;
using ImageViewHandle = DeviceHandle<VkImageView, vkDestroyImageView>;

class Image {
public:
    Image() = default;
    // Starts in VK_IMAGE_LAYOUT_UNDEFINED, optimal tiling.
    Image(const Context& ctx, std::uint32_t width, std::uint32_t height, VkFormat format, VkImageUsageFlags usage);

    VkImage get() const { return image_.get(); }
    explicit operator bool() const { return bool(image_); }
    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }

private:
    MemoryHandle memory_;  // declared first, so freed after the image
    ImageHandle image_;
    std::uint32_t width_ = 0, height_ = 0;
};

// Records a pipeline barrier that moves a colour image (all of it) from one layout to another.
void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                     VkAccessFlags srcAccess, VkAccessFlags dstAccess, VkPipelineStageFlags srcStage,
                     VkPipelineStageFlags dstStage);

}  // namespace penumbra::gpu
