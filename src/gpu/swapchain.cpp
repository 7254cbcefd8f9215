#include "gpu/swapchain.h"

#include <algorithm>

#include "core/error.h"
#include "gpu/check.h"

namespace penumbra::gpu {
namespace {

VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice device, VkSurfaceKHR surface) {
    std::uint32_t count = 0;
    PN_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    PN_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, formats.data()));
    if (formats.empty()) throw Error("the window surface offers no image formats");
    // 8-bit BGRA/RGBA, sRGB-encoding formats preferred (the viewer's display buffer is already
    // encoded, so its copy image is made sRGB too and the blit keeps the values).
    for (VkFormat want : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
        for (const auto& f : formats)
            if (f.format == want && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    throw Error("the window surface offers no 8-bit RGBA or BGRA format");
}

VkPresentModeKHR choosePresentMode(const Context& ctx, bool vsync) {
    std::uint32_t count = 0;
    PN_VK(vkGetPhysicalDeviceSurfacePresentModesKHR(ctx.physicalDevice(), ctx.surface(), &count, nullptr));
    std::vector<VkPresentModeKHR> modes(count);
    PN_VK(vkGetPhysicalDeviceSurfacePresentModesKHR(ctx.physicalDevice(), ctx.surface(), &count, modes.data()));
    if (!vsync)
        for (VkPresentModeKHR want : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
            if (std::find(modes.begin(), modes.end(), want) != modes.end()) return want;
    return VK_PRESENT_MODE_FIFO_KHR;  // always available: vsync
}

}  // namespace

Swapchain::Swapchain(const Context& ctx) : ctx_(ctx) {
    const VkSurfaceFormatKHR surfaceFormat = chooseFormat(ctx.physicalDevice(), ctx.surface());
    format_ = surfaceFormat.format;
    colorSpace_ = surfaceFormat.colorSpace;
}

void Swapchain::create(VkExtent2D windowSize, bool vsync, VkRenderPass renderPass) {
    VkDevice device = ctx_.device();
    VkSurfaceCapabilitiesKHR caps{};
    PN_VK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_.physicalDevice(), ctx_.surface(), &caps));
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw Error("the window's swapchain images cannot be copied to (no TRANSFER_DST usage)");
    extent_ = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent : windowSize;
    extent_.width = std::clamp(extent_.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent_.height = std::clamp(extent_.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    minImageCount_ = std::max(2u, caps.minImageCount);
    std::uint32_t imageCount = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) imageCount = std::min(imageCount, caps.maxImageCount);

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = ctx_.surface();
    info.minImageCount = imageCount;
    info.imageFormat = format_;
    info.imageColorSpace = colorSpace_;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                              ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
    info.presentMode = choosePresentMode(ctx_, vsync);
    info.clipped = VK_TRUE;
    info.oldSwapchain = swapchain_.get();
    VkSwapchainKHR swapchain = VK_NULL_HANDLE;
    PN_VK(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain));
    framebuffers_.clear();
    views_.clear();
    swapchain_ = SwapchainHandle(device, swapchain);

    std::uint32_t count = 0;
    PN_VK(vkGetSwapchainImagesKHR(device, swapchain, &count, nullptr));
    images_.resize(count);
    PN_VK(vkGetSwapchainImagesKHR(device, swapchain, &count, images_.data()));
    renderDone_.clear();
    for (VkImage image : images_) {
        VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        viewInfo.image = image;
        viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
        viewInfo.format = format_;
        viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view = VK_NULL_HANDLE;
        PN_VK(vkCreateImageView(device, &viewInfo, nullptr, &view));
        views_.emplace_back(device, view);
        VkFramebufferCreateInfo fbInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fbInfo.renderPass = renderPass;
        fbInfo.attachmentCount = 1;
        fbInfo.pAttachments = &view;
        fbInfo.width = extent_.width;
        fbInfo.height = extent_.height;
        fbInfo.layers = 1;
        VkFramebuffer fb = VK_NULL_HANDLE;
        PN_VK(vkCreateFramebuffer(device, &fbInfo, nullptr, &fb));
        framebuffers_.emplace_back(device, fb);
        VkSemaphoreCreateInfo semInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        VkSemaphore sem = VK_NULL_HANDLE;
        PN_VK(vkCreateSemaphore(device, &semInfo, nullptr, &sem));
        renderDone_.emplace_back(device, sem);
    }
}

}  // namespace penumbra::gpu
