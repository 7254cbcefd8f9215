// The swapchain side of the viewer: acquire, copy the display buffer into an RGBA8 image and blit
// it (scaled, format-converted) onto the swapchain image, draw the UI over it, present. One frame
// in flight: beginFrame waits for the previous one, so the renderer may rewrite its uniforms.
// Out-of-date or suboptimal swapchains (resizes) are rebuilt transparently.
#pragma once

#include <vector>

#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/handle.h"

namespace penumbra::viewer {

class Window;

using ImageHandle = gpu::DeviceHandle<VkImage, vkDestroyImage>;
using ImageViewHandle = gpu::DeviceHandle<VkImageView, vkDestroyImageView>;
using SemaphoreHandle = gpu::DeviceHandle<VkSemaphore, vkDestroySemaphore>;
using RenderPassHandle = gpu::DeviceHandle<VkRenderPass, vkDestroyRenderPass>;
using FramebufferHandle = gpu::DeviceHandle<VkFramebuffer, vkDestroyFramebuffer>;
using SwapchainHandle = gpu::DeviceHandle<VkSwapchainKHR, vkDestroySwapchainKHR>;

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
    std::uint32_t imageCount() const { return static_cast<std::uint32_t>(images_.size()); }
    std::uint32_t minImageCount() const { return minImageCount_; }
    VkFormat format() const { return format_; }

private:
    void createSwapchain();
    void createDisplayImage(std::uint32_t width, std::uint32_t height);
    void transition(VkImage image, VkImageLayout from, VkImageLayout to, VkAccessFlags srcAccess,
                    VkAccessFlags dstAccess, VkPipelineStageFlags srcStage, VkPipelineStageFlags dstStage);

    const gpu::Context& ctx_;
    const Window& window_;
    bool vsync_;
    bool rebuild_ = false;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkColorSpaceKHR colorSpace_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    VkExtent2D extent_{};
    std::uint32_t minImageCount_ = 2;
    SwapchainHandle swapchain_;
    std::vector<VkImage> images_;
    std::vector<ImageViewHandle> views_;
    std::vector<FramebufferHandle> framebuffers_;
    std::vector<SemaphoreHandle> renderDone_;  // one per swapchain image
    RenderPassHandle renderPass_;
    SemaphoreHandle acquired_;
    gpu::Fence frameFence_;
    gpu::CommandPool pool_;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    std::uint32_t imageIndex_ = 0;
    bool frameOpen_ = false;
    // The RGBA8 image the display buffer is copied into before the blit.
    ImageHandle displayImage_;
    gpu::MemoryHandle displayMemory_;
    std::uint32_t displayWidth_ = 0, displayHeight_ = 0;
};

}  // namespace penumbra::viewer
