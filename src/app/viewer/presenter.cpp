#include "app/viewer/presenter.h"

#include <algorithm>

#include "app/viewer/window.h"
#include "core/error.h"
#include "gpu/check.h"

namespace penumbra::viewer {

Presenter::Presenter(const gpu::Context& ctx, const Window& window, bool vsync)
    : ctx_(ctx), window_(window), vsync_(vsync), swapchain_(ctx) {
    VkDevice device = ctx.device();

    // The UI pass draws over the blitted image: load it, leave it ready to present.
    VkAttachmentDescription attachment{};
    attachment.format = swapchain_.format();
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
    acquired_ = gpu::SemaphoreHandle(device, sem);
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
    PN_VK(vkDeviceWaitIdle(ctx_.device()));
    swapchain_.create(window_.framebufferSize(), vsync_, renderPass_.get());
    rebuild_ = false;
}

bool Presenter::beginFrame() {
    VkDevice device = ctx_.device();
    VkFence fence = frameFence_.get();
    PN_VK(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX));
    VkExtent2D size = window_.framebufferSize();
    if (size.width == 0 || size.height == 0) return false;
    const VkExtent2D extent = swapchain_.extent();
    if (rebuild_ || size.width != extent.width || size.height != extent.height) createSwapchain();
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

void Presenter::blitDisplay(const gpu::Buffer& display, std::uint32_t width, std::uint32_t height) {
    PN_CHECK(frameOpen_);
    if (!displayImage_ || displayImage_.width() != width || displayImage_.height() != height) {
        PN_VK(vkDeviceWaitIdle(ctx_.device()));
        displayImage_ = gpu::Image();
        // Same encoding as the swapchain, so the blit moves encoded values unchanged.
        displayImage_ = gpu::Image(ctx_, width, height,
                                   swapchain_.srgb() ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM,
                                   VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    }
    VkImage src = displayImage_.get();
    VkImage dst = swapchain_.image(imageIndex_);
    const VkExtent2D extent = swapchain_.extent();
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
    blit.dstOffsets[1] = {std::int32_t(extent.width), std::int32_t(extent.height), 1};
    // Nearest when the sizes match keeps the pixels exact; linear for the upscale.
    const bool sameSize = width == extent.width && height == extent.height;
    vkCmdBlitImage(cmd_, src, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                   sameSize ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
}

void Presenter::clear(float r, float g, float b) {
    PN_CHECK(frameOpen_);
    VkImage dst = swapchain_.image(imageIndex_);
    transition(dst, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkClearColorValue color{{r, g, b, 1.0f}};
    VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd_, dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &color, 1, &range);
}

void Presenter::beginUi() {
    transition(swapchain_.image(imageIndex_), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
               VK_ACCESS_TRANSFER_WRITE_BIT,
               VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT);
    VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    info.renderPass = renderPass_.get();
    info.framebuffer = swapchain_.framebuffer(imageIndex_);
    info.renderArea = {{0, 0}, swapchain_.extent()};
    vkCmdBeginRenderPass(cmd_, &info, VK_SUBPASS_CONTENTS_INLINE);
}

void Presenter::endFrame() {
    PN_CHECK(frameOpen_);
    frameOpen_ = false;
    vkCmdEndRenderPass(cmd_);
    PN_VK(vkEndCommandBuffer(cmd_));
    VkSemaphore wait = acquired_.get();
    VkSemaphore signal = swapchain_.renderDone(imageIndex_);
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
