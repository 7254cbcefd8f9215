#include "app/viewer/presenter.h"

#include <algorithm>

#include "app/viewer/window.h"
#include "core/error.h"
#include "gpu/check.h"

namespace penumbra::viewer {
namespace {

bool isSrgb(VkFormat f) { return f == VK_FORMAT_B8G8R8A8_SRGB || f == VK_FORMAT_R8G8B8A8_SRGB; }

VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice device, VkSurfaceKHR surface) {
    std::uint32_t count = 0;
    PN_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    PN_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, formats.data()));
    if (formats.empty()) throw Error("the window surface offers no image formats");
    // 8-bit BGRA/RGBA, sRGB-encoding formats preferred (the display buffer is already encoded, so
    // the copy image is made sRGB too and the blit keeps the values).
    for (VkFormat want : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
        for (const auto& f : formats)
            if (f.format == want && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    throw Error("the window surface offers no 8-bit RGBA or BGRA format");
}

}  // namespace

Presenter::Presenter(const gpu::Context& ctx, const Window& window, bool vsync)
    : ctx_(ctx), window_(window), vsync_(vsync) {
    VkDevice device = ctx.device();
    VkSurfaceFormatKHR surfaceFormat = chooseFormat(ctx.physicalDevice(), ctx.surface());
    format_ = surfaceFormat.format;
    colorSpace_ = surfaceFormat.colorSpace;

    // The UI pass draws over the blitted image: load it, leave it ready to present.
    VkAttachmentDescription attachment{};
    attachment.format = format_;
    attachment.samples = VK_SAMPLE_COUNT_1_BIT;
    attachment.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachment.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    attachment.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;
    VkRenderPassCreateInfo rpInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    rpInfo.attachmentCount = 1;
    rpInfo.pAttachments = &attachment;
    rpInfo.subpassCount = 1;
    rpInfo.pSubpasses = &subpass;
    VkRenderPass rp = VK_NULL_HANDLE;
    PN_VK(vkCreateRenderPass(device, &rpInfo, nullptr, &rp));
    renderPass_ = RenderPassHandle(device, rp);

    VkSemaphoreCreateInfo semInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore sem = VK_NULL_HANDLE;
    PN_VK(vkCreateSemaphore(device, &semInfo, nullptr, &sem));
    acquired_ = SemaphoreHandle(device, sem);
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    VkFence fence = VK_NULL_HANDLE;
    PN_VK(vkCreateFence(device, &fenceInfo, nullptr, &fence));
    frameFence_ = gpu::Fence(device, fence);
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = ctx.queueFamily();
    VkCommandPool pool = VK_NULL_HANDLE;
    PN_VK(vkCreateCommandPool(device, &poolInfo, nullptr, &pool));
    pool_ = gpu::CommandPool(device, pool);
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    PN_VK(vkAllocateCommandBuffers(device, &alloc, &cmd_));
    createSwapchain();
}

Presenter::~Presenter() { vkDeviceWaitIdle(ctx_.device()); }  // nothing to do about a failure here

void Presenter::waitIdle() const { PN_VK(vkDeviceWaitIdle(ctx_.device())); }

void Presenter::setVsync(bool vsync) {
    if (vsync == vsync_) return;
    vsync_ = vsync;
    rebuild_ = true;
}

void Presenter::createSwapchain() {
    VkDevice device = ctx_.device();
    PN_VK(vkDeviceWaitIdle(device));
    VkSurfaceCapabilitiesKHR caps{};
    PN_VK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_.physicalDevice(), ctx_.surface(), &caps));
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw Error("the window's swapchain images cannot be copied to (no TRANSFER_DST usage)");
    VkExtent2D size = window_.framebufferSize();
    extent_ = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent : size;
    extent_.width = std::clamp(extent_.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent_.height = std::clamp(extent_.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    minImageCount_ = std::max(2u, caps.minImageCount);
    std::uint32_t imageCount = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) imageCount = std::min(imageCount, caps.maxImageCount);

    std::uint32_t modeCount = 0;
    PN_VK(vkGetPhysicalDeviceSurfacePresentModesKHR(ctx_.physicalDevice(), ctx_.surface(), &modeCount, nullptr));
    std::vector<VkPresentModeKHR> modes(modeCount);
    PN_VK(vkGetPhysicalDeviceSurfacePresentModesKHR(ctx_.physicalDevice(), ctx_.surface(), &modeCount, modes.data()));
    VkPresentModeKHR mode = VK_PRESENT_MODE_FIFO_KHR;  // always available: vsync
    if (!vsync_)
        for (VkPresentModeKHR want : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
            if (mode == VK_PRESENT_MODE_FIFO_KHR && std::find(modes.begin(), modes.end(), want) != modes.end()) mode = want;

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
    info.presentMode = mode;
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
        fbInfo.renderPass = renderPass_.get();
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
    rebuild_ = false;
}

bool Presenter::beginFrame() {
    VkDevice device = ctx_.device();
    VkFence fence = frameFence_.get();
    PN_VK(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX));
    VkExtent2D size = window_.framebufferSize();
    if (size.width == 0 || size.height == 0) return false;
    if (rebuild_ || size.width != extent_.width || size.height != extent_.height) createSwapchain();
    VkResult r = vkAcquireNextImageKHR(device, swapchain_.get(), UINT64_MAX, acquired_.get(), VK_NULL_HANDLE, &imageIndex_);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
        createSwapchain();
        return false;
    }
    if (r != VK_SUBOPTIMAL_KHR) PN_VK(r);
    PN_VK(vkResetCommandBuffer(cmd_, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    PN_VK(vkBeginCommandBuffer(cmd_, &begin));
    frameOpen_ = true;
    return true;
}

void Presenter::transition(VkImage image, VkImageLayout from, VkImageLayout to, VkAccessFlags srcAccess,
                           VkAccessFlags dstAccess, VkPipelineStageFlags srcStage, VkPipelineStageFlags dstStage) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.oldLayout = from;
    b.newLayout = to;
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd_, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

void Presenter::createDisplayImage(std::uint32_t width, std::uint32_t height) {
    if (displayImage_ && width == displayWidth_ && height == displayHeight_) return;
    VkDevice device = ctx_.device();
    PN_VK(vkDeviceWaitIdle(device));
    displayImage_.reset();
    displayMemory_.reset();
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    // Same encoding as the swapchain, so the blit moves encoded values unchanged.
    info.format = isSrgb(format_) ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
    info.extent = {width, height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImage image = VK_NULL_HANDLE;
    PN_VK(vkCreateImage(device, &info, nullptr, &image));
    displayImage_ = ImageHandle(device, image);
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device, image, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = ctx_.findMemoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (alloc.memoryTypeIndex == UINT32_MAX) throw Error("no device memory type for the display image");
    VkDeviceMemory memory = VK_NULL_HANDLE;
    PN_VK(vkAllocateMemory(device, &alloc, nullptr, &memory));
    displayMemory_ = gpu::MemoryHandle(device, memory);
    PN_VK(vkBindImageMemory(device, image, memory, 0));
    displayWidth_ = width;
    displayHeight_ = height;
}

void Presenter::blitDisplay(const gpu::Buffer& display, std::uint32_t width, std::uint32_t height) {
    PN_CHECK(frameOpen_);
    createDisplayImage(width, height);
    VkImage src = displayImage_.get();
    VkImage dst = images_[imageIndex_];
    transition(src, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_ACCESS_SHADER_WRITE_BIT,
               VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width, height, 1};
    vkCmdCopyBufferToImage(cmd_, display.get(), src, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    transition(src, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT);
    transition(dst, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkImageBlit blit{};
    blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.srcOffsets[1] = {std::int32_t(width), std::int32_t(height), 1};
    blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.dstOffsets[1] = {std::int32_t(extent_.width), std::int32_t(extent_.height), 1};
    // Nearest when the sizes match keeps the pixels exact; linear for the upscale.
    const bool sameSize = width == extent_.width && height == extent_.height;
    vkCmdBlitImage(cmd_, src, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                   sameSize ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
}

void Presenter::clear(float r, float g, float b) {
    PN_CHECK(frameOpen_);
    VkImage dst = images_[imageIndex_];
    transition(dst, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkClearColorValue color{{r, g, b, 1.0f}};
    VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd_, dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &color, 1, &range);
}

void Presenter::beginUi() {
    transition(images_[imageIndex_], VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
               VK_ACCESS_TRANSFER_WRITE_BIT,
               VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT);
    VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    info.renderPass = renderPass_.get();
    info.framebuffer = framebuffers_[imageIndex_].get();
    info.renderArea = {{0, 0}, extent_};
    vkCmdBeginRenderPass(cmd_, &info, VK_SUBPASS_CONTENTS_INLINE);
}

void Presenter::endFrame() {
    PN_CHECK(frameOpen_);
    frameOpen_ = false;
    vkCmdEndRenderPass(cmd_);
    PN_VK(vkEndCommandBuffer(cmd_));
    VkSemaphore wait = acquired_.get();
    VkSemaphore signal = renderDone_[imageIndex_].get();
    VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &wait;
    submit.pWaitDstStageMask = &waitStage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd_;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &signal;
    // Reset only now, right before the submission that signals it: a frame abandoned by an
    // exception anywhere before leaves the fence signalled, so no later wait can hang on it.
    VkFence fence = frameFence_.get();
    PN_VK(vkResetFences(ctx_.device(), 1, &fence));
    PN_VK(vkQueueSubmit(ctx_.queue(), 1, &submit, fence));
    VkSwapchainKHR swapchain = swapchain_.get();
    VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &signal;
    present.swapchainCount = 1;
    present.pSwapchains = &swapchain;
    present.pImageIndices = &imageIndex_;
    VkResult r = vkQueuePresentKHR(ctx_.queue(), &present);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) {
        rebuild_ = true;
    } else {
        PN_VK(r);
    }
}

}  // namespace penumbra::viewer
