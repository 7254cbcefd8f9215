// The swapchain side of the viewer: acquire, copy the display buffer into an RGBA8 image and blit
// it (scaled, format-converted) onto the swapchain image, draw the UI over it, present. One frame
// in flight: beginFrame waits for the previous one, so the renderer may rewrite its uniforms.
// Out-of-date or suboptimal swapchains (resizes) are rebuilt transparently. The Vulkan objects
// themselves (swapchain, images) come from src/gpu/.
#pragma once

#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/handle.h"
#include "gpu/image.h"
#include "gpu/swapchain.h"

namespace penumbra::viewer {

class Window;

using RenderPassHandle = gpu::DeviceHandle<VkRenderPass, vkDestroyRenderPass>;

class Presenter {
public:
    Presenter(const gpu::Context& ctx, const Window& window, bool vsync);
    ~Presenter();
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    void setVsync(bool vsync);
    // Waits for the previous frame, acquires an image and begins the command buffer. False when
    // there is nothing to draw on (minimised window); then skip the frame.
    bool beginFrame();
    VkCommandBuffer commandBuffer() const { return cmd_; }
    // Copies a width x height RGBA8 display buffer onto the whole swapchain image.
    void blitDisplay(const gpu::Buffer& display, std::uint32_t width, std::uint32_t height);
    void clear(float r, float g, float b);  // instead of blitDisplay, when nothing is rendered
    // Opens the UI render pass (load, so the image stays); endFrame closes it, submits and presents.
    void beginUi();
    void endFrame();
    void waitIdle() const;

    VkRenderPass renderPass() const { return renderPass_.get(); }
    std::uint32_t imageCount() const { return swapchain_.imageCount(); }
    std::uint32_t minImageCount() const { return swapchain_.minImageCount(); }
    VkFormat format() const { return swapchain_.format(); }

private:
    void createSwapchain();
    void transition(VkImage image, VkImageLayout from, VkImageLayout to, VkAccessFlags srcAccess,
                    VkAccessFlags dstAccess, VkPipelineStageFlags srcStage, VkPipelineStageFlags dstStage) {
        gpu::transitionImage(cmd_, image, from, to, srcAccess, dstAccess, srcStage, dstStage);
    }

    const gpu::Context& ctx_;
    const Window& window_;
    bool vsync_;
    bool rebuild_ = false;
    gpu::Swapchain swapchain_;
    RenderPassHandle renderPass_;
    gpu::SemaphoreHandle acquired_;
    gpu::Fence frameFence_;
    gpu::CommandPool pool_;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    std::uint32_t imageIndex_ = 0;
    bool frameOpen_ = false;
    gpu::Image displayImage_;  // the RGBA8 image the display buffer is copied into before the blit
};

}  // namespace penumbra::viewer
