// A window surface's swapchain: the surface format (8-bit RGBA or BGRA, sRGB encodings preferred),
// the swapchain and its images, an image view, framebuffer and "rendering done" semaphore per
// image. create() builds it (again) for a size, a present mode and a render pass; the old
// swapchain is handed to the new one, then destroyed.
#pragma once

#include <cstdint>
#include <vector>

#include "gpu/context.h"
#include "gpu/handle.h"
#include "gpu/image.h"

namespace penumbra::gpu {

using SemaphoreHandle = DeviceHandle<VkSemaphore, vkDestroySemaphore>;
using FramebufferHandle = DeviceHandle<VkFramebuffer, vkDestroyFramebuffer>;
using SwapchainHandle = DeviceHandle<VkSwapchainKHR, vkDestroySwapchainKHR>;

class Swapchain {
public:
    // Chooses the surface format of ctx's surface; create() makes the swapchain itself.
    explicit Swapchain(const Context& ctx);

    // (Re)builds the swapchain for a window of windowSize (the surface's own extent wins when it
    // has one); vsync picks FIFO, else mailbox or immediate where offered. The device must be
    // idle. Framebuffers are made for renderPass, whose one attachment is the swapchain image.
    void create(VkExtent2D windowSize, bool vsync, VkRenderPass renderPass);

    VkSwapchainKHR get() const { return swapchain_.get(); }
    VkFormat format() const { return format_; }
    bool srgb() const { return format_ == VK_FORMAT_B8G8R8A8_SRGB || format_ == VK_FORMAT_R8G8B8A8_SRGB; }
    VkExtent2D extent() const { return extent_; }
    std::uint32_t minImageCount() const { return minImageCount_; }
    std::uint32_t imageCount() const { return static_cast<std::uint32_t>(images_.size()); }
    VkImage image(std::uint32_t i) const { return images_[i]; }
    VkFramebuffer framebuffer(std::uint32_t i) const { return framebuffers_[i].get(); }
    VkSemaphore renderDone(std::uint32_t i) const { return renderDone_[i].get(); }

private:
    const Context& ctx_;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkColorSpaceKHR colorSpace_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    VkExtent2D extent_{};
    std::uint32_t minImageCount_ = 2;
    SwapchainHandle swapchain_;
    std::vector<VkImage> images_;  // owned by the swapchain
    std::vector<ImageViewHandle> views_;
    std::vector<FramebufferHandle> framebuffers_;
    std::vector<SemaphoreHandle> renderDone_;
};

}  // namespace penumbra::gpu
